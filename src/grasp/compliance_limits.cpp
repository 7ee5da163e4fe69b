#include "graspsim/grasp/compliance_limits.h"

#include "graspsim/error.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>

namespace graspsim::grasp {

using Vector6 = Eigen::Matrix<double, 6, 1>;

Vector6 calcContactWrenchInM(const std::vector<CompliantContact>& contacts, const Eigen::Matrix3d& R_GM,
                             const Eigen::Vector3d& p_GM) {
    Eigen::Vector3d moment = Eigen::Vector3d::Zero(), force = Eigen::Vector3d::Zero();
    for (const CompliantContact& c : contacts) {
        moment += (c.p_GC - p_GM).cross(c.force_G);
        force += c.force_G;
    }
    Vector6 w;
    w << R_GM.transpose() * moment, R_GM.transpose() * force;
    return w;
}

TwoSidedLimits calcComplianceLimits(const std::vector<CompliantContact>& contacts, const Eigen::Matrix3d& R_GM,
                                    const Eigen::Vector3d& p_GM, const ComplianceLimitOptions& options) {
    for (int k = 0; k < 6; ++k) {
        if (!(options.maxLoads[k] > 0) || !std::isfinite(options.maxLoads[k])) {
            throw InputError("compliance limits: the largest load on axis " + std::to_string(k) + " (" +
                             std::to_string(options.maxLoads[k]) + ") must be finite and > 0");
        }
    }
    const Vector6 w0 = calcContactWrenchInM(contacts, R_GM, p_GM);
    TwoSidedLimits limits;
    for (int k = 0; k < 6; ++k) {
        CompliantCapacityOptions o;
        o.mu = options.mu;
        o.kineticMu = options.kineticMu;
        o.slipDistance = options.slipDistance;
        o.slipPoints_G = options.slipPoints_G;
        o.maxLoad = options.maxLoads[k];
        double onset[2];  // loads along +e_k, -e_k
        for (int side = 0; side < 2; ++side) {
            Vector6 direction = Vector6::Zero();
            direction.segment<3>(k < 3 ? 0 : 3) = (side == 0 ? 1.0 : -1.0) * R_GM.col(k % 3);
            const double c = calcCompliantCapacity(contacts, p_GM, direction, o).onset;
            onset[side] = std::isfinite(c) ? std::min(c, o.maxLoad) : o.maxLoad;
        }
        limits.lower[k] = std::clamp(onset[0] - w0[k], 0.0, o.maxLoad);
        limits.upper[k] = std::clamp(w0[k] + onset[1], 0.0, o.maxLoad);
    }
    return limits;
}

}  // namespace graspsim::grasp
