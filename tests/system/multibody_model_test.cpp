#include "graspsim/system/multibody_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "graspsim/error.h"
#include "pendulum_models.h"

namespace graspsim::system {
namespace {

using test::makeBody;
using test::makeJoint;
using test::makePendulum;
using test::PendulumParameters;
using test::rotationAboutAxis;
using Type = model::Joint::Type;

// A measured value for the test report (RecordProperty would round a double to an integer).
std::string toText(double value) {
    std::ostringstream text;
    text << std::setprecision(3) << value;
    return text.str();
}

SimTK::Matrix calcMassMatrix(const MultibodyModel& model, const SimTK::State& state) {
    model.getSystem().realize(state, SimTK::Stage::Position);
    SimTK::Matrix M;
    model.getMatter().calcM(state, M);
    return M;
}

// Message of the graspsim exception `call` throws, or "" if it throws none.
template <class Exception, class Call>
std::string messageOf(Call&& call) {
    try {
        call();
    } catch (const Exception& e) {
        return e.what();
    }
    return "";
}

TEST(MultibodyModel, PendulumMassMatrixIsPivotInertia) {
    const PendulumParameters p;
    MultibodyModel model(makePendulum(p));
    SimTK::State state = model.realizeTopology();
    model.setJointPosition(state, "pivot", 0.7);

    const SimTK::Matrix M = calcMassMatrix(model, state);

    ASSERT_EQ(M.nrow(), 1);
    EXPECT_NEAR(M(0, 0), p.mass * p.length * p.length + p.centralIzz, 1e-12);
}

// Linear interpolation of the times where the sampled angle changes sign; near a zero
// crossing the angle is nearly linear in time, so the error is far below a sample interval.
std::vector<double> findZeroCrossings(const std::vector<double>& t, const std::vector<double>& q) {
    std::vector<double> crossings;
    for (std::size_t i = 1; i < q.size(); ++i) {
        if ((q[i - 1] < 0) != (q[i] < 0)) {
            crossings.push_back(t[i - 1] + (t[i] - t[i - 1]) * q[i - 1] / (q[i - 1] - q[i]));
        }
    }
    return crossings;
}

TEST(MultibodyModel, PendulumSmallAmplitudePeriodMatchesClosedForm) {
    const PendulumParameters p;
    const double g = 9.81;
    MultibodyModel model(makePendulum(p));
    SimTK::State state = model.realizeTopology();
    // At 0.01 rad amplitude the large-amplitude correction (1 + theta^2/16) is 6e-6.
    model.setJointPosition(state, "pivot", 0.01);
    const double expectedPeriod =
        2 * SimTK::Pi * std::sqrt(p.calcPivotInertia() / (p.mass * g * p.length));

    SimTK::RungeKuttaMersonIntegrator integrator(model.getSystem());
    integrator.setAccuracy(1e-8);
    integrator.initialize(state);
    std::vector<double> times, angles;
    const double dt = expectedPeriod / 200;
    for (int i = 0; i <= 700; ++i) {  // 3.5 periods
        integrator.stepTo(i * dt);
        times.push_back(integrator.getTime());
        angles.push_back(model.getJointPosition(integrator.getState(), "pivot"));
    }

    const std::vector<double> crossings = findZeroCrossings(times, angles);
    ASSERT_GE(crossings.size(), 7u);
    const double measuredPeriod = (crossings[6] - crossings[0]) / 3;
    RecordProperty("period_relative_error", toText(measuredPeriod / expectedPeriod - 1));
    EXPECT_NEAR(measuredPeriod, expectedPeriod, 0.005 * expectedPeriod);
    EXPECT_NEAR(measuredPeriod, expectedPeriod, 1e-4 * expectedPeriod) << "tighter than required";
}

SimTK::Rotation toRotation(const std::array<double, 9>& R) {
    return SimTK::Rotation(SimTK::Mat33(R[0], R[1], R[2], R[3], R[4], R[5], R[6], R[7], R[8]),
                           true);
}

// A joint whose axis is not z and whose frame is rotated and offset in a parent that is itself
// rotated in ground. Oracle: X_GB = X_GR * X_PJ * X_JB(q), each rotation by Rodrigues' formula.
TEST(MultibodyModel, OffAxisRevoluteJointPoseMatchesHandComputedRotation) {
    const model::Vec3 axisOfRoot{0, 0.6, 0.8}, axisOfFrame{std::sqrt(0.5), std::sqrt(0.5), 0};
    const model::Vec3 axis_J{1.0 / 3, 2.0 / 3, 2.0 / 3};
    model::ModelDescription m;
    m.name = "off_axis";
    m.X_GR.R = rotationAboutAxis(axisOfRoot, -0.4);
    m.X_GR.p = {0.5, 1.0, -0.2};
    m.bodies.push_back(makeBody("base", 1.0, {0, 0, 0}, {0.01, 0.01, 0.01}));
    m.bodies.push_back(makeBody("link", 0.3, {0.05, 0.01, 0}, {0.001, 0.002, 0.002}));
    model::Transform X_PJ;
    X_PJ.R = rotationAboutAxis(axisOfFrame, 0.7);
    X_PJ.p = {0.1, 0.2, 0.3};
    m.joints.push_back(makeJoint("hinge", Type::Revolute, "base", "link", axis_J, X_PJ));
    m.joints.back().lower = -2;
    m.joints.back().upper = 2;
    MultibodyModel model(m);
    SimTK::State state = model.realizeTopology();
    const double q = 0.9;
    model.setJointPosition(state, "hinge", q);
    model.getSystem().realize(state, SimTK::Stage::Position);

    const SimTK::Transform& X_GB = model.getMobilizedBody("link").getBodyTransform(state);

    const SimTK::Rotation R_GB =
        toRotation(m.X_GR.R) * toRotation(X_PJ.R) * toRotation(rotationAboutAxis(axis_J, q));
    const SimTK::Vec3 p_GB =
        SimTK::Vec3(0.5, 1.0, -0.2) + toRotation(m.X_GR.R) * SimTK::Vec3(0.1, 0.2, 0.3);
    EXPECT_LT((X_GB.R().asMat33() - R_GB.asMat33()).norm(), 1e-12);
    EXPECT_LT((X_GB.p() - p_GB).norm(), 1e-12);
}

TEST(MultibodyModel, OffAxisPrismaticJointTranslatesAlongItsAxis) {
    model::ModelDescription m;
    m.name = "slider";
    m.bodies.push_back(makeBody("base", 1.0, {0, 0, 0}, {0.01, 0.01, 0.01}));
    m.bodies.push_back(makeBody("carriage", 0.5, {0, 0, 0}, {0.001, 0.001, 0.001}));
    model::Transform X_PJ;
    X_PJ.R = rotationAboutAxis({1, 0, 0}, 0.5);
    X_PJ.p = {0, 0.1, 0};
    m.joints.push_back(makeJoint("rail", Type::Prismatic, "base", "carriage", {0, 0.6, 0.8}, X_PJ));
    m.joints.back().upper = 1;
    MultibodyModel model(m);
    SimTK::State state = model.realizeTopology();
    model.setJointPosition(state, "rail", 0.25);
    model.getSystem().realize(state, SimTK::Stage::Position);

    const SimTK::Transform& X_GB = model.getMobilizedBody("carriage").getBodyTransform(state);

    const SimTK::Rotation R_PJ = toRotation(X_PJ.R);
    EXPECT_LT((X_GB.R().asMat33() - R_PJ.asMat33()).norm(), 1e-12);
    EXPECT_LT((X_GB.p() - (SimTK::Vec3(0, 0.1, 0) + R_PJ * SimTK::Vec3(0, 0.15, 0.2))).norm(),
              1e-12);
}

// The mass matrix of a single pin is a^T I_O a, with I_O the inertia about the pivot by the
// parallel-axis theorem. Products of inertia and an off-centre mass centre exercise the
// conversion of the central inertia (URDF sign convention) to Simbody's origin inertia.
TEST(MultibodyModel, PinMassMatrixUsesParallelAxisInertiaWithProducts) {
    model::ModelDescription m;
    m.name = "products";
    m.bodies.push_back(makeBody("base", 1.0, {0, 0, 0}, {0.01, 0.01, 0.01}));
    model::Body link = makeBody("link", 1.5, {0.1, -0.2, 0.05}, {0.02, 0.03, 0.04});
    link.inertia.xy = 0.004;
    link.inertia.xz = -0.003;
    link.inertia.yz = 0.002;
    m.bodies.push_back(link);
    const model::Vec3 a{2.0 / 7, 3.0 / 7, 6.0 / 7};
    m.joints.push_back(makeJoint("hinge", Type::Continuous, "base", "link", a));
    MultibodyModel model(m);

    const SimTK::Matrix M = calcMassMatrix(model, model.realizeTopology());

    const double c[3] = {0.1, -0.2, 0.05};
    const double Ic[3][3] = {{0.02, 0.004, -0.003}, {0.004, 0.03, 0.002}, {-0.003, 0.002, 0.04}};
    const double c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    double expected = 0;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            const double I_O = Ic[i][j] + 1.5 * ((i == j ? c2 : 0) - c[i] * c[j]);
            expected += a[i] * I_O * a[j];
        }
    }
    EXPECT_NEAR(M(0, 0), expected, 1e-14);
}

