#pragma once
/// @file
/// The holding capacity of a grasp scenario: how large a load on the object the grasp holds
/// before the object slips, and before it drops.
///
/// The scene is the simulation's (simulation::GraspScene, any contact model and mode) with a
/// simulation::RampLoad on the object. The load starts kLoadStartDelay after the scenario's
/// settle_time, so the grasp has settled and, in approx mode, the approximation has engaged (it
/// engages at the first check from settle_time on; the run refuses to load a grasp it has not).
/// Slip: the largest displacement, relative to the palm, of the object's material points at the
/// grasp goals (where the fingertips press) since the load began; held: every goal fingertip
/// within the scenario's held_tolerance of its goal on the object.

#include "graspsim/capacity/capacity_protocol.h"
#include "graspsim/contact/friction_settings.h"
#include "graspsim/scenario/scenario.h"
#include "graspsim/simulation/simulation_options.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace graspsim::capacity {

/// Delay of the load's start after the scenario's settle_time (s).
constexpr double kLoadStartDelay = 0.1;

/// What to measure.
struct GraspCapacityRequest {
    SimTK::UnitVec3 direction{0, -1, 0};  ///< in G
    std::string directionName = "-y";     ///< for reports: an axis (x, -y, ...) or the vector as given
    bool torque = false;                  ///< a torque about the object's centre of mass instead of a force
    double rate = 0;                      ///< N/s or N m/s; 0: findDefaultRate
    double maxRampDuration = 4;           ///< s
    double initialLoad = 0;               ///< ramp: N or N m applied at once at its start (RampProtocol::initial)
    double sampleInterval = 0.005;        ///< s
    SlipCriteria criteria;
};

/// The nine loads of `capacity --direction all`: the six axis forces (x, -x, y, -y, z, -z), then
/// the torques about x, y and z; default rates, criteria and durations.
std::vector<GraspCapacityRequest> makeAllDirectionRequests();

/// The default ramp rate: twice the object's weight per second for a force (the thesis objects'
/// capacities, 1 to 8 weights, are then reached within 0.5-4 s), and for a torque that times the
/// farthest goal's distance from the centre of mass (the lever the fingers hold it with).
double findDefaultRate(const scenario::Scenario& scenario, bool torque);

/// Largest angle (rad) between a torque's axis and the line through a two-finger pinch's goals for
/// which the torque is refused: two point contacts carry no torque about the line through them
/// (graspsim's contacts have no torsional friction), so the object would spin at any load.
constexpr double kPinchAxisTolerance = 5.0 * 3.14159265358979323846 / 180;

/// Checks, before anything runs, that the grasp can resist the load at all.
/// @param flags the command's options for the direction and the torque, which the message names.
/// @throws graspsim::InputError naming the direction, the goals and the angle, for a torque about
///         (within kPinchAxisTolerance of) the line through the two goals of a two-goal grasp.
void checkLoadResistible(const scenario::Scenario& scenario, const GraspCapacityRequest& request,
                         const std::pair<std::string, std::string>& flags = {"--direction", "--torque"});

/// When the load starts (s): settle_time + kLoadStartDelay.
double findLoadStart(const scenario::Scenario& scenario);

/// A factory of loaded grasp runs (GraspScene + its stepper) for runRamp / runBisection, sharing one
/// settled scene per thread (settled_grasps.h). It refers to `scenario`, which must outlive it.
/// In approx mode a run throws graspsim::NumericalError if the approximation is not engaged when the
/// load starts.
LoadedRunFactory makeGraspRuns(const scenario::Scenario& scenario, const simulation::SimulationOptions& options);

/// One capacity measurement and its context (a row of capacity.json).
struct GraspCapacity {
    std::string directionName;
    SimTK::UnitVec3 direction;
    bool torque = false;
    std::string method;       ///< "ramp", "bisection" or "constant"
    simulation::ContactModel contact = simulation::ContactModel::Compliant;
    /// Compliant contact's friction law (the scenario's contact.friction_model, or --friction) when it
    /// is not the default, regularized; none for that law and for rigid contact. Reports name it.
    std::optional<contact::FrictionModel> friction;
    /// Compliant contact's capsule rule (contact.capsule_contact, or --capsule-contact) when it is
    /// not the default, deepest; none for that rule and for rigid contact. Reports name it.
    std::optional<contact::CapsuleContact> capsuleContact;
    simulation::SimulationMode mode = simulation::SimulationMode::Full;
    std::string realization;  ///< "" in full mode, else e.g. "bushing merged, limits thesis, release at compliance"
    double start = 0;         ///< load start (s)
    double rate = 0;          ///< N/s or N m/s (ramp)
    double load = 0;          ///< N or N m (constant)
    double hold = 0;          ///< s (constant, bisection)
    SlipCriteria criteria;
    /// ramp and constant: the time series and figures (on the scene's clock; for a constant load
    /// findOverloadFigures gives them after the load's start)
    CapacityTrace trace;
    BisectionResult bisection;  ///< bisection: the bracket
    double wallTime = 0;      ///< s, for all the runs of this measurement
};

class SettledGrasps;

/// Measures along one direction with the ramp, on `grasps`' settled scenes (settled_grasps.h:
/// measurements of one scenario and options share them).
GraspCapacity measureGraspCapacityRamp(SettledGrasps& grasps, const GraspCapacityRequest& request);
/// As above, on scenes of its own.
GraspCapacity measureGraspCapacityRamp(const scenario::Scenario& scenario, const simulation::SimulationOptions& options,
                                       const GraspCapacityRequest& request);

/// Measures along one direction by bisection over constant loads held `hold` s, bracketed from
/// [0, `guess`]. Its runs share one settled scene.
GraspCapacity measureGraspCapacityBisection(SettledGrasps& grasps, const GraspCapacityRequest& request, double guess, double hold);
/// As above, on a scene of its own.
GraspCapacity measureGraspCapacityBisection(const scenario::Scenario& scenario, const simulation::SimulationOptions& options,
                                            const GraspCapacityRequest& request, double guess, double hold);

/// Measures along one direction with a constant load of `load` (N or N m, > 0) from the load's start,
/// held `hold` s (overload.h), sampled every kOverloadSampleInterval (1 ms); request.rate,
/// maxRampDuration and sampleInterval (the ramp's) are not used.
GraspCapacity measureGraspCapacityConstant(SettledGrasps& grasps, const GraspCapacityRequest& request, double load, double hold);
/// As above, on a scene of its own.
GraspCapacity measureGraspCapacityConstant(const scenario::Scenario& scenario, const simulation::SimulationOptions& options,
                                           const GraspCapacityRequest& request, double load, double hold);

}  // namespace graspsim::capacity
