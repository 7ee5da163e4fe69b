#include "graspsim/grasp/friction_limits.h"

#include "graspsim/error.h"

#include <Eigen/Geometry>

#include <cmath>

namespace graspsim::grasp {

namespace {

// |P v| with P = 1 - n n^T, the length of v's component in the tangent plane of unit normal n.
double calcTangentialLength(const Eigen::Vector3d& v, const Eigen::Vector3d& n) { return (v - v.dot(n) * n).norm(); }

}  // namespace

std::string toString(FrictionLimitModel model) {
    switch (model) {
        case FrictionLimitModel::Thesis: return "thesis";
        case FrictionLimitModel::ContactGeometry: return "contact";
        case FrictionLimitModel::Compliance: return "compliance";
    }
    return "thesis";
}

FrictionLimitModel parseFrictionLimitModel(const std::string& text, const std::string& what) {
    if (text == "thesis") return FrictionLimitModel::Thesis;
    if (text == "contact") return FrictionLimitModel::ContactGeometry;
    if (text == "compliance") return FrictionLimitModel::Compliance;
    throw InputError(what + ": value '" + text + "' is not accepted; use thesis (eq. 4.1-4.3, one box), contact "
                            "(per axis, from each contact's normal and position) or compliance (two-sided per axis, "
                            "from the grasp's compliance model)");
}

Eigen::Matrix<double, 6, 1> calcContactGeometryLimits(const std::vector<GraspContact>& contacts, double mu,
                                                      const Eigen::Matrix3d& R_GM, const Eigen::Vector3d& p_GM) {
    if (!(mu >= 0) || !std::isfinite(mu)) {
        throw InputError("friction limits: friction coefficient " + std::to_string(mu) + " is not accepted; must be finite and >= 0");
    }
    Eigen::Matrix<double, 6, 1> limits = Eigen::Matrix<double, 6, 1>::Zero();
    for (const GraspContact& c : contacts) {
        const Eigen::Vector3d n = c.n_G.normalized();
        const Eigen::Vector3d r = c.p_GC - p_GM;
        for (int k = 0; k < 3; ++k) {
            const Eigen::Vector3d axis = R_GM.col(k);
            limits[k] += mu * c.normalForce * calcTangentialLength(axis.cross(r), n);
            limits[3 + k] += mu * c.normalForce * calcTangentialLength(axis, n);
        }
    }
    return limits;
}

}  // namespace graspsim::grasp