// The same shoulder as one Gimbal (body-fixed x-y-z) whose F and M frames map its x, y, z onto
// the chain's z, x, y. Simbody documents a Gimbal as equal to 3 pins through massless bodies.
struct GimbalShoulder {
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter{system};
    SimTK::GeneralForceSubsystem forces{system};

    GimbalShoulder() {
        SimTK::Force::Gravity(forces, matter, SimTK::Vec3(0, -9.81, 0));
        const SimTK::Inertia I_Bcm(0.012, 0.003, 0.011);
        const SimTK::Vec3 p_BCm(0.02, -0.15, 0.01);
        const SimTK::MassProperties massProperties(2.0, p_BCm,
                                                   I_Bcm.shiftFromMassCenter(p_BCm, 2.0));
        SimTK::MobilizedBody::Weld thorax(matter.updGround(), SimTK::Transform(),
                                          SimTK::Body::Rigid(SimTK::MassProperties(
                                              20, SimTK::Vec3(0), SimTK::Inertia(0.5, 0.4, 0.3))),
                                          SimTK::Transform());
        const SimTK::Rotation R_JF(SimTK::Mat33(0, 1, 0, 0, 0, 1, 1, 0, 0),
                                   true);  // F x,y,z = J z,x,y
        SimTK::MobilizedBody::Gimbal(thorax, SimTK::Transform(R_JF, SimTK::Vec3(0, 0.4, 0.18)),
                                     SimTK::Body::Rigid(massProperties), SimTK::Transform(R_JF));
        system.realizeTopology();
    }
};

