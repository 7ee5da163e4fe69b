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

// Simbody itself, as the oracle: a bare system with the body on a free joint, realized.
void realizeInSimbody(const model::Body& body) {
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter(system);
    SimTK::MobilizedBody::Free(matter.updGround(), SimTK::Body::Rigid(calcMassPropertiesAboutOrigin(body)));
    system.realizeTopology();
}

// Simbody's rules are part of ModelDescription::validate (so that a URDF breaking them is refused
// naming its file): a one-link model, validated as MultibodyModel does.
std::string rejectionOf(const model::Body& body) {
    model::ModelDescription m;
    m.name = "m";
    m.bodies.push_back(body);
    try {
        m.validate("model 'm'");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(BodyMobilizer, MassCentreThatSwampsTheInertiaIsRefusedAndSimbodyWouldStopOnIt) {
    // What the URDF fuzzer found: a 0.2 kg ball's numbers with mass 2e11 kg and its mass centre
    // 5 m from the origin; the shift (5e12 kg m^2) cancels the 1.6e-4 kg m^2 inertia away.
    const model::Body ball = test::makeBody("ball", 2e11, {0, 0, 5}, {1.62e-4, 1.62e-4, 1.62e-4});

    const std::string message = rejectionOf(ball);

    EXPECT_NE(message.find("model 'm': link 'ball' centre of mass = (0, 0, 5) m is not accepted; with mass 2e+11 kg, "
                           "m |p|^2 = 5e+12 kg m^2 swamps"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("accepted: m |p|^2 below"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_THROW(realizeInSimbody(ball), SimTK::Exception::Base);
}

TEST(BodyMobilizer, MassCentreJustInsideTheLimitIsAcceptedBySimbody) {
    // 1 kg, central inertia 1e-4 kg m^2 each: the limit is sqrt(eps)/2 / (8 eps) ~ 4.2e6 kg m^2,
    // so a mass centre 1900 m out (3.6e6 kg m^2) passes, and Simbody must agree.
    const model::Body far = test::makeBody("far", 1.0, {0, 1900, 0}, {1e-4, 1e-4, 1e-4});
    const model::Body tooFar = test::makeBody("far", 1.0, {0, 2100, 0}, {1e-4, 1e-4, 1e-4});

    EXPECT_EQ(rejectionOf(far), "");
    EXPECT_NO_THROW(realizeInSimbody(far));
    EXPECT_NE(rejectionOf(tooFar), "");
}

TEST(BodyMobilizer, HeavyPlateWithinTheDescriptionSlackButOutsideSimbodysIsRefused) {
    // Trace 200 kg m^2: the description allows 1e-6 of the trace (2e-4) in the triangle
    // inequality, Simbody only sqrt(eps) of it (3e-6); this plate breaks it by 1e-5.
    model::Body plate = test::makeBody("plate", 100.0, {0, 0, 0}, {50, 50, 100.00001});
    plate.inertia.zz = plate.inertia.xx + plate.inertia.yy + 1e-5;

    const std::string message = rejectionOf(plate);

    EXPECT_NE(message.find("model 'm': link 'plate' inertia = [50 50 100.00001 0 0 0] kg m^2 is not accepted; "),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("here izz exceeds ixx + iyy by 1e-05 kg m^2"), std::string::npos) << message;
    EXPECT_THROW(realizeInSimbody(plate), SimTK::Exception::Base);
}

TEST(BodyMobilizer, ProductOfInertiaWithinTheDescriptionSlackButOutsideSimbodysIsRefused) {
    // The plate above (principal moments 50, 50, 100.00001) turned 45 degrees about x: the triangle
    // inequality holds on the diagonal, but |2 iyz| = 50.00001 exceeds ixx = 50 by 1e-5.
    model::Body plate = test::makeBody("plate", 100.0, {0, 0, 0}, {50, 75.000005, 75.000005});
    plate.inertia.yz = -25.000005;

    const std::string message = rejectionOf(plate);

    EXPECT_NE(message.find("model 'm': link 'plate' inertia = [50 75.000005 75.000005 0 0 -25.000005] kg m^2"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("here |2 iyz| exceeds ixx by 1e-05 kg m^2"), std::string::npos) << message;
    EXPECT_THROW(realizeInSimbody(plate), SimTK::Exception::Base);
}

TEST(BodyMobilizer, MasslessBodiesPassTheMassPropertiesCheck) {
    model::Body hinge = test::makeBody("hinge", 0.0, {0, 0, 0}, {0, 0, 0});
    EXPECT_EQ(rejectionOf(hinge), "");
}

}  // namespace
}  // namespace graspsim::system
