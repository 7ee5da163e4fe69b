#pragma once
/// @file
/// The deflected hand-back (ApproxHandBack::Deflected, `--hand-back deflected`): when the compliance
/// trigger (compliance_release.h) releases the merged bushing, full contact takes the object back
/// in the state the grasp's compliance model gives for the load the constraint carried, instead of
/// the state the grasp had at engagement.
///
/// Why: the bushing holds the object within a hundredth of a millimetre of its engaged pose, while
/// full contact gives way under the same load (the fingers bend, the pads compress, the friction
/// creeps: on the ball tripod 1.8 mm at the grasp goals and 0.3 rad just below slip onset). Handed
/// back engaged, full contact starts that give from zero at the load of the release and, under a
/// growing load, reaches slip onset only well beyond it (docs/capacity.md, "The planned scenes").
///
/// How: the load beyond engagement, w0 - R (R the constraint's reaction on the object, w0 the
/// contacts' wrench at the first engagement; both about O's origin along O's axes), is followed
/// through the compliance model of the first engagement (grasp::calcCompliantCapacityAlong, up to
/// the load itself; where the model gives way first, up to where it does). Its answer is the
/// object's displacement delta from the engaged pose (rotation vector about O's origin, then the
/// translation of O's origin, along O's axes) and each contact's force change df_i. The object is
/// placed at X_HO_engaged * delta relative to the palm, and the finger joints, unlocked, are bent
/// by dq = -K_q^-1 sum_i J_i^T df_i (FingerCompliance::calcJointDeflection). The pads' compression
/// follows from the two. Velocities are left as they are; the regularized friction of full contact
/// has no state of its own to set.

#include "graspsim/simulation/approximation_context.h"
#include "graspsim/simulation/compliance_release.h"

#include "graspsim/simbody.h"

#include <Eigen/Core>

#include <string>

namespace graspsim::simulation {

/// The compliance model's deflection of the grasp under a carried load.
struct HandBackDeflection {
    /// The object's displacement from its engaged pose in the palm: rotation vector (rad) about O's
    /// origin, then the translation of O's origin (m), along O's axes.
    SimTK::Vec6 displacement_O{0};
    /// The finger joints' deflection (rad), over the context's finger mobilizers in order.
    Eigen::VectorXd jointDeflection;
    /// The fraction of the carried load the model took up: 1, or less where it gave way first.
    double loadFraction = 1;
};

/// The deflection of the file comment for the constraint's reaction `reaction_O` on the object
/// (about O's origin, along O's axes, moment first: N m, N) and the first engagement's model
/// `limits` (with its contacts and their finger segments). The state is the engaged one: fingers
/// locked at their engagement angles. Realizes `state` to Stage::Position.
/// @throws graspsim::InputError when `limits` has no contacts or no finger segments for them.
HandBackDeflection calcHandBackDeflection(const ApproximationContext& context, const SimTK::State& state,
                                          const ComplianceReleaseLimits& limits, const SimTK::Vec6& reaction_O);

/// Places the object at `X_HO_engaged` (its engaged pose in the palm H) moved by the deflection,
/// and adds the joint deflection to the finger joints (which must be unlocked). Leaves velocities
/// alone; `state` needs realizing again.
void applyHandBackDeflection(const ApproximationContext& context, SimTK::State& state, const SimTK::Transform& X_HO_engaged,
                             const HandBackDeflection& deflection);

/// "; handed back deflected by 1.23 mm and 0.0456 rad (load fraction 1)" for the release event.
std::string describeHandBackDeflection(const HandBackDeflection& deflection);

}  // namespace graspsim::simulation
