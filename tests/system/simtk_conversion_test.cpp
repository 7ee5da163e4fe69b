#include "graspsim/system/simtk_conversion.h"

#include <gtest/gtest.h>

#include <string>

#include "graspsim/error.h"
#include "pendulum_models.h"

namespace graspsim::system {
namespace {

TEST(SimTKConversion, VectorKeepsItsComponents) {
    EXPECT_EQ(toSimTKVec3({0.25, -1.5, 3e-7}), SimTK::Vec3(0.25, -1.5, 3e-7));
}

TEST(SimTKConversion, TransformKeepsRotationAndTranslation) {
    model::Transform X_AB;
    X_AB.R = test::rotationAboutAxis({0, 0.6, 0.8}, 1.1);
    X_AB.p = {1, 2, 3};

    const SimTK::Transform X = toSimTKTransform(X_AB, "test");

    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) EXPECT_EQ(X.R().asMat33()(i, j), X_AB.R[3 * i + j]);
    }
    EXPECT_EQ(X.p(), SimTK::Vec3(1, 2, 3));
}

TEST(SimTKConversion, TransformRejectsScaledAndReflectedMatrices) {
    model::Transform scaled, reflected;
    scaled.R = {1.01, 0, 0, 0, 1, 0, 0, 0, 1};
    reflected.R = {-1, 0, 0, 0, 1, 0, 0, 0, 1};

    for (const model::Transform& X : {scaled, reflected}) {
        try {
            toSimTKTransform(X, "joint 'bent' X_PJ");
            ADD_FAILURE() << "accepted a matrix that is not a rotation";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("joint 'bent' X_PJ"), std::string::npos)
                << e.what();
        }
    }
}

// To Eigen: the same entries, so a rotation still maps vectors as Simbody's does.
TEST(SimTKConversion, EigenCopiesKeepEveryEntry) {
    const SimTK::Rotation R_AB(1.1, SimTK::UnitVec3(0, 0.6, 0.8));
    const SimTK::Vec3 v_B(0.3, -2, 5);
    const Eigen::Matrix3d R = toEigenMatrix(R_AB);
    const Eigen::Vector3d v = toEigenVector(v_B);
    const SimTK::Vec3 v_A = R_AB * v_B;
    const Eigen::Vector3d mapped = R * v;
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(v[i], v_B[i]);
        EXPECT_NEAR(mapped[i], v_A[i], 1e-15);
        for (int j = 0; j < 3; ++j) EXPECT_EQ(R(i, j), R_AB.asMat33()(i, j));
    }
}

}  // namespace
}  // namespace graspsim::system
