#include "graspsim/simulation/finger_follow.h"

#include "graspsim/error.h"
#include "graspsim/simulation/finger_compliance.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <string>

namespace graspsim::simulation {

namespace {

SimTK::Mat33 toMat33(const Eigen::Matrix3d& m) {
    SimTK::Mat33 result;
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) result(r, c) = m(r, c);
    }
    return result;
}

// Each pad's target minus its point now (m, in G), stacked.
Eigen::VectorXd calcFollowError(const ApproximationContext& context, const SimTK::State& state, const std::vector<FollowedPad>& pads) {
    const SimTK::SimbodyMatterSubsystem& matter = context.model.getMatter();
    context.model.getSystem().realize(state, SimTK::Stage::Position);
    const SimTK::Transform& X_GO = context.object.getBodyTransform(state);
    const SimTK::Transform& X_GH = context.palm.getBodyTransform(state);
    Eigen::VectorXd error(3 * Eigen::Index(pads.size()));
    for (std::size_t i = 0; i < pads.size(); ++i) {
        const FollowedPad& pad = pads[i];
        const SimTK::Vec3 delta_H = ~X_GH * (X_GO * pad.p_OC) - pad.p_HC;
        const SimTK::Vec3 target_G = X_GH * (pad.p_HC + pad.share_H * delta_H);
        const SimTK::Vec3 e = target_G - matter.getMobilizedBody(pad.segment).findStationLocationInGround(state, pad.p_SC);
        for (int a = 0; a < 3; ++a) error[3 * Eigen::Index(i) + a] = e[a];
    }
    return error;
}

// The pads' points' Jacobian over the finger joints (one column per finger mobilizer, in G), stacked
// as calcFollowError's rows. Needs Stage::Position.
Eigen::MatrixXd calcPadJacobian(const ApproximationContext& context, const SimTK::State& state, const std::vector<FollowedPad>& pads) {
    const SimTK::SimbodyMatterSubsystem& matter = context.model.getMatter();
    const Eigen::Index joints = Eigen::Index(context.fingerMobilizers.size());
    Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(3 * Eigen::Index(pads.size()), joints);
    for (std::size_t i = 0; i < pads.size(); ++i) {
        SimTK::Matrix J;
        matter.calcStationJacobian(state, pads[i].segment, pads[i].p_SC, J);
        for (Eigen::Index k = 0; k < joints; ++k) {
            const int u = int(matter.getMobilizedBody(context.fingerMobilizers[std::size_t(k)]).getFirstUIndex(state));
            for (int a = 0; a < 3; ++a) jacobian(3 * Eigen::Index(i) + a, k) = J(a, u);
        }
    }
    return jacobian;
}

double findLargestPadDistance(const Eigen::VectorXd& stacked) {
    double largest = 0;
    for (Eigen::Index i = 0; i + 2 < stacked.size(); i += 3) largest = std::max(largest, stacked.segment<3>(i).norm());
    return largest;
}

}  // namespace

// A contact that does not give tangentially (k_t infinite) has no tangential term; the sum is then
// singular along the tangents where the finger is rigid too, and the pseudo-inverse gives such a
// direction no share.
Eigen::Matrix3d calcFingerShare(const grasp::CompliantContact& c) {
    const Eigen::Matrix3d nn = c.n_G * c.n_G.transpose();
    Eigen::Matrix3d contactCompliance = nn / c.normalStiffness;
    if (std::isfinite(c.tangentialStiffness)) contactCompliance += (Eigen::Matrix3d::Identity() - nn) / c.tangentialStiffness;
    const Eigen::Matrix3d sum = c.fingerCompliance_G + contactCompliance;
    return c.fingerCompliance_G * sum.completeOrthogonalDecomposition().pseudoInverse();
}

FollowedGrasp captureFollowedGrasp(const ApproximationContext& context, const SimTK::State& state,
                                   const std::vector<contact::ContactReport>& reports,
                                   const std::vector<grasp::CompliantContact>& contacts) {
    const auto pressing = std::count_if(reports.begin(), reports.end(),
                                        [](const contact::ContactReport& r) { return r.normalForce > 0 && r.depth > 0; });
    if (std::size_t(pressing) != contacts.size()) {
        throw InputError("finger follow: " + std::to_string(pressing) + " pressing contacts but " +
                         std::to_string(contacts.size()) + " compliance-model contacts");
    }
    const Eigen::MatrixXd K = makeFingerCompliance(context).calcJointStiffness(state, FingerComplianceSettings{}.ikFollowsNullSpace);
    const Eigen::LLT<Eigen::MatrixXd> compliance(K.allFinite() ? Eigen::MatrixXd(K.inverse()) : K);
    if (!K.allFinite() || compliance.info() != Eigen::Success) {
        throw InputError("finger follow: the finger joints' stiffness is not positive definite");
    }
    const SimTK::Transform& X_GO = context.object.getBodyTransform(state);
    const SimTK::Transform& X_GH = context.palm.getBodyTransform(state);
    FollowedGrasp grasp{{}, compliance.matrixL()};
    for (const contact::ContactReport& report : reports) {
        if (!(report.normalForce > 0) || !(report.depth > 0)) continue;
        const grasp::CompliantContact& c = contacts[grasp.pads.size()];
        const SimTK::MobilizedBody& segment = context.model.getMobilizedBody(report.bodyA);
        const SimTK::Mat33 share_G = toMat33(calcFingerShare(c));
        grasp.pads.push_back({segment.getMobilizedBodyIndex(), segment.findStationAtGroundPoint(state, report.p_G), ~X_GO * report.p_G,
                              ~X_GH * report.p_G, ~X_GH.R() * share_G * X_GH.R()});
    }
    return grasp;
}

// The move is judged by what the joints can do: where two pads share a finger the least-squares
// fit leaves a residual, and a tolerance on the residual itself would re-lock the fingers at every
// check without moving them. With dq = L y (L L^T = K_q^-1) the energy dq^T K_q dq is |y|^2: the
// least-norm least-squares y of (J L) y = e is the least-energy move.
void followObjectGive(const ApproximationContext& context, SimTK::State& state, const FollowedGrasp& grasp, double tolerance) {
    if (grasp.pads.empty()) return;
    // J dq is e projected orthogonally onto what the joints can reach, so no pad moves farther
    // than |e|: below the tolerance the least-squares solve is skipped (most checks of a hold).
    const Eigen::VectorXd error = calcFollowError(context, state, grasp.pads);
    if (!(error.norm() > tolerance)) return;
    const Eigen::MatrixXd jacobian = calcPadJacobian(context, state, grasp.pads);
    const Eigen::MatrixXd& L = grasp.jointComplianceRoot;
    const Eigen::VectorXd dq = L * (jacobian * L).completeOrthogonalDecomposition().solve(error);
    if (!(findLargestPadDistance(jacobian * dq) > tolerance)) return;
    const SimTK::SimbodyMatterSubsystem& matter = context.model.getMatter();
    for (std::size_t k = 0; k < context.fingerMobilizers.size(); ++k) {
        const SimTK::MobilizedBody& joint = matter.getMobilizedBody(context.fingerMobilizers[k]);
        joint.lockAt(state, joint.getOneQ(state, 0) + dq[Eigen::Index(k)], SimTK::Motion::Position);
    }
}

}  // namespace graspsim::simulation
