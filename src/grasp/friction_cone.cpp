#include "graspsim/grasp/friction_cone.h"

#include "graspsim/error.h"

#include <Eigen/Geometry>  // cross

#include <cmath>
#include <sstream>

namespace graspsim::grasp {

namespace {

const double kPi = 3.14159265358979323846;

}  // namespace

void validateFrictionCone(double mu, FrictionCone cone, int edges) {
    if (!std::isfinite(mu) || mu < 0) {
        std::ostringstream msg;
        msg << "grasp quality: friction coefficient mu (" << mu << ") must be finite and >= 0";
        throw InputError(msg.str());
    }
    if (cone == FrictionCone::Polyhedral && edges < 3) {
        std::ostringstream msg;
        msg << "grasp quality: a polyhedral friction cone needs edges >= 3 (got " << edges << ")";
        throw InputError(msg.str());
    }
}

Eigen::Vector3d findTangent(const Eigen::Vector3d& n) {
    // Crossing with the axis n is least aligned with keeps the product's length >= sqrt(2/3),
    // so normalizing it never amplifies round-off.
    Eigen::Index axis = 0;
    n.cwiseAbs().minCoeff(&axis);
    return n.cross(Eigen::Vector3d::Unit(axis)).normalized();
}

int getNumConeEdges(FrictionCone cone, int edges) { return cone == FrictionCone::Box ? 4 : edges; }

Eigen::Matrix3Xd calcFrictionConeBasis(const Eigen::Vector3d& n, const Eigen::Vector3d& t1,
                                       double mu, FrictionCone cone, int edges) {
    validateFrictionCone(mu, cone, edges);
    const Eigen::Vector3d t2 = n.cross(t1);
    const int k = getNumConeEdges(cone, edges);
    Eigen::Matrix3Xd basis(3, k);
    if (cone == FrictionCone::Box) {
        // The box's corners, walked around the square cross-section.
        const double s1[4] = {1, -1, -1, 1};
        const double s2[4] = {1, 1, -1, -1};
        for (int j = 0; j < 4; ++j) basis.col(j) = n + mu * (s1[j] * t1 + s2[j] * t2);
        return basis;
    }
    for (int j = 0; j < k; ++j) {
        const double th = 2 * kPi * j / k;
        basis.col(j) = n + mu * (std::cos(th) * t1 + std::sin(th) * t2);
    }
    return basis;
}

}  // namespace graspsim::grasp
