// The viewer's forward kinematics against Simbody's (a second, independent method): every body of
// the arm model at random joint angles, 1e-12 m and 1e-12 in the rotation matrix.

#include "graspsim/model/body_model.h"
#include "graspsim/system/multibody_model.h"
#include "graspsim/viewer/body_poses.h"

#include <gtest/gtest.h>

#include <random>

namespace graspsim::viewer {
namespace {

TEST(BodyPoses, AgreeWithSimbodyAtRandomJointAngles) {
    const model::ModelDescription description = model::buildBodyModel({});
    system::MultibodyModel simbody(description);
    SimTK::State state = simbody.realizeTopology();
    std::mt19937 random(19);
    for (int trial = 0; trial < 5; ++trial) {
        std::map<std::string, double> q;
        for (const model::Joint& joint : description.joints) {
            if (joint.getDofCount() == 0) continue;
            q[joint.name] = std::uniform_real_distribution<double>(joint.lower, joint.upper)(random);
            simbody.setJointPosition(state, joint.name, q[joint.name]);
        }
        simbody.getSystem().realize(state, SimTK::Stage::Position);
        const std::vector<model::Transform> X_GB = calcBodyPoses(description, q);
        ASSERT_EQ(X_GB.size(), description.bodies.size());
        for (std::size_t b = 0; b < X_GB.size(); ++b) {
            const SimTK::Transform& expected = simbody.getMobilizedBody(description.bodies[b].name).getBodyTransform(state);
            for (int i = 0; i < 3; ++i) {
                EXPECT_NEAR(X_GB[b].p[i], expected.p()[i], 1e-12) << description.bodies[b].name;
                for (int j = 0; j < 3; ++j) EXPECT_NEAR(X_GB[b].R[3 * i + j], expected.R()[i][j], 1e-12) << description.bodies[b].name;
            }
        }
    }
}

TEST(BodyPoses, JointsInAnyOrderAndMissingAnglesAtZero) {
    model::ModelDescription description = model::buildBodyModel({});
    const std::vector<model::Transform> inOrder = calcBodyPoses(description, {{"elbow_flexion", 0.5}});
    std::reverse(description.joints.begin(), description.joints.end());
    const std::vector<model::Transform> reversed = calcBodyPoses(description, {{"elbow_flexion", 0.5}});
    for (std::size_t b = 0; b < inOrder.size(); ++b) {
        for (int i = 0; i < 3; ++i) EXPECT_EQ(inOrder[b].p[i], reversed[b].p[i]);
    }
}

}  // namespace
}  // namespace graspsim::viewer
