#pragma once
/// @file
/// The holding capacity predicted by the grasp's compliance model (grasp/compliant_grasp_capacity.h)
/// from a full-contact run's state at the load's start, without ramping: a research step of issue
/// 17 (docs/capacity.md, "A compliance model of the capacity").
///
/// The grasp is run in full compliant contact up to the load's start (settle_time + 0.1 s, as the
/// ramp). There its contacts, with their stiffness and the fingers' compliance, are those of
/// simulation/finger_compliance.h.

#include "graspsim/capacity/grasp_capacity.h"
#include "graspsim/grasp/compliant_grasp_capacity.h"
#include "graspsim/grasp/compliant_grasp_creep.h"
#include "graspsim/scenario/scenario.h"
#include "graspsim/simulation/finger_compliance.h"
#include "graspsim/simulation/grasp_scene.h"
#include "graspsim/simulation/simulation_options.h"

#include <string>
#include <vector>

namespace graspsim::capacity {

/// The model's free choices.
struct CompliancePredictionSettings {
    double tangentialStiffnessRatio = 2.0 / 3.0;  ///< k_t / k_n (> 0)
    /// The total k_t shared by normal force (simulation::FingerComplianceSettings)
    bool tangentialByNormalForce = true;
    /// k_t / k_n of the creep ramp (grasp/compliant_grasp_creep.h), where k_t only regularizes:
    /// stiff, since full contact's regularized friction has no tangential spring.
    double creepTangentialStiffnessRatio = 10;
    /// Whether the PD targets follow the finger along its IK null space (simulation/finger_compliance.h).
    bool ikFollowsNullSpace = true;
    /// Whether the contacts' curvatures add the preload's rolling stiffness (simulation/finger_compliance.h).
    bool rolling = false;
};

/// The model's answer for one load, with both friction coefficients of the contact pair.
struct CompliancePrediction {
    GraspCapacityRequest request;
    grasp::CompliantCapacity dynamicFriction;  ///< with mu_d
    grasp::CompliantCapacity staticFriction;   ///< breaking loose at mu_s (the regularized law's peak), sliding at mu_d
    /// The creep ramp at the request's rate (the default rate if 0), with the scenario's friction law.
    grasp::CompliantRamp creep;
};

/// The finger settings of `settings` (simulation/finger_compliance.h).
simulation::FingerComplianceSettings toFingerSettings(const CompliancePredictionSettings& settings);

/// The grasp at the load's start, as the compliance model sees it.
struct LoadStartGrasp {
    std::vector<grasp::CompliantContact> contacts;
    std::vector<std::string> bodies;  ///< the finger segment of each contact
    Eigen::Vector3d p_GO = Eigen::Vector3d::Zero();  ///< the object's centre of mass (m, in G)
    std::vector<Eigen::Vector3d> goals_G;  ///< the grasp goals' material points (m, in G)
};

/// Runs `scenario` in full compliant contact (the mode and contact of `options` are overridden;
/// its accuracy is used, with Simbody's CPodes) to the load's start and returns its contacts.
/// @throws graspsim::InputError for an invalid scenario; graspsim::NumericalError if no contact is
///         found at the load's start.
LoadStartGrasp findLoadStartGrasp(const scenario::Scenario& scenario, simulation::SimulationOptions options,
                                  const CompliancePredictionSettings& settings);

/// Predicts every request from findLoadStartGrasp's contacts, its slip onset at the request's
/// criteria.slip (the displacement the ramp's onset is measured at).
std::vector<CompliancePrediction> predictGraspCapacities(const scenario::Scenario& scenario,
                                                         const simulation::SimulationOptions& options,
                                                         const std::vector<GraspCapacityRequest>& requests,
                                                         const CompliancePredictionSettings& settings);

/// One line: the request and the predicted first slip, slip onset and ultimate load with mu_d and
/// mu_s, and of the creep ramp.
std::string describePrediction(const CompliancePrediction& prediction);

}  // namespace graspsim::capacity
