#include "graspsim/grasp/grasp_quality.h"

#include "graspsim/grasp/ferrari_canny.h"
#include "graspsim/grasp/grasp_matrix.h"

#include "graspsim/error.h"

#include <Eigen/SVD>

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
    // Jacobi SVD: accurate small singular values, which is what Q is about.
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
