#pragma once
/// @file
/// Locked fingers that follow the object's give (with the bushing's rotational give,
/// ApproxOptions::bushingGive Model; docs/capacity.md, "The bushing's rotational give").
///
/// While the merged bushing holds the object, the finger joints are locked to the palm and the
/// contact pairs are off. With the give the object turns in the palm under a load, as in full
/// contact. Left where they were, the locked pads would stay put: the object's surface would move
/// into the pads on one side and away from them on the other, and at the hand-back full contact
/// would take over fingers that carry none of the load the object's turn stands for (it then turned
/// the object as far again before its fingers took the load).
///
/// In the compliance model of the grasp (grasp/compliant_grasp_capacity.h) the finger and the
/// contact are springs in series at each contact C: the finger's Cartesian compliance C_f (J K_q^-1
/// J^T) and the contact's own, C_c = n n^T / k_n + (1 - n n^T) / k_t. When the object's material
/// point at C moves by delta relative to the palm, the contact force changes by (C_f + C_c)^-1 delta,
/// and the finger's point moves by its share, C_f (C_f + C_c)^-1 delta; the rest is the contact's
/// compression and shear. followObjectGive places the locked fingers there and locks them again at
/// the new angles. The joints move as the model's finger would: C_f comes from the joints'
/// stiffness K_q, and the motion dq that brings the pads to their targets with the least elastic
/// energy dq^T K_q dq is the one a force at the pads produces, dq = K_q^-1 J^T f. Over all pads at
/// once, since two pads may share a joint; where the joints cannot reach every target, the
/// energy-weighted least-squares fit.

#include "graspsim/contact/compliant_contact_force.h"
#include "graspsim/grasp/compliant_grasp_capacity.h"
#include "graspsim/simulation/approximation_context.h"

#include "graspsim/simbody.h"

#include <Eigen/Core>

#include <vector>

namespace graspsim::simulation {

/// One pressing contact at engagement, as its finger follows the object.
struct FollowedPad {
    SimTK::MobilizedBodyIndex segment;  ///< the finger segment that carries the pad
    SimTK::Vec3 p_SC;                   ///< the contact point as a station of the segment (m)
    SimTK::Vec3 p_OC;                   ///< the contact point as a material point of the object (m, in O)
    SimTK::Vec3 p_HC;                   ///< the contact point in the palm H at engagement (m, in H)
    /// The finger's share C_f (C_f + C_c)^-1 of the object point's motion (file comment), in H's axes.
    SimTK::Mat33 share_H;
};

/// The pads of one engagement and the finger joints' compliance they move with.
struct FollowedGrasp {
    std::vector<FollowedPad> pads;
    /// L with L L^T = K_q^-1 at engagement (rad/(N m)), over the context's finger mobilizers in order.
    Eigen::MatrixXd jointComplianceRoot;
};

/// The finger's share C_f (C_f + C_c)^-1 of the motion of the object's point at `contact` (file
/// comment), in the contact's frame of expression (G): zero for a rigid finger; along a direction in
/// which the contact does not give (k_t infinite), the finger takes the whole motion.
Eigen::Matrix3d calcFingerShare(const grasp::CompliantContact& contact);

/// One pad per report that presses (normal force and depth > 0), in the reports' order, with
/// `contacts` the compliance model's contacts of those reports in the same order
/// (FingerCompliance::findCompliantContacts), and the finger joints' compliance now
/// (FingerCompliance::calcJointStiffness). Realizes `state` to Stage::Position.
/// @throws graspsim::InputError when the pressing reports and `contacts` differ in number, or the
///         joints' stiffness is not positive definite.
FollowedGrasp captureFollowedGrasp(const ApproximationContext& context, const SimTK::State& state,
                                   const std::vector<contact::ContactReport>& reports,
                                   const std::vector<grasp::CompliantContact>& contacts);

/// Moves the locked finger joints so that the pads reach their targets (file comment) and locks
/// them at the new angles, when the move would bring a pad more than `tolerance` (m) nearer its
/// target; otherwise leaves them. The fingers must be locked (Motion::Position). Realizes `state`
/// to Stage::Position.
void followObjectGive(const ApproximationContext& context, SimTK::State& state, const FollowedGrasp& grasp, double tolerance);

}  // namespace graspsim::simulation
