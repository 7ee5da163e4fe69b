#include "ellipsoid_distance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace graspsim::contact {

namespace {

// Iterations until the bracket cannot shrink: bisection alone needs at most about 1100 halvings
// of a double interval; the Newton steps below usually finish in 5-20.
constexpr int kMaxIterations = 1100;

double calcRobustLength(double a, double b, double c = 0) {
    const double m = std::max({std::abs(a), std::abs(b), std::abs(c)});
    if (m == 0) return 0;
    return m * std::sqrt((a / m) * (a / m) + (b / m) * (b / m) + (c / m) * (c / m));
}

// Root s of S(s) = sum_k (r_k z_k / (s + r_k))^2 = 1 over the n = 2 or 3 terms (r_{n-1} = 1),
// g = S(0) - 1. Eberly's bracket [s0, s1] holds the root, S(s0) >= 1 >= S(s1). Newton steps
// are taken on phi(s) = 1 / sqrt(S(s)) - 1, which is nearly linear in s (exactly so for one
// term), when they stay strictly inside the bracket; otherwise the bracket is bisected as in
// Eberly's robust method. Ends when the bracket cannot shrink: the root to the last bit.
double findRoot(int n, const double* r, const double* z, double g) {
    std::array<double, 3> num{};
    for (int i = 0; i < n; ++i) num[i] = r[i] * z[i];
    double s0 = z[n - 1] - 1;
    double s1 = g < 0 ? 0 : calcRobustLength(num[0], num[1], n == 3 ? num[2] : 0) - 1;
    double s = s0;
    for (int i = 0; i < kMaxIterations; ++i) {
        double sum = 0, slope = 0;  // S(s) and dS/ds
        for (int k = 0; k < n; ++k) {
            const double ratio = num[k] / (s + r[k]);
            sum += ratio * ratio;
            slope -= 2 * ratio * ratio / (s + r[k]);
        }
        if (sum == 1) return s;
        (sum > 1 ? s0 : s1) = s;
        const double root = std::sqrt(sum);
        const double phi = 1 / root - 1, dPhi = -0.5 * slope / (sum * root);
        double next = dPhi > 0 ? s - phi / dPhi : s0;
        if (next == s) return s;  // Newton has converged: the step is below s's last bit
        if (!(next > s0 && next < s1)) next = 0.5 * (s0 + s1);
        if (next <= s0 || next >= s1) return s;  // no double strictly inside the bracket
        s = next;
    }
    return s;
}

// Ellipse e0 >= e1 > 0, query y0, y1 >= 0; writes the nearest point x.
void findEllipsePoint(double e0, double e1, double y0, double y1, double& x0, double& x1) {
    if (y1 > 0) {
        if (y0 > 0) {
            const double z[2] = {y0 / e0, y1 / e1};
            const double g = z[0] * z[0] + z[1] * z[1] - 1;
            if (g != 0) {
                const double r[2] = {(e0 / e1) * (e0 / e1), 1};
                const double s = findRoot(2, r, z, g);
                x0 = r[0] * y0 / (s + r[0]);
                x1 = y1 / (s + 1);
            } else {
                x0 = y0, x1 = y1;
            }
        } else {
            x0 = 0, x1 = e1;
        }
        return;
    }
    const double numer0 = e0 * y0, denom0 = e0 * e0 - e1 * e1;
    if (numer0 < denom0) {
        const double xde0 = numer0 / denom0;
        x0 = e0 * xde0;
        x1 = e1 * std::sqrt(1 - xde0 * xde0);
    } else {
        x0 = e0, x1 = 0;
    }
}

// Ellipsoid e0 >= e1 >= e2 > 0, query y >= 0 componentwise; writes the nearest point x.
void findSortedPoint(const double* e, const double* y, double* x) {
    if (y[2] > 0) {
        if (y[1] > 0) {
            if (y[0] > 0) {
                const double z[3] = {y[0] / e[0], y[1] / e[1], y[2] / e[2]};
                const double g = z[0] * z[0] + z[1] * z[1] + z[2] * z[2] - 1;
                if (g == 0) {
                    x[0] = y[0], x[1] = y[1], x[2] = y[2];
                    return;
                }
                const double r[3] = {(e[0] / e[2]) * (e[0] / e[2]), (e[1] / e[2]) * (e[1] / e[2]), 1};
                const double s = findRoot(3, r, z, g);
                for (int i = 0; i < 3; ++i) x[i] = r[i] * y[i] / (s + r[i]);
            } else {
                x[0] = 0;
                findEllipsePoint(e[1], e[2], y[1], y[2], x[1], x[2]);
            }
        } else if (y[0] > 0) {
            x[1] = 0;
            findEllipsePoint(e[0], e[2], y[0], y[2], x[0], x[2]);
        } else {
            x[0] = 0, x[1] = 0, x[2] = e[2];
        }
        return;
    }
    const double denom0 = e[0] * e[0] - e[2] * e[2], denom1 = e[1] * e[1] - e[2] * e[2];
    const double numer0 = e[0] * y[0], numer1 = e[1] * y[1];
    if (numer0 < denom0 && numer1 < denom1) {
        const double xde0 = numer0 / denom0, xde1 = numer1 / denom1;
        const double discr = 1 - xde0 * xde0 - xde1 * xde1;
        if (discr > 0) {
            x[0] = e[0] * xde0, x[1] = e[1] * xde1, x[2] = e[2] * std::sqrt(discr);
            return;
        }
    }
    x[2] = 0;
    findEllipsePoint(e[0], e[1], y[0], y[1], x[0], x[1]);
}

}  // namespace

