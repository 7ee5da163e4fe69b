#pragma once
/// @file
/// The holding capacity predicted by the grasp's compliance model (grasp/compliant_grasp_capacity.h)
/// from a full-contact run's state at the load's start, without ramping: a research step of issue
/// 17 (docs/capacity.md, "A compliance model of the capacity").
///
/// The grasp is run in full compliant contact up to the load's start (settle_time + 0.1 s, as the
/// ramp). There, per finger-object contact point:
///  - position, inward normal and force (normal and friction) from the contact reports;
///  - the contact's normal stiffness linearized from Hertz at its depth, k_n = 3/2 f_n / x (the
///    Hunt-Crossley damping term is left out: the grasp is at rest);
///  - a tangential stiffness k_t = ratio k_n (Mindlin's 2/3 for skin by default, the elastic
///    anchor's; the regularized friction of the default contact has no tangential stiffness, it
///    creeps);
///  - the finger's Cartesian compliance at the contact point, J K_q^-1 J^T, J the point's
///    Jacobian over the finger joints (relative to the palm; the arm does not count, as slip is
///    measured relative to the palm) and K_q the joints' stiffness: passive springs (+ the limit
///    stop's where a joint is past its limit) and the PD gains kp. The PD targets are not fixed:
///    every ik_interval the controller re-solves the fingertip IK warm-started from the present
///    joint angles, and a finger has one joint more (4) than its fingertip goal has coordinates
///    (3), so the targets follow the finger along the null space of its end-effector Jacobian J_E
///    and the gains resist only motions that move the end-effector: kp J_E^+ J_E (linearized:
///    q* - q0* = (1 - J_E^+ J_E)(q - q0)). Along the null space only the passive springs
///    (0.25 N m/rad in the thesis model) hold the finger: a soft direction for contacts that are
///    not at the end-effector (a middle phalanx, the side of a pad).

#include "graspsim/capacity/grasp_capacity.h"
#include "graspsim/grasp/compliant_grasp_capacity.h"
#include "graspsim/grasp/compliant_grasp_creep.h"
#include "graspsim/scenario/scenario.h"
#include "graspsim/simulation/grasp_scene.h"
#include "graspsim/simulation/simulation_options.h"

#include <string>
#include <vector>

namespace graspsim::capacity {

/// The model's free choices.
struct CompliancePredictionSettings {
    double tangentialStiffnessRatio = 2.0 / 3.0;  ///< k_t / k_n (> 0)
    double slipDistance = 2e-3;                   ///< m, the ramp's slip-onset displacement
    /// k_t / k_n of the creep ramp (grasp/compliant_grasp_creep.h), where k_t only regularizes:
    /// stiff, since full contact's regularized friction has no tangential spring.
    double creepTangentialStiffnessRatio = 10;
    /// Whether the PD targets follow the finger along its IK null space (file comment).
    bool ikFollowsNullSpace = true;
};

/// The model's answer for one load, with both friction coefficients of the contact pair.
struct CompliancePrediction {
    GraspCapacityRequest request;
    grasp::CompliantCapacity dynamicFriction;  ///< with mu_d
    grasp::CompliantCapacity staticFriction;   ///< with mu_s (the regularized law's peak)
    /// The creep ramp at the request's rate (the default rate if 0), with the scenario's friction law.
    grasp::CompliantRamp creep;
};

/// The finger joints' stiffness matrix K_q (N m/rad), over GraspScene::getFingerMobilizers() in
/// that order: passive springs (+ a limit stop's stiffness past its limit) on the diagonal, and the
/// PD gains kp either on the diagonal or, with settings.ikFollowsNullSpace, as kp J_E^+ J_E over
/// each goal end-effector E's chain (file comment). Realizes `state` to Stage::Position.
Eigen::MatrixXd calcFingerJointStiffness(const simulation::GraspScene& scene, const SimTK::State& state,
                                         const CompliancePredictionSettings& settings);

/// The finger's Cartesian compliance J K_q^-1 J^T (m/N, in G) at the material point of segment
/// `body` that is at `p_G` (m, in G), J its Jacobian over the finger joints and K_q
/// `jointStiffness` (calcFingerJointStiffness). Zero for a body no finger joint moves (the palm).
Eigen::Matrix3d calcFingerCompliance(const simulation::GraspScene& scene, const SimTK::State& state,
                                     const Eigen::MatrixXd& jointStiffness, const std::string& body, const SimTK::Vec3& p_G);

/// The compliance model's contacts at `state`, one per finger-object contact point with a positive
/// normal force (Stage::Velocity is realized here).
std::vector<grasp::CompliantContact> findCompliantContacts(const simulation::GraspScene& scene, const SimTK::State& state,
                                                           const CompliancePredictionSettings& settings);

/// The grasp at the load's start, as the compliance model sees it.
struct LoadStartGrasp {
    std::vector<grasp::CompliantContact> contacts;
    std::vector<std::string> bodies;  ///< the finger segment of each contact
    Eigen::Vector3d p_GO = Eigen::Vector3d::Zero();  ///< the object's centre of mass (m, in G)
};

/// Runs `scenario` in full compliant contact (the mode and contact of `options` are overridden;
/// its accuracy is used, with Simbody's CPodes) to the load's start and returns its contacts.
/// @throws graspsim::InputError for an invalid scenario; graspsim::NumericalError if no contact is
///         found at the load's start.
LoadStartGrasp findLoadStartGrasp(const scenario::Scenario& scenario, simulation::SimulationOptions options,
                                  const CompliancePredictionSettings& settings);

/// Predicts every request from findLoadStartGrasp's contacts.
std::vector<CompliancePrediction> predictGraspCapacities(const scenario::Scenario& scenario,
                                                         const simulation::SimulationOptions& options,
                                                         const std::vector<GraspCapacityRequest>& requests,
                                                         const CompliancePredictionSettings& settings);

/// One line: the request and the predicted first slip, slip onset and ultimate load with mu_d and
/// mu_s, and of the creep ramp.
std::string describePrediction(const CompliancePrediction& prediction);

}  // namespace graspsim::capacity
