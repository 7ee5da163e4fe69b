// The fingers' compliance at a point against central differences of the joint angles, and the IK
// null space's effect on it.
#include "graspsim/simulation/finger_compliance.h"

#include "graspsim/error.h"
#include "graspsim/model/model_description.h"
#include "graspsim/scenario/scenario_file.h"
#include "graspsim/simulation/grasp_experiment.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace graspsim::simulation {
namespace {

// Second method for the finger's compliance: each finger joint's column of the point's Jacobian
// by a central difference of the material point's position in the joint angle.
Eigen::Matrix3d calcComplianceByDifferences(const GraspScene& scene, const SimTK::State& state,
                                            const std::string& body, const SimTK::Vec3& p_G) {
    const SimTK::MobilizedBody& segment = scene.getModel().getMobilizedBody(body);
    scene.getSystem().realize(state, SimTK::Stage::Position);
    const SimTK::Vec3 p_B = segment.findStationAtGroundPoint(state, p_G);
    const std::vector<SimTK::MobilizedBodyIndex>& fingers = scene.getFingerMobilizers();
    Eigen::Matrix3d compliance = Eigen::Matrix3d::Zero();
    for (const system::JointImpedance& j : scene.findJointImpedances()) {
        if (std::find(fingers.begin(), fingers.end(), j.mobod) == fingers.end()) continue;
        const SimTK::MobilizedBody& joint = scene.getModel().getMatter().getMobilizedBody(j.mobod);
        const double h = 1e-6, q = joint.getOneQ(state, 0);
        SimTK::Vec3 p[2];
        for (int side = 0; side < 2; ++side) {
            SimTK::State moved = state;
            joint.setOneQ(moved, 0, q + (side ? h : -h));
            scene.getSystem().realize(moved, SimTK::Stage::Position);
            p[side] = segment.findStationLocationInGround(moved, p_B);
        }
        const SimTK::Vec3 d = (p[1] - p[0]) / (2 * h);
        const Eigen::Vector3d column(d[0], d[1], d[2]);
        compliance += column * column.transpose() / j.stiffness;
    }
    return compliance;
}

TEST(FingerCompliance, FingerComplianceAgainstFiniteDifferences) {
    const scenario::Scenario pinch = scenario::findBuiltinScenario("phone-pinch");
    GraspExperiment experiment(pinch, SimulationOptions{});
    const GraspScene& scene = experiment.getScene();
    const SimTK::State state = experiment.makeInitialState();
    const FingerCompliance fingers = makeFingerCompliance(scene);
    const Eigen::MatrixXd K = fingers.calcJointStiffness(state, false);
    ASSERT_TRUE(K.isDiagonal());
    for (const char* body : {"index_distal", "thumb_distal", "index_middle"}) {
        const SimTK::MobilizedBody& segment = scene.getModel().getMobilizedBody(body);
        const SimTK::Vec3 p_G = segment.findStationLocationInGround(state, SimTK::Vec3(0.003, 0.008, -0.002));
        const Eigen::Matrix3d model = fingers.calcCompliance(state, K, body, p_G);
        const Eigen::Matrix3d reference = calcComplianceByDifferences(scene, state, body, p_G);
        EXPECT_GT(model.norm(), 1e-5) << body;
        EXPECT_LT((model - reference).norm(), 1e-6 * reference.norm()) << body;
    }
    const SimTK::Vec3 p_palm = scene.getPalm().getBodyOriginLocation(state);
    EXPECT_EQ(fingers.calcCompliance(state, K, scene.getModel().getDescription().findPalm().name, p_palm).norm(), 0);
}

// With the IK following the finger along its null space, the PD stiffness is kp J_E^+ J_E. At the
// end-effector E itself the null space does not move the point, so its compliance is the plain
// J_E J_E^T / (kp + k_s) of equal joint stiffnesses; elsewhere on the finger it can only be larger.
TEST(FingerCompliance, IkNullSpaceLeavesTheEndEffectorsComplianceAndSoftensTheRest) {
    const scenario::Scenario pinch = scenario::findBuiltinScenario("phone-pinch");
    GraspExperiment experiment(pinch, SimulationOptions{});
    const GraspScene& scene = experiment.getScene();
    const SimTK::State state = experiment.makeInitialState();
    const FingerCompliance fingers = makeFingerCompliance(scene);
    const Eigen::MatrixXd Kplain = fingers.calcJointStiffness(state, false);
    const Eigen::MatrixXd Kik = fingers.calcJointStiffness(state, true);
    const model::EndEffector& tip = *scene.getModel().getDescription().findEndEffector("index_tip");
    const SimTK::MobilizedBody& distal = scene.getModel().getMobilizedBody(tip.body);
    const SimTK::Vec3 p_tip = distal.findStationLocationInGround(state, SimTK::Vec3(tip.p_BE[0], tip.p_BE[1], tip.p_BE[2]));
    const Eigen::Matrix3d atTipPlain = fingers.calcCompliance(state, Kplain, tip.body, p_tip);
    const Eigen::Matrix3d atTipIk = fingers.calcCompliance(state, Kik, tip.body, p_tip);
    EXPECT_LT((atTipIk - atTipPlain).norm(), 1e-6 * atTipPlain.norm());
    const SimTK::Vec3 p_middle = scene.getModel().getMobilizedBody("index_middle").findStationLocationInGround(state, SimTK::Vec3(0.004, 0.01, 0));
    const Eigen::Matrix3d extra = fingers.calcCompliance(state, Kik, "index_middle", p_middle) -
                                  fingers.calcCompliance(state, Kplain, "index_middle", p_middle);
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(extra).eigenvalues().maxCoeff(), 1e-4);  // m/N, soft
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(extra).eigenvalues().minCoeff(), -1e-12);
}

