#include "graspsim/grasp/wrench_distribution.h"

#include "graspsim/error.h"

#include <Eigen/Dense>

#include <cmath>
#include <string>

namespace graspsim::grasp {

namespace {

void checkInputs(const std::vector<GraspContact>& contacts, const ObjectFrame& frame,
                 const Eigen::Matrix<double, 6, 1>& wrench_G, const std::vector<Eigen::Vector3d>& reference, double mu) {
    if (reference.size() != contacts.size()) {
        throw InputError("wrench distribution: " + std::to_string(reference.size()) + " reference forces for " +
                         std::to_string(contacts.size()) + " contacts; give one per contact");
    }
    if (!std::isfinite(mu) || mu < 0) {
        throw InputError("wrench distribution: friction coefficient mu (" + std::to_string(mu) +
                         ") must be finite and >= 0");
    }
    if (!wrench_G.allFinite() || !frame.p_GO.allFinite()) throw InputError("wrench distribution: non-finite wrench or frame");
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        const GraspContact& c = contacts[i];
        if (!c.p_GC.allFinite() || !reference[i].allFinite() || std::abs(c.n_G.norm() - 1) > 1e-6) {
            throw InputError("wrench distribution: contact " + std::to_string(i) +
                             " has a non-finite point or reference force, or a normal that is not unit (to 1e-6)");
        }
    }
}

// Rows 0-2 the moment about O's origin, rows 3-5 the force (the wrench's order), all in G.
Eigen::MatrixXd calcWrenchMap(const std::vector<GraspContact>& contacts, const ObjectFrame& frame) {
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(6, 3 * static_cast<Eigen::Index>(contacts.size()));
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        const Eigen::Vector3d r = contacts[i].p_GC - frame.p_GO;
        Eigen::Matrix3d cross;
        cross << 0, -r.z(), r.y(), r.z(), 0, -r.x(), -r.y(), r.x(), 0;
        const Eigen::Index col = 3 * static_cast<Eigen::Index>(i);
        A.block<3, 3>(0, col) = cross;
        A.block<3, 3>(3, col) = Eigen::Matrix3d::Identity();
    }
    return A;
}

// A force inside the cone {f.n >= 0, |f_t| <= mu f.n}: the normal part clipped at 0 (a contact
// cannot pull), then the tangential part scaled down to the friction limit (its direction kept).
Eigen::Vector3d projectOntoCone(const Eigen::Vector3d& f, const Eigen::Vector3d& n, double mu) {
    const double normal = std::max(0.0, f.dot(n));
    Eigen::Vector3d tangential = f - f.dot(n) * n;
    const double limit = mu * normal;
    if (tangential.norm() > limit) tangential *= tangential.norm() > 0 ? limit / tangential.norm() : 0;
    return normal * n + tangential;
}

// Singular values of the wrench map below this fraction of the largest count as zero: the
// directions a grasp cannot push in (torsion about the line through two point contacts) are
// exactly zero up to rounding, ~1e-16 of the largest; a real grasp's smallest is above 1e-3.
constexpr double kRankTolerance = 1e-7;
// Pivots of the Gram matrix's pivoted Cholesky above this fraction of the largest: clearly full
// rank. The pivots do not bound the eigenvalues tightly: over 200 000 random wrench maps (2 to 7
// contacts, some nearly collinear) and random 6 x 6 Gram matrices, the smallest eigenvalue ratio
// was at least 2.5e-6 times the smallest pivot ratio, so above 1e-6 pivots mean eigenvalues above
// ~2.5e-12 of the largest, far from the rank tolerance's 1e-14, where both ways keep every
// direction and agree to rounding. Below it the eigenvalues decide.
constexpr double kFullRankPivot = 1e-6;

// A^+ r, the minimum-norm least-squares solution of A x = r, as A^T (A A^T)^+ r through the 6 x 6
// Gram matrix: by Cholesky when it is clearly full rank (every real grasp of 3+ contacts), else by
// its eigenvalues, the squared singular values of A, leaving out the directions under the rank
// tolerance as a rank-revealing decomposition of A does. A complete orthogonal decomposition of
// the 6 x 3N map did the same at several times the cost, at every 10-ms check of an engaged
// approximation.
Eigen::VectorXd solveMinimumNorm(const Eigen::MatrixXd& A, const Eigen::Matrix<double, 6, 1>& r) {
    const Eigen::Matrix<double, 6, 6> gram = A * A.transpose();
    const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> cholesky(gram);
    const Eigen::Matrix<double, 6, 1> pivots = cholesky.vectorD();
    if (cholesky.info() == Eigen::Success && pivots.minCoeff() > kFullRankPivot * pivots.maxCoeff()) {
        return A.transpose() * cholesky.solve(r);
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eigen(gram);
    const Eigen::Matrix<double, 6, 1>& lambda = eigen.eigenvalues();  // ascending
    const double cutoff = kRankTolerance * kRankTolerance * lambda[5];
    Eigen::Matrix<double, 6, 1> y = eigen.eigenvectors().transpose() * r;
    for (int k = 0; k < 6; ++k) y[k] = lambda[k] > cutoff ? y[k] / lambda[k] : 0.0;
    return A.transpose() * (eigen.eigenvectors() * y);
}

}  // namespace

WrenchDistribution distributeWrench(const std::vector<GraspContact>& contacts, const ObjectFrame& frame,
                                    const Eigen::Matrix<double, 6, 1>& wrench_G,
                                    const std::vector<Eigen::Vector3d>& referenceForces_G, double mu) {
    checkInputs(contacts, frame, wrench_G, referenceForces_G, mu);
    WrenchDistribution result;
    if (contacts.empty()) {
        result.residual = wrench_G.norm();
        return result;
    }
    const Eigen::MatrixXd A = calcWrenchMap(contacts, frame);
    Eigen::VectorXd f0(A.cols());
    for (std::size_t i = 0; i < contacts.size(); ++i) f0.segment<3>(3 * static_cast<Eigen::Index>(i)) = referenceForces_G[i];
    // Minimum-norm least-squares correction: the pseudo-inverse, rank-revealing so that a wrench
    // direction the contacts cannot produce is left out rather than blown up.
    const Eigen::VectorXd f = f0 + solveMinimumNorm(A, wrench_G - A * f0);
    Eigen::VectorXd projected(A.cols());
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        const Eigen::Index k = 3 * static_cast<Eigen::Index>(i);
        const Eigen::Vector3d fi = projectOntoCone(f.segment<3>(k), contacts[i].n_G, mu);
        projected.segment<3>(k) = fi;
        result.forces_G.push_back(fi);
        result.normalForces.push_back(fi.dot(contacts[i].n_G));
    }
    result.residual = (wrench_G - A * projected).norm();
    return result;
}

}  // namespace graspsim::grasp
