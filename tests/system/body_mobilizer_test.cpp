#include "body_mobilizer.h"

#include <gtest/gtest.h>

#include <string>

#include "graspsim/error.h"
#include "pendulum_models.h"

namespace graspsim::system {
namespace {

TEST(BodyMobilizer, MassPropertiesShiftCentralInertiaToTheOrigin) {
    model::Body body = test::makeBody("link", 2.0, {0.1, -0.3, 0.2}, {0.05, 0.04, 0.03});
    body.inertia.xy = 0.002;
    body.inertia.xz = -0.001;
    body.inertia.yz = 0.003;

    const SimTK::MassProperties mp = calcMassPropertiesAboutOrigin(body);

    // Parallel-axis theorem by hand: I_O = I_C + m (|c|^2 1 - c c^T), c = p_BCm.
    const double c[3] = {0.1, -0.3, 0.2};
    const double Ic[3][3] = {{0.05, 0.002, -0.001}, {0.002, 0.04, 0.003}, {-0.001, 0.003, 0.03}};
    const double c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    const SimTK::Mat33 I_O = mp.getInertia().toMat33();
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            EXPECT_NEAR(I_O(i, j), Ic[i][j] + 2.0 * ((i == j ? c2 : 0) - c[i] * c[j]), 1e-15)
                << i << "," << j;
        }
    }
    EXPECT_EQ(mp.getMass(), 2.0);
    EXPECT_EQ(mp.getMassCenter(), SimTK::Vec3(0.1, -0.3, 0.2));
}

TEST(BodyMobilizer, AxisAlignedRotationPutsTheMobilizerAxisOnTheJointAxis) {
    const model::Vec3 axis{2.0 / 7, -3.0 / 7, 6.0 / 7};

    const SimTK::Rotation R_JF_pin = calcAxisAlignedRotation(axis, SimTK::ZAxis);
    const SimTK::Rotation R_JF_slider = calcAxisAlignedRotation(axis, SimTK::XAxis);

    const SimTK::Vec3 expected(axis[0], axis[1], axis[2]);
    EXPECT_LT((R_JF_pin.z() - expected).norm(), 1e-15);
    EXPECT_LT((R_JF_slider.x() - expected).norm(), 1e-15);
}

TEST(BodyMobilizer, TransformKeepsRotationAndTranslation) {
    model::Transform X_AB;
    X_AB.R = test::rotationAboutAxis({0, 0.6, 0.8}, 1.1);
    X_AB.p = {1, 2, 3};

    const SimTK::Transform X = toSimTKTransform(X_AB, "test");

    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) EXPECT_EQ(X.R().asMat33()(i, j), X_AB.R[3 * i + j]);
    }
    EXPECT_EQ(X.p(), SimTK::Vec3(1, 2, 3));
}

TEST(BodyMobilizer, TransformRejectsScaledAndReflectedMatrices) {
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

}  // namespace
}  // namespace graspsim::system
