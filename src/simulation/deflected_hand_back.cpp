#include "graspsim/simulation/deflected_hand_back.h"

#include "graspsim/error.h"
#include "graspsim/grasp/compliant_grasp_capacity.h"
#include "graspsim/simulation/finger_compliance.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace graspsim::simulation {

// Both the model's contacts and its displacement are along O's axes at the first engagement; the
// object has turned by no more than the bushing's deflection since, so they are taken along O's
// present axes.
HandBackDeflection calcHandBackDeflection(const ApproximationContext& context, const SimTK::State& state,
                                          const ComplianceReleaseLimits& limits, const SimTK::Vec6& reaction_O) {
    if (limits.contacts_O.empty() || limits.contactBodies.size() != limits.contacts_O.size()) {
        throw InputError("deflected hand-back: the compliance limits carry no contacts with their finger segments");
    }
    HandBackDeflection result;
    result.jointDeflection = Eigen::VectorXd::Zero(Eigen::Index(context.fingerMobilizers.size()));
    const Eigen::Matrix<double, 6, 1> load = findLoadBeyondEngagement(reaction_O, limits);
    if (load.isZero(0)) return result;
    const grasp::CompliantCapacity answer = followDirectionModel(limits, load, 1);  // up to the load itself
    result.loadFraction = std::isfinite(answer.ultimate) ? std::min(answer.ultimate, 1.0) : 1.0;
    for (int k = 0; k < 6; ++k) result.displacement_O[k] = answer.displacement_G[k];
    context.model.getSystem().realize(state, SimTK::Stage::Position);
    const SimTK::Transform& X_GO = context.object.getBodyTransform(state);
    std::vector<SimTK::Vec3> points_G;
    std::vector<Eigen::Vector3d> forceChanges_G;
    for (std::size_t i = 0; i < limits.contacts_O.size(); ++i) {
        const grasp::CompliantContact& c = limits.contacts_O[i];
        points_G.push_back(X_GO * SimTK::Vec3(c.p_GC.x(), c.p_GC.y(), c.p_GC.z()));
        const Eigen::Vector3d df_O = answer.forces_G[i] - c.force_G;
        const SimTK::Vec3 df_G = X_GO.R() * SimTK::Vec3(df_O.x(), df_O.y(), df_O.z());
        forceChanges_G.emplace_back(df_G[0], df_G[1], df_G[2]);
    }
    const FingerCompliance fingers = makeFingerCompliance(context);
    const Eigen::MatrixXd stiffness = fingers.calcJointStiffness(state, FingerComplianceSettings{}.ikFollowsNullSpace);
    result.jointDeflection = fingers.calcJointDeflection(state, stiffness, limits.contactBodies, points_G, forceChanges_G);
    return result;
}

void applyHandBackDeflection(const ApproximationContext& context, SimTK::State& state, const SimTK::Transform& X_HO_engaged,
                             const HandBackDeflection& deflection) {
    const SimTK::SimbodyMatterSubsystem& matter = context.model.getMatter();
    for (std::size_t k = 0; k < context.fingerMobilizers.size(); ++k) {
        const SimTK::MobilizedBody& joint = matter.getMobilizedBody(context.fingerMobilizers[k]);
        joint.setOneQ(state, 0, joint.getOneQ(state, 0) + deflection.jointDeflection[Eigen::Index(k)]);
    }
    const SimTK::Vec3 theta = deflection.displacement_O.getSubVec<3>(0);
    const SimTK::Rotation R_OO2 = theta.norm() > 0 ? SimTK::Rotation(theta.norm(), SimTK::UnitVec3(theta)) : SimTK::Rotation();
    const SimTK::Transform X_OO2(R_OO2, deflection.displacement_O.getSubVec<3>(3));
    context.model.getSystem().realize(state, SimTK::Stage::Position);
    const SimTK::Transform X_GO = context.palm.getBodyTransform(state) * X_HO_engaged * X_OO2;
    // The object's mobilizer joins frame F on its parent P to frame M on the object: X_FM =
    // X_PF^-1 X_GP^-1 X_GO X_OM.
    const SimTK::MobilizedBody& object = context.object;
    const SimTK::Transform X_GP = object.getParentMobilizedBody().getBodyTransform(state);
    const SimTK::Transform X_FM = ~object.getInboardFrame(state) * ~X_GP * X_GO * object.getOutboardFrame(state);
    object.setQToFitTransform(state, X_FM);
}

std::string describeHandBackDeflection(const HandBackDeflection& deflection) {
    char text[160];
    std::snprintf(text, sizeof text, "; handed back deflected by %.6g mm and %.6g rad (load fraction %.6g)",
                  1e3 * deflection.displacement_O.getSubVec<3>(3).norm(), deflection.displacement_O.getSubVec<3>(0).norm(),
                  deflection.loadFraction);
    return text;
}

}  // namespace graspsim::simulation
