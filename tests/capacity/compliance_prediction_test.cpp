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
    for (const grasp::CompliantContact& c : grasp.contacts) {
        sum += c.force_G;
        EXPECT_GT(c.normalStiffness, 0);
        EXPECT_NEAR(c.tangentialStiffness, 2.0 / 3.0 * c.normalStiffness, 1e-9 * c.normalStiffness);
        EXPECT_LT((c.fingerCompliance_G - c.fingerCompliance_G.transpose()).norm(), 1e-12);
        EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(c.fingerCompliance_G).eigenvalues().minCoeff(), -1e-12);
    }
    const Eigen::Vector3d weight = pinch.object.mass * Eigen::Vector3d(pinch.world.gravity[0], pinch.world.gravity[1], pinch.world.gravity[2]);
    EXPECT_LT((sum + weight).norm(), 0.02 * weight.norm());
}

}  // namespace
}  // namespace graspsim::capacity
