#include "graspsim/grasp/rolling_stiffness.h"

#include "graspsim/error.h"

#include <cmath>
#include <string>

namespace graspsim::grasp {

namespace {

using Matrix36 = Eigen::Matrix<double, 3, 6>;

Eigen::Matrix3d cross(const Eigen::Vector3d& v) {
    Eigen::Matrix3d m;
    m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
    return m;
}

void checkCurvatures(const CompliantContact& c) {
    const auto valid = [](double k) { return std::isfinite(k) && k >= 0; };
    if (!valid(c.fingerCurvature) || !valid(c.objectCurvature)) {
        throw InputError("rolling stiffness: curvatures (" + std::to_string(c.fingerCurvature) +
                         ", " + std::to_string(c.objectCurvature) + " 1/m) must be finite and >= 0");
    }
}

}  // namespace

Eigen::Matrix<double, 6, 6> calcRollingStiffness(const CompliantContact& c, const Eigen::Vector3d& f, const Eigen::Vector3d& p_GO) {
    checkCurvatures(c);
    const double kf = c.fingerCurvature, ko = c.objectCurvature, sum = kf + ko;
    if (!(sum > 0)) return Eigen::Matrix<double, 6, 6>::Zero();
    const Eigen::Vector3d r = c.p_GC - p_GO, n = c.n_G;
    Matrix36 u, turn, shift;  // u, theta x n and dp as functions of delta
    u << Eigen::Matrix3d::Identity(), -cross(r);
    turn << Eigen::Matrix3d::Zero(), -cross(n);
    shift << Eigen::Matrix3d::Identity(), Eigen::Matrix3d::Zero();
    const Eigen::Matrix3d across = Eigen::Matrix3d::Identity() - n * n.transpose();
    const Matrix36 dn = kf * ko / sum * across * u + kf / sum * turn;
    const Matrix36 df = -cross(f) * cross(n) * dn;
    const Matrix36 dC = ko / sum * u + 1 / sum * turn;
    Eigen::Matrix<double, 6, 6> term;
    term << df, -cross(f) * (dC - shift) + cross(r) * df;
    return term;
}

Eigen::Matrix<double, 6, 6> calcRollingStiffness(const std::vector<CompliantContact>& contacts, const Eigen::Vector3d& p_GO) {
    Eigen::Matrix<double, 6, 6> g = Eigen::Matrix<double, 6, 6>::Zero();
    for (const CompliantContact& c : contacts) g += calcRollingStiffness(c, c.force_G, p_GO);
    return g;
}

}  // namespace graspsim::grasp
