#pragma once
/// @file
/// The fingers' compliance at their contacts with the object, for the compliance model of the
/// grasp (grasp/compliant_grasp_capacity.h): used by the holding-capacity prediction
/// (capacity/compliance_prediction.h) and by the approximation's compliance limits
/// (grasp_switch.h, `--limits compliance`).
///
/// Per finger-object contact point (from the contact reports):
///  - position, inward normal and force (normal and friction);
///  - the contact's normal stiffness linearized from Hertz at its depth, k_n = 3/2 f_n / x (the
///    Hunt-Crossley damping term is left out: the grasp is at rest);
///  - a tangential stiffness k_t = ratio k_n (Mindlin's 2/3 for skin by default);
///  - the finger's Cartesian compliance at the contact point, J K_q^-1 J^T, J the point's
///    Jacobian over the finger joints (relative to the palm: the arm does not count, as slip is
///    measured relative to the palm) and K_q the joints' stiffness: passive springs (+ the limit
///    stop's where a joint is past its limit) and the PD gains kp. The PD targets are not fixed:
///    every ik_interval the controller re-solves the fingertip IK warm-started from the present
///    joint angles, and a finger has one joint more (4) than its fingertip goal has coordinates
///    (3), so the targets follow the finger along the null space of its end-effector Jacobian J_E
///    and the gains resist only motions that move the end-effector: kp J_E^+ J_E (linearized:
///    q* - q0* = (1 - J_E^+ J_E)(q - q0)). Along the null space only the passive springs hold
///    the finger: a soft direction for contacts that are not at the end-effector.

#include "graspsim/contact/compliant_contact_force.h"
#include "graspsim/grasp/compliant_grasp_capacity.h"
#include "graspsim/system/implicit_joint_impedance.h"
#include "graspsim/system/multibody_model.h"

#include "graspsim/simbody.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace graspsim::simulation {

class GraspScene;
struct ApproximationContext;

/// The model's free choices at the contacts and fingers.
struct FingerComplianceSettings {
    double tangentialStiffnessRatio = 2.0 / 3.0;  ///< k_t / k_n (> 0)
    /// Whether the grasp's total k_t is shared in proportion to the normal forces, as full
    /// contact's creep shares friction (grasp::setTangentialStiffnessByNormalForce); false:
    /// each contact keeps tangentialStiffnessRatio k_n (Hertz-Mindlin's sharing).
    bool tangentialByNormalForce = true;
    /// Whether the PD targets follow the finger along its IK null space (file comment).
    bool ikFollowsNullSpace = true;
    /// Whether each contact gets its surfaces' curvatures (the finger pad's, 1 / its sphere's or
    /// capsule's radius; the object's, from the contact's effective Hertz radius), so that the
    /// model adds the preload's rolling stiffness (grasp/rolling_stiffness.h); false: frozen geometry.
    bool rolling = false;
};

/// The compliance model's contact for one contact report that presses (normal force and depth
/// > 0): point, inward normal, force (normal and friction) and the contact's own stiffnesses; the
/// finger's compliance left zero (FingerCompliance::findCompliantContacts adds it). nullopt for a
/// report that does not press.
std::optional<grasp::CompliantContact> findPressingContact(const contact::ContactReport& report,
                                                           const FingerComplianceSettings& settings);

/// The fingers of a scene, as the compliance model needs them. Holds a reference to `model`,
/// which must outlive it.
class FingerCompliance {
public:
    /// @param fingerMobilizers the finger joints (relative to the palm), in the order of K_q.
    /// @param jointImpedances every joint's stiffness (springs + PD) and stop; non-finger joints
    ///        are ignored.
    /// @param goalEndEffectors the end-effectors with IK goals (their chains follow the null space).
    FingerCompliance(const system::MultibodyModel& model, std::vector<SimTK::MobilizedBodyIndex> fingerMobilizers,
                     std::vector<system::JointImpedance> jointImpedances, std::vector<std::string> goalEndEffectors);

    /// The finger joints' stiffness matrix K_q (N m/rad), over the finger mobilizers in order:
    /// passive springs (+ a limit stop's stiffness past its limit) on the diagonal, and the PD
    /// gains kp either on the diagonal or, with ikFollowsNullSpace, as kp J_E^+ J_E over each goal
    /// end-effector E's chain (file comment). Realizes `state` to Stage::Position.
    Eigen::MatrixXd calcJointStiffness(const SimTK::State& state, bool ikFollowsNullSpace) const;

    /// The finger's Cartesian compliance J K_q^-1 J^T (m/N, in G) at the material point of segment
    /// `body` that is at `p_G` (m, in G), K_q `jointStiffness` (calcJointStiffness). Zero for a
    /// body no finger joint moves (the palm).
    Eigen::Matrix3d calcCompliance(const SimTK::State& state, const Eigen::MatrixXd& jointStiffness,
                                   const std::string& body, const SimTK::Vec3& p_G) const;

    /// The finger joints' deflection dq = -K_q^-1 sum_i J_i^T df_i (rad, over the finger mobilizers
    /// in order) that takes up the changes `forceChanges_G` (N, in G) of the forces the fingers
    /// exert on the object at the material points of segments `bodies` at `points_G` (m, in G): the
    /// object pushes back on each finger with -df_i. K_q is `jointStiffness` (calcJointStiffness).
    /// Realizes `state` to Stage::Position.
    /// @throws graspsim::InputError when the three lists differ in length.
    Eigen::VectorXd calcJointDeflection(const SimTK::State& state, const Eigen::MatrixXd& jointStiffness,
                                        const std::vector<std::string>& bodies, const std::vector<SimTK::Vec3>& points_G,
                                        const std::vector<Eigen::Vector3d>& forceChanges_G) const;

    /// The compliance model's contacts, one per report with a positive normal force and depth, in
    /// the reports' order (Stage::Velocity is realized here).
    std::vector<grasp::CompliantContact> findCompliantContacts(const SimTK::State& state,
                                                               const std::vector<contact::ContactReport>& reports,
                                                               const FingerComplianceSettings& settings) const;

private:
    Eigen::MatrixXd calcJacobian(const SimTK::State& state, const std::string& body, const SimTK::Vec3& p_G) const;
    Eigen::MatrixXd calcFollowedPdStiffness(const SimTK::State& state, const Eigen::VectorXd& kp) const;

    const system::MultibodyModel& model_;
    std::vector<SimTK::MobilizedBodyIndex> fingerMobilizers_;
    std::vector<system::JointImpedance> jointImpedances_;
    std::vector<std::string> goalEndEffectors_;
};

/// The fingers of `scene` (its finger mobilizers, joint impedances and goal end-effectors).
FingerCompliance makeFingerCompliance(const GraspScene& scene);

/// The same fingers as the approximation's switch sees them, from its context.
FingerCompliance makeFingerCompliance(const ApproximationContext& context);

}  // namespace graspsim::simulation
