#pragma once
/// @file
/// Running one grasp experiment and what comes out of it.

#include "graspsim/contact/compliant_contact_force.h"
#include "graspsim/integration/stepper.h"
#include "graspsim/scenario/scenario.h"
#include "graspsim/simulation/constraint_sample.h"
#include "graspsim/simulation/grasp_switch.h"
#include "graspsim/simulation/simulation_options.h"

#include "graspsim/simbody.h"

#include <functional>
#include <string>
#include <vector>

namespace graspsim::simulation {

/// The object's pose and the hand's joint angles at one output time.
struct TrajectorySample {
    double time = 0;                  ///< s
    SimTK::Vec3 p_GO{0};              ///< object centre of mass in ground (m)
    SimTK::Quaternion q_GO;           ///< object orientation in ground (w, x, y, z)
    std::vector<double> jointAngles;  ///< rad, ordered as SimulationResult::jointNames
    /// Smallest singular value of the grasp matrix (N): of the active contacts (contact_grasp_quality.h),
    /// or, while the approximation is engaged, its estimate from the constraint's reaction wrench
    /// (GraspSwitch::calcEngagedQuality).
    double graspQuality = 0;
};

/// The contacts at one output time.
struct ContactSample {
    double time = 0;  ///< s
    std::vector<contact::ContactReport> contacts;
};

/// Summary figures of a run (the fields of summary.json, in SI units).
struct SimulationSummary {
    std::string scenario, perturbation;
    ContactModel contact = ContactModel::Compliant;  ///< written as toString(contact)
    SimulationMode mode = SimulationMode::Full;      ///< written as toString(mode)
    bool complete = false;          ///< false when the run stopped early (see failure)
    std::string failure;            ///< why it stopped early, with the time and the last event
    double simTime = 0;             ///< simulated time reached (s)
    double wallTime = 0;            ///< wall-clock time of the integration (s)
    double planTime = 0;            ///< wall-clock time of planning the grasp when loaded (s; grasp: {type}), 0 if not planned
    long steps = 0;                 ///< integrator steps taken
    double meanStepUs = 0;          ///< wall time per step (µs)
    double ikUsPerStep = 0;         ///< of which inverse kinematics (µs)
    double dynamicsUsPerStep = 0;   ///< of which everything else: dynamics, contact, integration (µs)
    long ikSolves = 0;              ///< IK solutions computed
    double settleTime = 0;          ///< when the grasp counts as settled (s)
    double objectDisplacement = 0;  ///< |p_GO(end) - p_GO(settle)| (m)
    double maxPenetration = 0;      ///< deepest contact over the output samples (m)
    double initialPenetration = 0;  ///< deepest segment-object overlap at t = 0 (m; setup_check.h), 0 if none
    double maxGraspQuality = 0;     ///< largest grasp quality over the output samples (N)
    bool held = false;              ///< at the end every goal's fingertip is within the held tolerance of its goal
    double maxFingertipGoalDistance = 0;  ///< at the end (m)
    // The grasp approximation (mode approx; see grasp_switch.h).
    bool engaged = false;           ///< the approximation engaged at least once
    double engageTime = -1;         ///< first engagement (s); < 0 if none
    double releaseTime = -1;        ///< first release after it (s); < 0 if none
    double qAtEngage = 0;           ///< grasp quality at the first engagement (N)
    /// Why the approximation is not engaged at the end of a complete run (GraspSwitch::
    /// findEngageObstacle: the switch's test that fails, with its numbers); empty when it is engaged.
    std::string engageObstacleAtEnd;
    double qThreshold = 0;          ///< Q_Th in use (N)
    double qMinimum = 0;            ///< Q_M in use (N)
    ApproxConstraint constraint = ApproxConstraint::Bushing;  ///< the approximation's realization (approx mode)
    /// Smallest engaged-quality estimate at the output samples while engaged (N; 0 if never
    /// engaged): the Q the release test compares with Q_M (engaged_grasp_tracker.h).
    double minEngagedGraspQuality = 0;
    /// Penetration of the tracked contacts while engaged (engaged_grasp_tracker.h), m: the deepest
    /// contact at engagement (the skin compression the grasp engages with), the deepest seen while
    /// engaged, and the largest growth of one contact's depth beyond its depth at engagement (what
    /// the approximation itself adds; bounded by the tests).
    double engagedPenetrationAtEngage = 0;
    double maxEngagedPenetration = 0;
    double maxEngagedPenetrationGrowth = 0;
    /// Largest object velocity jump across a release (m/s; GraspEvent::velocityJump).
    double maxReleaseVelocityJump = 0;
    /// Wall time per integrator step (µs) from the object's release to the first engagement (or
    /// the end): the full-contact grasp with IK. Boundaries fall on output samples, so up to one
    /// output interval of the other phase may be included.
    double fullStepUs = 0;
    /// Wall time per step (µs) while the first engagement lasts (to its release or the end); 0 if none.
    double approxStepUs = 0;
    /// The same two phases measured per simulated second (wall s per simulated s), the fair
    /// comparison for a variable-step integrator, whose steps lengthen once contact is gone.
    double fullWallPerSimSecond = 0;
    double approxWallPerSimSecond = 0;
    long fullSteps = 0;    ///< integrator steps of the full-contact phase
    long approxSteps = 0;  ///< integrator steps of the first engagement
    std::string integrator;  ///< the stepper's method name (integration::Stepper::getMethodName)
    integration::IntegrationStatistics integratorStatistics;  ///< its own counts over the run
};

/// Everything a run produces.
struct SimulationResult {
    std::vector<std::string> jointNames;
    std::vector<TrajectorySample> trajectory;
    std::vector<ContactSample> contacts;
    SimulationSummary summary;
    std::vector<GraspEvent> events;  ///< engage/release switches of the approximation, in time order
    std::vector<ConstraintSample> constraint;  ///< the merged approximation's constraint at each output time it is engaged
    /// The contact pairs (CompliantContactForce indices) the approximation switched off while
    /// engaged, ascending; empty in full mode. A full run of the same scene numbers its pairs alike.
    std::vector<int> replacedPairs;
};

/// Called after each output sample with the simulated time reached (s).
using ProgressCallback = std::function<void(double time, double duration)>;

class GraspExperiment;
/// Called after each output sample with the run's system (its scene and, in approx mode, its
/// approximation) and the state there (realized to Velocity at least), e.g. to measure the cost
/// of the dynamics in that state. Must not change the experiment.
using SampleObserver = std::function<void(const GraspExperiment& experiment, const SimTK::State& state)>;

/// Runs the scenario with the chosen implicit integrator (SimulationOptions::integrator: Simbody's
/// CPodes by default, or the SUNDIALS CVODE reference) at the scenario's accuracy,
/// sampling every output interval, at the perturbation's start and end, and at the object's
/// release. With ContactModel::Rigid: Simbody's SemiExplicitEulerTimeStepper at the fixed
/// kRigidStepSize with the same samples (rigid_stepping.h); summary.steps counts its steps.
/// A numerical failure (a non-finite state, an integrator that cannot step) ends the
/// run early: the result keeps every sample so far and summary.complete is false.
/// @throws graspsim::InputError for options the scenario cannot take (before simulating).
SimulationResult runGraspSimulation(const scenario::Scenario& scenario, const SimulationOptions& options,
                                    const ProgressCallback& progress = {}, const SampleObserver& observer = {});

}  // namespace graspsim::simulation