TEST(MultibodyModel, ShoulderChainThroughMasslessBodiesMatchesGimbal) {
    MultibodyModel model(test::makeShoulderChain());
    SimTK::State state = model.realizeTopology();
    const std::vector<double> q{0.3, -0.4, 0.5};
    ASSERT_EQ(model.getJointNames(),
              (std::vector<std::string>{"flexion", "abduction", "rotation"}));
    for (int i = 0; i < 3; ++i) model.setJointPosition(state, model.getJointNames()[i], q[i]);
    model.getSystem().realize(state, SimTK::Stage::Acceleration);
    GimbalShoulder gimbal;
    SimTK::State gimbalState = gimbal.system.getDefaultState();
    for (int i = 0; i < 3; ++i) gimbalState.updQ()[i] = q[i];
    gimbal.system.realize(gimbalState, SimTK::Stage::Acceleration);

    const SimTK::Matrix M = calcMassMatrix(model, state);
    SimTK::Matrix M_gimbal;
    gimbal.matter.calcM(gimbalState, M_gimbal);

    ASSERT_EQ(M.nrow(), 3);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            EXPECT_NEAR(M(i, j), M(j, i), 1e-14) << "symmetry at " << i << "," << j;
            EXPECT_NEAR(M(i, j), M_gimbal(i, j), 1e-12) << "gimbal at " << i << "," << j;
        }
        EXPECT_NEAR(state.getUDot()[i], gimbalState.getUDot()[i], 1e-9) << "udot " << i;
    }
    // Sylvester's criterion: a symmetric matrix with positive leading minors is positive definite.
    const double minor2 = M(0, 0) * M(1, 1) - M(0, 1) * M(1, 0);
    EXPECT_GT(M(0, 0), 0);
    EXPECT_GT(minor2, 0);
    EXPECT_GT(SimTK::det(SimTK::Mat33(M(0, 0), M(0, 1), M(0, 2), M(1, 0), M(1, 1), M(1, 2), M(2, 0),
                                      M(2, 1), M(2, 2))),
              0);
}

