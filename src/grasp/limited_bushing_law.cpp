#include "graspsim/grasp/limited_bushing_law.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "graspsim/error.h"

namespace graspsim::grasp {

double calcSlipFraction(double stiffness, double limit, double onsetWidth, double e, double r) {
    // Only loading slips: unloading (e r < 0) and rest (r = 0) stick, which keeps a held object
    // from creeping and makes reversal elastic, as in elasto-plastic (and Dahl) friction.
    if (!(e * r > 0) || std::isinf(limit)) return 0;
    const double u = limit > 0 ? stiffness * std::abs(e) / limit : SimTK::Infinity;
    if (u > 1) {
        // Past the limit (an integrator's overshoot, or drift of e = relative pose - anchor,
        // a difference of two large integrated quantities): the anchor outruns the relative
        // motion a little, pulling |K e| back to L while loading. C1 at u = 1.
        if (std::isinf(u)) return 1;
        const double excess = (u - 1) / onsetWidth;
        return 1 + excess * excess;
    }
    const double t = std::max(0.0, (u - (1 - onsetWidth)) / onsetWidth);
    // C1 smoothstep: zdot stays continuous in the state, so error-controlled integrators see
    // no discontinuity at slip onset (the hard switch is the limit onsetWidth -> 0).
    return t * t * (3 - 2 * t);
}

double calcAxisForce(double stiffness, double damping, double limit, double e, double edot) {
    // The clamp bounds the damping transient too: the element never transmits more than the
    // friction limit, whatever the elastic state.
    return std::clamp(-stiffness * e - damping * edot, -limit, limit);
}

double findLoadedSideLimit(double lower, double upper, double e) { return e < 0 ? upper : lower; }

double calcTwoSidedSlipFraction(double stiffness, double lower, double upper, double onsetWidth, double e, double r) {
    return calcSlipFraction(stiffness, findLoadedSideLimit(lower, upper, e), onsetWidth, e, r);
}

double calcTwoSidedAxisForce(double stiffness, double damping, double lower, double upper, double e, double edot) {
    return std::clamp(-stiffness * e - damping * edot, -lower, upper);
}

SimTK::Vec6 applyAxisLocks(const SimTK::Vec6& limits, const std::array<bool, 6>& locked) {
    SimTK::Vec6 result = limits;
    for (int k = 0; k < 6; ++k) {
        if (locked[k]) result[k] = SimTK::Infinity;
    }
    return result;
}

SimTK::Vec6 findLargerSide(const SimTK::Vec6& lower, const SimTK::Vec6& upper) {
    SimTK::Vec6 result;
    for (int k = 0; k < 6; ++k) result[k] = std::max(lower[k], upper[k]);
    return result;
}

bool isPositiveDefinite(const SimTK::Mat66& K) {
    double L[6][6] = {};
    for (int j = 0; j < 6; ++j) {
        double d = K(j, j);
        for (int k = 0; k < j; ++k) d -= L[j][k] * L[j][k];
        if (!(d > 0)) return false;
        L[j][j] = std::sqrt(d);
        for (int i = j + 1; i < 6; ++i) {
            double v = K(i, j);
            for (int k = 0; k < j; ++k) v -= L[i][k] * L[j][k];
            L[i][j] = v / L[j][j];
        }
    }
    return true;
}

void checkStiffnessMatrix(const SimTK::Mat66& K) {
    for (int r = 0; r < 6; ++r) {
        for (int c = 0; c < 6; ++c) {
            if (!std::isfinite(K(r, c)) || std::abs(K(r, c) - K(c, r)) > 1e-9 * (std::abs(K(r, c)) + std::abs(K(c, r)))) {
                throw InputError("limited bushing stiffness matrix entry (" + std::to_string(r) + ", " + std::to_string(c) +
                                 ") is " + std::to_string(K(r, c)) + "; accepted: finite and symmetric");
            }
        }
    }
    if (!isPositiveDefinite(K)) throw InputError("limited bushing stiffness matrix is not positive definite");
}

SimTK::Vec3 calcRotationVector(const SimTK::Rotation& R) {
    const SimTK::Vec4 angleAxis = R.convertRotationToAngleAxis();
    return angleAxis[0] * SimTK::Vec3(angleAxis[1], angleAxis[2], angleAxis[3]);
}

SimTK::Rotation calcRotationFromVector(const SimTK::Vec3& theta) {
    const double angle = theta.norm();
    if (angle == 0) return SimTK::Rotation();
    return SimTK::Rotation(angle, SimTK::UnitVec3(theta / angle, true));
}

SimTK::Vec3 calcRotationVectorRate(const SimTK::Vec3& theta, const SimTK::Vec3& w_PB_B) {
    const double phi = theta.norm();
    // (1 - (phi/2) cot(phi/2)) / phi^2 loses all digits as phi -> 0; its series is exact to
    // double precision below 1e-3 rad.
    const double c = phi < 1e-3 ? 1.0 / 12 + phi * phi / 720
                                : (1 - 0.5 * phi / std::tan(0.5 * phi)) / (phi * phi);
    const SimTK::Vec3 thetaCrossW = theta % w_PB_B;
    return w_PB_B + 0.5 * thetaCrossW + c * (theta % thetaCrossW);
}

SimTK::Vec6 calcStiffnessForBound(const SimTK::Vec6& minimum, const SimTK::Vec6& loads, double leverArm, double bound) {
    const double perAxis = bound / (2 * std::sqrt(3.0));
    SimTK::Vec6 stiffness;
    for (int k = 0; k < 6; ++k) stiffness[k] = std::max(minimum[k], loads[k] * (k < 3 ? leverArm : 1.0) / perAxis);
    return stiffness;
}

SimTK::Vec6 calcCriticalDamping(const SimTK::Vec6& stiffness, const SimTK::Vec3& centralMoments, double mass) {
    SimTK::Vec6 damping;
    for (int k = 0; k < 3; ++k) {
        damping[k] = 2 * std::sqrt(stiffness[k] * centralMoments[k]);
        damping[k + 3] = 2 * std::sqrt(stiffness[k + 3] * mass);
    }
    return damping;
}

}  // namespace graspsim::grasp
