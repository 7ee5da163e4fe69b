#include "graspsim/simulation/bushing_give.h"

#include "graspsim/grasp/compliance_limits.h"
#include "graspsim/grasp/grasp_stiffness.h"
#include "graspsim/simulation/finger_compliance.h"
#include "graspsim/system/simtk_conversion.h"

namespace graspsim::simulation {

std::vector<grasp::CompliantContact> setModelGive(const ApproximationContext& context, const SimTK::State& state,
                                                  const std::vector<contact::ContactReport>& reports, const SimTK::Vec3& p_GM,
                                                  grasp::AttachmentEngagement& engagement) {
    FingerComplianceSettings settings;
    settings.rolling = true;
    const std::vector<grasp::CompliantContact> contacts =
        makeFingerCompliance(context).findCompliantContacts(state, reports, settings);
    if (contacts.empty()) return contacts;
    const Eigen::Matrix3d R_GM = system::toEigenMatrix(context.object.getBodyTransform(state).R());
    const Eigen::Vector3d p = system::toEigenVector(p_GM);
    // Force first in the model; its rotational block in M's axes is R_MG K_rr R_GM.
    const Eigen::Matrix<double, 6, 6> K_G = grasp::calcStickingGraspStiffness(contacts, p);
    const Eigen::Matrix3d K_rr_M = R_GM.transpose() * K_G.block<3, 3>(3, 3) * R_GM;
    SimTK::Vec6 stiffness(SimTK::NaN);
    for (int k = 0; k < 3; ++k) {
        if (K_rr_M(k, k) > 0) stiffness[k] = K_rr_M(k, k);
    }
    const Eigen::Matrix<double, 6, 1> w0 = grasp::calcContactWrenchInM(contacts, R_GM, p);
    SimTK::Vec6 preload;
    for (int k = 0; k < 6; ++k) preload[k] = w0[k];
    engagement.stiffness = stiffness;
    engagement.preload = preload;
    return contacts;
}

}  // namespace graspsim::simulation