TEST(MultibodyModel, ShoulderChainMassMatrixIsSingularAtGimbalLock) {
    MultibodyModel model(test::makeShoulderChain());
    SimTK::State state = model.realizeTopology();
    model.setJointPosition(state, "abduction", SimTK::Pi / 2);  // first and last axes align

    const SimTK::Matrix M = calcMassMatrix(model, state);

    const double det = SimTK::det(SimTK::Mat33(M(0, 0), M(0, 1), M(0, 2), M(1, 0), M(1, 1), M(1, 2),
                                               M(2, 0), M(2, 1), M(2, 2)));
    EXPECT_NEAR(det, 0, 1e-12 * M(0, 0) * M(1, 1) * M(2, 2));
}

TEST(MultibodyModel, JointNamesFollowStateOrderAndIndexTheState) {
    model::ModelDescription m = test::makeShoulderChain();
    std::swap(m.joints[0], m.joints[2]);  // listed leaf first: bodies must still go in parent first
    m.bodies.push_back(makeBody("hand", 0.4, {0, -0.05, 0}, {0.001, 0.0005, 0.001}));
    m.joints.push_back(makeJoint("wrist_weld", Type::Fixed, "upper_arm", "hand", {0, 0, 1}));
    MultibodyModel model(m);
    SimTK::State state = model.realizeTopology();

    EXPECT_EQ(model.getDofCount(), 3);
    const std::vector<std::string> names = model.getJointNames();
    ASSERT_EQ(names, (std::vector<std::string>{"flexion", "abduction", "rotation"}));
    for (std::size_t i = 0; i < names.size(); ++i) {
        EXPECT_EQ(int(model.getJointQIndex(names[i])), int(i));
        EXPECT_EQ(int(model.getJointUIndex(names[i])), int(i));
        model.setJointPosition(state, names[i], 0.1 * (i + 1));
        model.setJointSpeed(state, names[i], -0.2 * (i + 1));
    }
    const std::string bodyOf[] = {"shoulder_1", "shoulder_2", "upper_arm"};
    for (std::size_t i = 0; i < names.size(); ++i) {
        EXPECT_DOUBLE_EQ(model.getMobilizedBody(bodyOf[i]).getOneQ(state, 0), 0.1 * (i + 1));
        EXPECT_DOUBLE_EQ(model.getJointSpeed(state, names[i]), -0.2 * (i + 1));
    }
}

TEST(MultibodyModel, EndEffectorLocationFollowsTheJoint) {
    const PendulumParameters p;
    MultibodyModel model(makePendulum(p));
    SimTK::State state = model.realizeTopology();
    model.setJointPosition(state, "pivot", 0.6);
    model.getSystem().realize(state, SimTK::Stage::Position);

    const SimTK::Vec3 p_GE = model.findEndEffectorLocationInGround(state, "tip");

    // Rotating (0, -l, 0) by q about z gives (l sin q, -l cos q, 0).
    EXPECT_LT((p_GE - SimTK::Vec3(p.length * std::sin(0.6), -p.length * std::cos(0.6), 0)).norm(),
              1e-14);
}

