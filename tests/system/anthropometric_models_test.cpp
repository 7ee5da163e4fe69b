// Built models in Simbody: the anthropometric arm's kinematics against an independent
// forward-kinematics composition of the description, energy bookkeeping of the passive arm under
// gravity, and the DOF count of the humanoid and of a foreign URDF.

#include "graspsim/model/body_model.h"
#include "graspsim/model/urdf_import.h"
#include "graspsim/system/multibody_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

using namespace graspsim;

namespace {

// Independent forward kinematics on the description: X_GB = X_GR * prod(X_PJ * rotation(axis, q)).
model::Transform findPose(const model::ModelDescription& m, const std::map<std::string, double>& q,
                          const std::string& body) {
    const model::Joint* joint = m.findParentJoint(body);
    if (!joint) return m.X_GR;
    const auto it = q.find(joint->name);
    const double angle = it == q.end() ? 0.0 : it->second;
    return findPose(m, q, joint->parent) * joint->X_PJ * model::Transform::axisAngle(joint->axis, angle);
}

}  // namespace

TEST(PassiveArm, SimbodyFingertipsMatchIndependentKinematics) {
    const model::ModelDescription arm = model::buildBodyModel(model::BuildOptions{});
    system::MultibodyModel multibody(arm);
    SimTK::State state = multibody.realizeTopology();
    std::mt19937 rng(7);
    std::map<std::string, double> q;
    for (const model::Joint& j : arm.joints) {
        std::uniform_real_distribution<double> within(j.lower, j.upper);
        q[j.name] = within(rng);
        multibody.setJointPosition(state, j.name, q[j.name]);
    }
    multibody.getSystem().realize(state, SimTK::Stage::Position);
    for (const model::EndEffector& e : arm.endEffectors) {
        const model::Vec3 expected = findPose(arm, q, e.body).shiftFrameStationToBase(e.p_BE);
        const SimTK::Vec3 actual = multibody.findEndEffectorLocationInGround(state, e.name);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(actual[k], expected[k], 1e-12) << e.name;
    }
}

// Oracle: a conservation law. With only gravity, springs, dampers and stops, the mechanical
// energy can only fall, and what it loses equals the integral of the dissipated power.
TEST(PassiveArm, ReleasedUnderGravityLosesEnergyOnlyThroughDamping) {
    model::BuildOptions options;
    options.armDamping = 0.5;
    const model::ModelDescription arm = model::buildBodyModel(options);
    system::MultibodyModel multibody(arm);
    SimTK::State state = multibody.realizeTopology();
    multibody.setJointPosition(state, "shoulder_flexion", 1.0);
    multibody.setJointPosition(state, "elbow_flexion", 0.8);
    multibody.setJointPosition(state, "wrist_flexion", 0.4);
    multibody.setJointPosition(state, "index_mcp_flexion", 0.6);

    // The finger joints are stiff (a 4 g distal phalanx on 0.05 N m s/rad damping has a time
    // constant near 10 us), so an implicit BDF integrator (Simbody's CPodes) keeps this fast.
    SimTK::CPodesIntegrator integrator(multibody.getSystem(), SimTK::CPodes::BDF, SimTK::CPodes::Newton);
    integrator.setAccuracy(1e-7);
    integrator.initialize(state);
    const SimTK::System& system = multibody.getSystem();
    auto energyAt = [&](const SimTK::State& s) {
        system.realize(s, SimTK::Stage::Dynamics);
        return multibody.calcMechanicalEnergy(s);
    };
    const double E0 = energyAt(integrator.getState());
    double previousE = E0, previousP = multibody.calcPassiveDissipationPower(integrator.getState());
    double dissipated = 0;
    const double dt = 5e-4;
    for (int k = 1; k <= 2000; ++k) {
        integrator.stepTo(k * dt);
        const SimTK::State& s = integrator.getState();
        const double E = energyAt(s);
        const double P = multibody.calcPassiveDissipationPower(s);
        dissipated += 0.5 * (P + previousP) * dt;
        ASSERT_LE(E, previousE + 1e-7) << "energy rose at t = " << s.getTime();
        previousE = E;
        previousP = P;
    }
    const double lost = E0 - previousE;
    EXPECT_GT(lost, 0.5);  // the arm really swung and damped (joules)
    EXPECT_NEAR(lost / dissipated, 1.0, 0.01);
}

TEST(AnthropometricModels, HumanoidBuildsInSimbodyWithEveryDof) {
    model::BuildOptions options;
    options.body = model::BodyKind::Humanoid;
    system::MultibodyModel humanoid(model::buildBodyModel(options));
    SimTK::State state = humanoid.realizeTopology();
    EXPECT_EQ(humanoid.getMatter().getNumMobilities(), 75);
    humanoid.getSystem().realize(state, SimTK::Stage::Acceleration);
    EXPECT_TRUE(state.getUDot().norm() < 1e6);  // finite accelerations: no singular joint chain
}

// Oracle: the DOF count of tests/data/foreign_gripper.urdf counted by hand (see that file):
// 4 revolute + 1 continuous + 1 prismatic joints; fixed joints add none.
TEST(AnthropometricModels, ForeignUrdfBuildsInSimbodyWithTheRightDofCount) {
    const model::ModelDescription gripper =
        model::importUrdf(std::string(GRASPSIM_TEST_DATA_DIR) + "/foreign_gripper.urdf");
    system::MultibodyModel multibody(gripper);
    SimTK::State state = multibody.realizeTopology();
    EXPECT_EQ(multibody.getMatter().getNumMobilities(), 6);
    multibody.getSystem().realize(state, SimTK::Stage::Acceleration);
    EXPECT_TRUE(std::isfinite(state.getUDot().norm()));
}
