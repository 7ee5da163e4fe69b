#include "graspsim/capacity/compliance_prediction.h"

#include "graspsim/scenario/scenario_file.h"
#include "graspsim/simulation/grasp_experiment.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

namespace graspsim::capacity {
namespace {

// At the load's start the grasp is at rest: its contact forces carry the object's weight.
TEST(CompliancePrediction, LoadStartContactsCarryTheWeight) {
    const scenario::Scenario pinch = scenario::findBuiltinScenario("phone-pinch");
    const LoadStartGrasp grasp = findLoadStartGrasp(pinch, simulation::SimulationOptions{}, {});
    ASSERT_GE(grasp.contacts.size(), 2u);
    EXPECT_EQ(grasp.bodies.size(), grasp.contacts.size());
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double tangential = 0, normal = 0;
    for (const grasp::CompliantContact& c : grasp.contacts) {
        sum += c.force_G;
        EXPECT_GT(c.normalStiffness, 0);
        // Shared by normal force (grasp::setTangentialStiffnessByNormalForce): k_t / f_n alike.
        const double ratio = grasp.contacts[0].tangentialStiffness / grasp.contacts[0].force_G.dot(grasp.contacts[0].n_G);
        EXPECT_NEAR(c.tangentialStiffness / c.force_G.dot(c.n_G), ratio, 1e-9 * ratio);
        tangential += c.tangentialStiffness, normal += c.normalStiffness;
        EXPECT_LT((c.fingerCompliance_G - c.fingerCompliance_G.transpose()).norm(), 1e-12);
        EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(c.fingerCompliance_G).eigenvalues().minCoeff(), -1e-12);
    }
    EXPECT_NEAR(tangential, 2.0 / 3.0 * normal, 1e-9 * normal);  // Hertz-Mindlin's total
    const Eigen::Vector3d weight = pinch.object.mass * Eigen::Vector3d(pinch.world.gravity[0], pinch.world.gravity[1], pinch.world.gravity[2]);
    EXPECT_LT((sum + weight).norm(), 0.02 * weight.norm());
}

// With rolling, each contact gets its pad's curvature from the hand's shapes and the object's from
// what the contact's effective Hertz radius leaves: the ball's 1 / its radius at every contact (the
// scenario's size, a source of its own), the phone's faces 0.
TEST(CompliancePrediction, RollingContactsTakeThePadsAndTheObjectsCurvatures) {
    CompliancePredictionSettings settings;
    settings.rolling = true;
    const scenario::Scenario ball = scenario::findBuiltinScenario("ball-clutch");
    const LoadStartGrasp clutch = findLoadStartGrasp(ball, simulation::SimulationOptions{}, settings);
    ASSERT_GE(clutch.contacts.size(), 3u);
    for (const grasp::CompliantContact& c : clutch.contacts) {
        EXPECT_GT(c.fingerCurvature, 0);
        EXPECT_NEAR(c.objectCurvature, 1 / ball.object.radius, 1e-6 / ball.object.radius);
    }
    const LoadStartGrasp pinch = findLoadStartGrasp(scenario::findBuiltinScenario("phone-pinch"), simulation::SimulationOptions{}, settings);
    for (const grasp::CompliantContact& c : pinch.contacts) {
        EXPECT_GT(c.fingerCurvature, 0);
        EXPECT_EQ(c.objectCurvature, 0);
    }
    for (const grasp::CompliantContact& c : findLoadStartGrasp(ball, simulation::SimulationOptions{}, {}).contacts) {
        EXPECT_EQ(c.fingerCurvature + c.objectCurvature, 0);  // frozen geometry by default
    }
}

}  // namespace
}  // namespace graspsim::capacity
