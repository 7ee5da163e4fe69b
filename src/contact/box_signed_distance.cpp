#include "box_signed_distance.h"

#include <algorithm>
#include <cmath>

namespace graspsim::contact {

double calcBoxSignedDistance(const SimTK::Vec3& h, const SimTK::Vec3& p_S) {
    double outsideSquared = 0, deepest = -SimTK::Infinity;
    for (int i = 0; i < 3; ++i) {
        const double q = std::abs(p_S[i]) - h[i];
        if (q > 0) outsideSquared += q * q;
        deepest = std::max(deepest, q);
    }
    return outsideSquared > 0 ? std::sqrt(outsideSquared) : deepest;
}

namespace {

BoxSurfacePoint findOutsideSurface(const SimTK::Vec3& h, const SimTK::Vec3& p_S) {
    SimTK::Vec3 d_S(0);  // from the closest box point to p_S
    for (int i = 0; i < 3; ++i) {
        d_S[i] = p_S[i] - std::clamp(p_S[i], -h[i], h[i]);
    }
    BoxSurfacePoint result;
    result.distance = d_S.norm();
    result.n_S = SimTK::UnitVec3(d_S / result.distance, true);
    return result;
}

BoxSurfacePoint findInsideSurface(const SimTK::Vec3& h, const SimTK::Vec3& p_S) {
    SimTK::Vec3 q;  // depth below the nearer face of each axis, <= 0
    for (int i = 0; i < 3; ++i) q[i] = std::abs(p_S[i]) - h[i];
    BoxSurfacePoint result;
    result.distance = std::max({q[0], q[1], q[2]});
    result.tiedAxisCount = 0;
    SimTK::Vec3 sum(0);
    for (int i = 0; i < 3; ++i) {
        if (q[i] < result.distance - kBoxFaceTieTolerance) continue;
        // On the mid-plane (p_i = 0) both faces are equally near; take the + face.
        const int sign = p_S[i] < 0 ? -1 : 1;
        sum[i] = sign;
        result.tiedAxes[result.tiedAxisCount] = i;
        result.tiedSigns[result.tiedAxisCount] = sign;
        ++result.tiedAxisCount;
    }
    result.n_S = SimTK::UnitVec3(sum);  // a sum of distinct unit axes is never zero
    return result;
}

}  // namespace

BoxSurfacePoint findBoxSurface(const SimTK::Vec3& h, const SimTK::Vec3& p_S) {
    for (int i = 0; i < 3; ++i) {
        if (std::abs(p_S[i]) > h[i]) return findOutsideSurface(h, p_S);
    }
    return findInsideSurface(h, p_S);
}

}  // namespace graspsim::contact
