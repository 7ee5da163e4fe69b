#include "graspsim/grasp/grasp_matrix.h"

#include "graspsim/grasp/friction_cone.h"

#include "graspsim/error.h"

#include <Eigen/Geometry>

#include <cmath>
#include <sstream>
#include <string>

namespace graspsim::grasp {

namespace {

// Unit-length and orthogonality checks allow 1e-6: contact normals and rotations coming from a
// simulation are unit to round-off, while a user's hand-typed "0.7071" must not pass silently.
const double kUnitTolerance = 1e-6;

std::string contactName(std::size_t i) { return "grasp contact " + std::to_string(i); }

void checkFinite(const Eigen::Vector3d& v, const std::string& owner, const std::string& field) {
    if (!v.allFinite()) throw InputError(owner + ": " + field + " has a non-finite component");
}

void checkUnit(const Eigen::Vector3d& v, const std::string& owner, const std::string& field) {
    checkFinite(v, owner, field);
    if (std::abs(v.norm() - 1) > kUnitTolerance) {
        std::ostringstream msg;
        msg << owner << ": " << field << " has length " << v.norm()
            << "; it must be a unit vector (to 1e-6)";
        throw InputError(msg.str());
    }
}

void checkFrame(const ObjectFrame& frame) {
    checkFinite(frame.p_GO, "object frame", "p_GO");
    if (!frame.R_GO.allFinite()) throw InputError("object frame: R_GO has a non-finite entry");
    const double orthogonality =
        (frame.R_GO.transpose() * frame.R_GO - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    const double det = frame.R_GO.determinant();
    if (orthogonality > kUnitTolerance || det < 0) {
        std::ostringstream msg;
        msg << "object frame: R_GO is not a proper rotation (|R^T R - I| = " << orthogonality
            << ", det = " << det << "; accepted: orthonormal to 1e-6 with det +1)";
        throw InputError(msg.str());
    }
}

void checkContact(const GraspContact& c, std::size_t i) {
    const std::string owner = contactName(i);
    checkFinite(c.p_GC, owner, "p_GC");
    checkUnit(c.n_G, owner, "normal n_G");
    if (!std::isfinite(c.normalForce) || c.normalForce < 0) {
        std::ostringstream msg;
        msg << owner << ": normalForce (" << c.normalForce << ") must be finite and >= 0 (N)";
        throw InputError(msg.str());
    }
    if (c.t_G.isZero(0)) return;  // the tangent is optional
    checkUnit(c.t_G, owner, "tangent t_G");
    if (std::abs(c.t_G.dot(c.n_G)) > kUnitTolerance) {
        std::ostringstream msg;
        msg << owner
            << ": tangent t_G is not perpendicular to n_G (t_G . n_G = " << c.t_G.dot(c.n_G)
            << "; accepted: |t_G . n_G| <= 1e-6)";
        throw InputError(msg.str());
    }
}

// The contact's friction basis in O for unit normal force. Working in O (rather than G) makes the
// automatic tangent a property of the object, so the whole of G is independent of the world frame.
// The 1e-6 slack accepted above is removed here (normalize, Gram-Schmidt) so that every basis
// force has normal component exactly 1.
Eigen::Matrix3Xd calcUnitBasisInO(const GraspContact& c, const Eigen::Matrix3d& R_OG,
                                  const QualityOptions& options) {
    const Eigen::Vector3d n_O = (R_OG * c.n_G).normalized();
    Eigen::Vector3d t_O = c.t_G.isZero(0) ? findTangent(n_O) : Eigen::Vector3d(R_OG * c.t_G);
    t_O = (t_O - t_O.dot(n_O) * n_O).normalized();
    return calcFrictionConeBasis(n_O, t_O, options.mu, options.cone, options.edges);
}

}  // namespace

Eigen::Matrix<double, 6, 3> calcContactWrenchMap(const Eigen::Vector3d& p_OC, double torqueScale) {
    Eigen::Matrix3d pHat;            // p_OC^ : pHat v = p_OC x v
    pHat << 0, -p_OC.z(), p_OC.y(),  //
        p_OC.z(), 0, -p_OC.x(),      //
        -p_OC.y(), p_OC.x(), 0;
    Eigen::Matrix<double, 6, 3> D;
    D << Eigen::Matrix3d::Identity(), pHat / torqueScale;
    return D;
}

Eigen::MatrixXd calcGraspMatrix(const std::vector<GraspContact>& contacts, const ObjectFrame& frame,
                                const QualityOptions& options) {
    validate(options);
    checkFrame(frame);
    for (std::size_t i = 0; i < contacts.size(); ++i) checkContact(contacts[i], i);

    const Eigen::Matrix3d R_OG = frame.R_GO.transpose();
    const int k = getNumConeEdges(options.cone, options.edges);
    Eigen::MatrixXd G(6, k * static_cast<Eigen::Index>(contacts.size()));
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        const GraspContact& c = contacts[i];
        const Eigen::Vector3d p_OC = R_OG * (c.p_GC - frame.p_GO);
        const Eigen::Matrix3Xd f_O = c.normalForce * calcUnitBasisInO(c, R_OG, options);
        G.middleCols(k * static_cast<Eigen::Index>(i), k) =
            calcContactWrenchMap(p_OC, options.torqueScale) * f_O;
    }
    return G;
}

}  // namespace graspsim::grasp