EllipsoidSurfacePoint findEllipsoidSurfacePoint(const SimTK::Vec3& e, const SimTK::Vec3& p_S) {
    // Sort the axes by decreasing semi-axis (stable, so equal axes keep their order) and fold
    // the query into the positive octant; the answer is unfolded the same way.
    std::array<int, 3> order{0, 1, 2};
    for (int i = 1; i < 3; ++i) {  // insertion sort: stable, and no allocation in the hot path
        for (int j = i; j > 0 && e[order[j]] > e[order[j - 1]]; --j) std::swap(order[j], order[j - 1]);
    }
    double es[3], ys[3], xs[3];
    for (int k = 0; k < 3; ++k) {
        es[k] = e[order[k]];
        ys[k] = std::abs(p_S[order[k]]);
    }
    findSortedPoint(es, ys, xs);
    EllipsoidSurfacePoint result;
    double inside = 0;
    for (int k = 0; k < 3; ++k) {
        const int i = order[k];
        result.p_SP[i] = p_S[i] < 0 ? -xs[k] : xs[k];
        inside += (p_S[i] / e[i]) * (p_S[i] / e[i]);
    }
    const double distance = (p_S - result.p_SP).norm();
    result.distance = inside < 1 ? -distance : distance;
    return result;
}

SimTK::UnitVec3 calcEllipsoidNormal(const SimTK::Vec3& e, const SimTK::Vec3& p_SP) {
    return SimTK::UnitVec3(SimTK::Vec3(p_SP[0] / (e[0] * e[0]), p_SP[1] / (e[1] * e[1]),
                                       p_SP[2] / (e[2] * e[2])));
}

double calcEllipsoidCurvatureRadius(const SimTK::Vec3& e, const SimTK::Vec3& p_SP) {
    const SimTK::Vec3 g(p_SP[0] / (e[0] * e[0]), p_SP[1] / (e[1] * e[1]), p_SP[2] / (e[2] * e[2]));
    return e[0] * e[1] * e[2] * SimTK::dot(g, g);
}

SimTK::Vec3 findEllipsoidSupportPoint(const SimTK::Vec3& e, const SimTK::Vec3& u_S) {
    const SimTK::Vec3 eu(e[0] * u_S[0], e[1] * u_S[1], e[2] * u_S[2]);
    const double norm = eu.norm();
    return SimTK::Vec3(e[0] * eu[0], e[1] * eu[1], e[2] * eu[2]) / norm;
}

}  // namespace graspsim::contact
