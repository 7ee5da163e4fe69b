#include "graspsim/system/simtk_conversion.h"

#include <array>
#include <cmath>
#include <sstream>

#include "graspsim/error.h"

namespace graspsim::system {

namespace {

// Largest Frobenius norm of R R^T - I accepted as a rotation; rotations built from angles in
// double precision are orthonormal to about 1e-15.
constexpr double kRotationTolerance = 1e-9;

// Frobenius norm of R R^T - I for a row-major 3x3 R.
double calcOrthonormalityError(const std::array<double, 9>& R) {
    double sum = 0;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            const double dot =
                R[3 * i] * R[3 * j] + R[3 * i + 1] * R[3 * j + 1] + R[3 * i + 2] * R[3 * j + 2];
            sum += (dot - (i == j ? 1 : 0)) * (dot - (i == j ? 1 : 0));
        }
    }
    return std::sqrt(sum);
}

}  // namespace

SimTK::Vec3 toSimTKVec3(const model::Vec3& v) { return SimTK::Vec3(v[0], v[1], v[2]); }

SimTK::Transform toSimTKTransform(const model::Transform& X_AB, const std::string& what) {
    const auto& R = X_AB.R;
    // SimTK::Rotation's Mat33 constructor would silently re-orthogonalize a bad matrix, hiding
    // a builder's mistake; reject it instead and take a good one as given.
    const double error = calcOrthonormalityError(R);
    const double det = R[0] * (R[4] * R[8] - R[5] * R[7]) - R[1] * (R[3] * R[8] - R[5] * R[6]) +
                       R[2] * (R[3] * R[7] - R[4] * R[6]);
    if (!(error < kRotationTolerance) || det < 0) {
        std::ostringstream message;
        message << what << " rotation is not accepted: ||R R^T - I|| = " << error
                << ", det R = " << det << "; it must be a proper rotation";
        throw InputError(message.str());
    }
    const SimTK::Mat33 R_AB(R[0], R[1], R[2], R[3], R[4], R[5], R[6], R[7], R[8]);
    return SimTK::Transform(SimTK::Rotation(R_AB, true), toSimTKVec3(X_AB.p));
}

Eigen::Vector3d toEigenVector(const SimTK::Vec3& v) { return {v[0], v[1], v[2]}; }

Eigen::Matrix3d toEigenMatrix(const SimTK::Rotation& R_AB) {
    Eigen::Matrix3d R;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) R(i, j) = R_AB.asMat33()(i, j);
    return R;
}

}  // namespace graspsim::system
