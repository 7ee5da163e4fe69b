#include "graspsim/grasp/grasp_quality.h"

#include "graspsim/grasp/ferrari_canny.h"
#include "graspsim/grasp/grasp_matrix.h"

#include "graspsim/error.h"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include <algorithm>
#include <limits>
#include <string>

namespace graspsim::grasp {

double calcMinSingularValue(const Eigen::MatrixXd& G) {
    if (G.rows() != 6)
        throw InputError("grasp quality: the grasp matrix must have 6 rows (got " +
                         std::to_string(G.rows()) + ")");
    if (!G.allFinite()) throw InputError("grasp quality: the grasp matrix has a non-finite entry");
    // A 6 x n matrix with n < 6 has only n singular values from the SVD, but as a map onto wrench
    // space its sixth singular value is 0: some wrench direction is not generated at all.
    if (G.cols() < 6) return 0;
    // Fast path (Q is computed at every check while engaged): the smallest eigenpair of the 6 x 6
    // Gram matrix G G^T, whose eigenvalues are the squared singular values, with sigma_6 taken as
    // |G^T v| for its eigenvector v. The eigenvector's error is bounded by the rounding in G G^T
    // over the gap to the next eigenvalue (Davis-Kahan) and enters |G^T v| squared, or by the gap
    // itself when the two smallest values nearly coincide. Where that bound is not far below
    // double precision, or sigma_6 < 1e-3 sigma_1 (forming G G^T squares the condition number),
    // the Jacobi SVD decides: it is accurate for small singular values.
    const Eigen::Matrix<double, 6, 6> gram = G * G.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eigen(gram);
    const auto& lambda = eigen.eigenvalues();  // ascending
    const double gap = lambda(1) - lambda(0);
    const double vectorError = (8.0 + static_cast<double>(G.cols())) * std::numeric_limits<double>::epsilon() * lambda(5) / gap;
    const double relativeError = std::min(vectorError * vectorError * lambda(5), gap) / (2 * lambda(0));
    if (eigen.info() == Eigen::Success && lambda(0) > 1e-6 * lambda(5) && gap > 0 && relativeError < 1e-14) {
        return (G.transpose() * eigen.eigenvectors().col(0)).norm();
    }
    return Eigen::JacobiSVD<Eigen::MatrixXd>(G).singularValues()(5);
}

double calcGraspQuality(const std::vector<GraspContact>& contacts, const ObjectFrame& frame,
                        const QualityOptions& options) {
    const Eigen::MatrixXd G = calcGraspMatrix(contacts, frame, options);
    switch (options.metric) {
        case QualityMetric::MinSingularValue: return calcMinSingularValue(G);
        case QualityMetric::FerrariCanny: return calcFerrariCanny(G);
    }
    throw Error("grasp quality: unknown metric");
}

}  // namespace graspsim::grasp
