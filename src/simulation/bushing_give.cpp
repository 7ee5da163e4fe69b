#include "graspsim/simulation/bushing_give.h"

#include "graspsim/grasp/compliance_limits.h"
#include "graspsim/grasp/grasp_stiffness.h"
#include "graspsim/grasp/limited_bushing_law.h"
#include "graspsim/simulation/finger_compliance.h"
#include "graspsim/system/simtk_conversion.h"

#include <cstdio>

namespace graspsim::simulation {

namespace {

// The model's stiffness (force first, in G) along M's axes with rotations first, symmetrized (the
// rolling part G need not be symmetric); none unless positive definite.
std::optional<SimTK::Mat66> findCoupledStiffness(const Eigen::Matrix<double, 6, 6>& K_G, const Eigen::Matrix3d& R_GM) {
    Eigen::Matrix<double, 6, 6> T = Eigen::Matrix<double, 6, 6>::Zero();  // [theta_M ; dp_M] = T [dp_G ; theta_G]
    T.block<3, 3>(0, 3) = R_GM.transpose();
    T.block<3, 3>(3, 0) = R_GM.transpose();
    const Eigen::Matrix<double, 6, 6> K_M = T * K_G * T.transpose();
    SimTK::Mat66 K;
    for (int r = 0; r < 6; ++r) {
        for (int c = 0; c < 6; ++c) K(r, c) = 0.5 * (K_M(r, c) + K_M(c, r));
    }
    if (!grasp::isPositiveDefinite(K)) return std::nullopt;
    return K;
}

}  // namespace

std::vector<grasp::CompliantContact> setModelGive(const ApproximationContext& context, const SimTK::State& state,
                                                  const std::vector<contact::ContactReport>& reports, const SimTK::Vec3& p_GM,
                                                  bool coupled, grasp::AttachmentEngagement& engagement) {
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
    if (coupled) engagement.stiffnessMatrix = findCoupledStiffness(K_G, R_GM);
    engagement.stiffness = stiffness;
    engagement.preload = preload;
    return contacts;
}

std::string describeModelGive(const grasp::AttachmentEngagement& engagement) {
    char text[200];
    if (engagement.stiffnessMatrix) {
        const SimTK::Mat66& K = *engagement.stiffnessMatrix;
        std::snprintf(text, sizeof text,
                      "; stiffness from the compliance model, 6 x 6 coupled, diagonal %.6g %.6g %.6g N m/rad, %.6g %.6g %.6g N/m",
                      K(0, 0), K(1, 1), K(2, 2), K(3, 3), K(4, 4), K(5, 5));
        return text;
    }
    if (!engagement.stiffness) return {};
    std::string result = "; rotational stiffness from the compliance model";
    for (int k = 0; k < 3; ++k) {
        const double value = (*engagement.stiffness)[k];
        std::snprintf(text, sizeof text, " %.6g", value);
        result += value > 0 ? std::string(text) : std::string(" (the bound's)");
    }
    return result + " N m/rad";
}

}  // namespace graspsim::simulation