TEST(MultibodyModel, UnknownNamesThrowInputErrorNamingThem) {
    model::ModelDescription m = makePendulum();
    m.bodies.push_back(makeBody("cap", 0.1, {0, 0, 0}, {1e-4, 1e-4, 1e-4}));
    m.joints.push_back(makeJoint("cap_weld", Type::Fixed, "rod", "cap", {0, 0, 1}));
    MultibodyModel model(m);
    SimTK::State state = model.realizeTopology();
    model.getSystem().realize(state, SimTK::Stage::Position);

    EXPECT_NE(messageOf<InputError>([&] { model.getMobilizedBody("femur"); }).find("'femur'"),
              std::string::npos);
    EXPECT_NE(messageOf<InputError>([&] { model.getJointQIndex("knee"); }).find("'knee'"),
              std::string::npos);
    EXPECT_NE(messageOf<InputError>([&] { model.getJointUIndex("knee"); }).find("'knee'"),
              std::string::npos);
    EXPECT_NE(messageOf<InputError>([&] { model.setJointPosition(state, "hip", 1); }).find("'hip'"),
              std::string::npos);
    EXPECT_NE(messageOf<InputError>([&] {
                  model.findEndEffectorLocationInGround(state, "toe");
              }).find("'toe'"),
              std::string::npos);
    // A Fixed joint has no coordinate; its body is still found.
    EXPECT_NE(messageOf<InputError>([&] { model.getJointQIndex("cap_weld"); }).find("'cap_weld'"),
              std::string::npos);
    EXPECT_NO_THROW(model.getMobilizedBody("cap"));
}

TEST(MultibodyModel, SimbodyStageErrorsBecomeGraspsimErrors) {
    MultibodyModel model(makePendulum());
    const SimTK::State state = model.realizeTopology();  // realized to Topology only

    const std::string message = messageOf<Error>([&] { model.calcMechanicalEnergy(state); });

    EXPECT_NE(message.find("model 'pendulum'"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(MultibodyModel, JointMovingOnlyMasslessBodiesIsRejected) {
    model::ModelDescription m = makePendulum();
    m.bodies.push_back(test::makeVirtualBody("dangling"));
    m.joints.push_back(makeJoint("loose", Type::Continuous, "rod", "dangling", {1, 0, 0}));

    const std::string message = messageOf<InputError>([&] { MultibodyModel model(m); });

    EXPECT_NE(message.find("'loose'"), std::string::npos) << message;
}

TEST(MultibodyModel, MasslessBodyWeldedToAMassiveOneIsAccepted) {
    model::ModelDescription m = makePendulum();
    m.bodies.push_back(test::makeVirtualBody("tip_frame"));
    m.joints.push_back(makeJoint("tip_weld", Type::Fixed, "rod", "tip_frame", {0, 0, 1}));
    MultibodyModel model(m);
    SimTK::State state = model.realizeTopology();

    EXPECT_NO_THROW(model.getSystem().realize(state, SimTK::Stage::Acceleration));
}

TEST(MultibodyModel, NonRotationJointFrameIsRejectedNamingTheJoint) {
    model::ModelDescription m = makePendulum();
    m.joints[0].X_PJ.R = {1, 0, 0, 0, 1, 0, 0, 0, -1};  // a reflection

    const std::string message = messageOf<InputError>([&] { MultibodyModel model(m); });

    EXPECT_NE(message.find("'pivot'"), std::string::npos) << message;
}

TEST(MultibodyModel, InvalidDescriptionIsRejectedBeforeSimbodySeesIt) {
    model::ModelDescription m = makePendulum();
    m.joints[0].parent = "nowhere";

    const std::string message = messageOf<InputError>([&] { MultibodyModel model(m); });

    EXPECT_NE(message.find("'nowhere'"), std::string::npos) << message;
}

}  // namespace
}  // namespace graspsim::system