// The joints bent by calcJointDeflection for a force change df at a fingertip point move that
// material point by -C_f df (the finger gives way before the push it takes up), measured by
// setting the joint angles and reading the point's position: the Jacobian route and the moved
// model agree to first order (df small: 0.05 N).
TEST(FingerCompliance, JointDeflectionMovesThePointByMinusTheComplianceTimesTheForceChange) {
    const scenario::Scenario pinch = scenario::findBuiltinScenario("phone-pinch");
    GraspExperiment experiment(pinch, SimulationOptions{});
    const GraspScene& scene = experiment.getScene();
    const SimTK::State state = experiment.makeInitialState();
    const FingerCompliance fingers = makeFingerCompliance(scene);
    const Eigen::MatrixXd K = fingers.calcJointStiffness(state, true);
    const SimTK::MobilizedBody& segment = scene.getModel().getMobilizedBody("index_distal");
    const SimTK::Vec3 p_B(0.003, 0.008, -0.002);
    const SimTK::Vec3 p_G = segment.findStationLocationInGround(state, p_B);
    const Eigen::Vector3d df(0.03, -0.04, 0.02);
    const Eigen::VectorXd dq = fingers.calcJointDeflection(state, K, {"index_distal"}, {p_G}, {df});
    SimTK::State moved = state;
    const std::vector<SimTK::MobilizedBodyIndex>& joints = scene.getFingerMobilizers();
    for (std::size_t k = 0; k < joints.size(); ++k) {
        const SimTK::MobilizedBody& joint = scene.getModel().getMatter().getMobilizedBody(joints[k]);
        joint.setOneQ(moved, 0, joint.getOneQ(moved, 0) + dq[Eigen::Index(k)]);
    }
    scene.getSystem().realize(moved, SimTK::Stage::Position);
    const SimTK::Vec3 u = segment.findStationLocationInGround(moved, p_B) - p_G;
    const Eigen::Vector3d expected = -fingers.calcCompliance(state, K, "index_distal", p_G) * df;
    EXPECT_GT(expected.norm(), 1e-5);
    EXPECT_LT((Eigen::Vector3d(u[0], u[1], u[2]) - expected).norm(), 0.02 * expected.norm());
    EXPECT_THROW(fingers.calcJointDeflection(state, K, {"index_distal"}, {p_G, p_G}, {df}), InputError);
}

}  // namespace
}  // namespace graspsim::simulation
