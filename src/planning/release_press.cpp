#include "graspsim/planning/release_press.h"

#include <Eigen/Dense>

#include <algorithm>

namespace graspsim::planning {

namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

Vector6 findWrenchDirection(const FingerPress& f, const SimTK::Vec3& p_GCm) {
    const SimTK::Vec3 moment = (f.p_GC - p_GCm) % f.n_G;
    Vector6 w;
    w << moment[0], moment[1], moment[2], f.n_G[0], f.n_G[1], f.n_G[2];
    return w;
}

// A thousandth of the mean stiffness the normals give, rotation and translation apart, on every
// axis: the twist the normals leave free (a cylinder's axis) stays bounded without moving the rest.
Matrix6 makeHoldingStiffness(const Matrix6& A) {
    const double rotation = std::max(A.topLeftCorner<3, 3>().trace() / 3, 1e-12);
    const double translation = std::max(A.bottomRightCorner<3, 3>().trace() / 3, 1e-9);
    Matrix6 H = Matrix6::Zero();
    for (int k = 0; k < 3; ++k) {
        H(k, k) = 1e-3 * rotation;
        H(k + 3, k + 3) = 1e-3 * translation;
    }
    return H;
}

}  // namespace

std::vector<double> calcPressAfterRelease(const std::vector<FingerPress>& fingers, const SimTK::Vec3& p_GCm,
                                          double mass, const SimTK::Vec3& gravity) {
    std::vector<Vector6> w;
    Matrix6 all = Matrix6::Zero();
    for (const FingerPress& f : fingers) {
        w.push_back(findWrenchDirection(f, p_GCm));
        all += f.stiffness * w.back() * w.back().transpose();
    }
    const Matrix6 holding = makeHoldingStiffness(all);
    Vector6 weight = Vector6::Zero();
    for (int k = 0; k < 3; ++k) weight(k + 3) = mass * gravity[k];
    // Active set: a finger the twist pulls out of contact carries nothing; a few passes settle it
    // (each pass only drops fingers or brings back one that the new twist presses again).
    std::vector<bool> active(fingers.size(), true);
    Vector6 x = Vector6::Zero();
    for (int pass = 0; pass < 8; ++pass) {
        Matrix6 A = holding;
        Vector6 b = weight;
        for (std::size_t i = 0; i < fingers.size(); ++i) {
            if (!active[i]) continue;
            A += fingers[i].stiffness * w[i] * w[i].transpose();
            b += fingers[i].stiffness * fingers[i].depth * w[i];
        }
        x = A.ldlt().solve(b);
        bool changed = false;
        for (std::size_t i = 0; i < fingers.size(); ++i) {
            const bool pressing = fingers[i].depth - w[i].dot(x) > 0;
            changed = changed || pressing != active[i];
            active[i] = pressing;
        }
        if (!changed) break;
    }
    std::vector<double> press;
    for (std::size_t i = 0; i < fingers.size(); ++i) press.push_back(std::max(0.0, fingers[i].depth - w[i].dot(x)));
    return press;
}

}  // namespace graspsim::planning
