#include "graspsim/grasp/limited_bushing_jacobian.h"

#include "graspsim/integration/point_jacobian.h"

#include <algorithm>

namespace graspsim::grasp {

LimitedBushingJacobian::LimitedBushingJacobian(const SimTK::SimbodyMatterSubsystem& matter, const LimitedBushing& bushing,
                                               const SimTK::MobilizedBody& bodyH, const SimTK::MobilizedBody& bodyO)
    : matter_(matter), bushing_(bushing), bodyH_(bodyH), bodyO_(bodyO) {}

void LimitedBushingJacobian::fillRelativeJacobian(const SimTK::State& state, std::vector<double>& J) const {
    std::fill(J.begin(), J.end(), 0.0);
    const SimTK::Vec3 p_GM = bodyO_.getBodyTransform(state) * bushing_.getFrameOnO(state).p();
    integration::addPointJacobian(matter_, state, bodyO_.getMobilizedBodyIndex(), p_GM, 1, 6, J);
    integration::addPointJacobian(matter_, state, bodyH_.getMobilizedBodyIndex(), p_GM, -1, 6, J);
    // Ground to A: R_AG = ~(R_GH R_HF R_FA).
    const SimTK::Rotation R_GA =
        bodyH_.getBodyRotation(state) * bushing_.getFrameOnH(state).R() * bushing_.findAnchorTransform(state).R();
    const int nu = state.getNU();
    for (int c = 0; c < nu; ++c) {
        double* column = &J[6 * static_cast<std::size_t>(c)];
        for (int block = 0; block < 6; block += 3) {
            const SimTK::Vec3 in_A = ~R_GA * SimTK::Vec3(column[block], column[block + 1], column[block + 2]);
            for (int r = 0; r < 3; ++r) column[block + r] = in_A[r];
        }
    }
}

void LimitedBushingJacobian::addForceJacobians(const SimTK::State& state, SimTK::Matrix& D, SimTK::Matrix& K) const {
    if (!bushing_.isEnabled(state)) return;
    SimTK::Vec6 damping = bushing_.getDamping(state);
    SimTK::Mat66 stiffness = bushing_.findStiffnessMatrix(state);
    // A sliding axis's force is its limit: no row of K (its load no longer sets the force).
    for (int k = 0; k < 6; ++k) {
        if (!bushing_.isSliding(state, static_cast<BushingAxis>(k))) continue;
        damping[k] = 0;
        for (int l = 0; l < 6; ++l) stiffness(k, l) = 0;
    }
    const int nu = state.getNU();
    std::vector<double> J(6 * static_cast<std::size_t>(nu));
    fillRelativeJacobian(state, J);
    std::vector<int> columns;
    integration::findNonzeroColumns(J, 6, nu, columns);
    double* d = D.updContiguousScalarData();
    double* s = K.updContiguousScalarData();
    // A -= J^T diag(w) J over J's nonzero columns.
    for (int c : columns) {
        const double* Jc = &J[6 * static_cast<std::size_t>(c)];
        for (int r : columns) {
            const double* Jr = &J[6 * static_cast<std::size_t>(r)];
            double dd = 0, kk = 0;
            for (int k = 0; k < 6; ++k) {
                dd += Jr[k] * damping[k] * Jc[k];
                kk += Jr[k] * stiffness(k, k) * Jc[k];
                for (int l = 0; l < 6; ++l) {
                    if (l != k && stiffness(k, l) != 0) kk += Jr[k] * stiffness(k, l) * Jc[l];
                }
            }
            d[r + nu * c] -= dd;
            s[r + nu * c] -= kk;
        }
    }
}

void LimitedBushingJacobian::appendActiveSet(const SimTK::State& state, std::vector<int>& active) const {
    if (!bushing_.isEnabled(state)) return;
    active.push_back(0);
    for (int k = 0; k < 6; ++k) {
        if (!bushing_.isSliding(state, static_cast<BushingAxis>(k))) active.push_back(1 + k);
    }
}

// Defined beside the Jacobian it makes, so that limited_bushing.cpp needs nothing of the stepper.
std::unique_ptr<integration::ForceJacobianContributor> LimitedBushing::makeForceJacobian(
    const SimTK::SimbodyMatterSubsystem& matter, const SimTK::MobilizedBody& bodyH, const SimTK::MobilizedBody& bodyO) const {
    return std::make_unique<LimitedBushingJacobian>(matter, *this, bodyH, bodyO);
}

}  // namespace graspsim::grasp
