#include "graspsim/control/fingertip_ik.h"

#include "graspsim/model/body_model.h"

#include "graspsim/error.h"

#include <gtest/gtest.h>

#include <random>

using namespace graspsim;

namespace {

const std::vector<std::string> kTips = {"thumb_tip", "index_tip", "middle_tip", "ring_tip", "little_tip"};

std::vector<std::string> fingerJoints(const model::ModelDescription& arm) {
    std::vector<std::string> joints;
    for (const model::Joint& j : arm.joints) {
        const bool hand = arm.findBody(j.child)->segment == "hand";
        if (hand && j.name.find("wrist") == std::string::npos) joints.push_back(j.name);
    }
    return joints;
}

// Solves the IK from `start` for goals at the fingertips of `known` (reachable, so the IK must
// put every fingertip on its goal, though not necessarily with the same angles: the hand is
// redundant) and returns `start` with the solution applied, realized to Stage::Position.
SimTK::State solveForTipsOf(const system::MultibodyModel& model, control::FingertipIk& ik, const std::vector<std::string>& joints,
                            const SimTK::State& known, const SimTK::State& start) {
    model.getSystem().realize(known, SimTK::Stage::Position);
    std::vector<SimTK::Vec3> goals;
    for (const std::string& tip : kTips) goals.push_back(model.findEndEffectorLocationInGround(known, tip));
    const SimTK::Vector q = ik.solve(start, goals);
    SimTK::State solved = start;
    for (std::size_t k = 0; k < joints.size(); ++k) model.setJointPosition(solved, joints[k], q[static_cast<int>(k)]);
    model.getSystem().realize(solved, SimTK::Stage::Position);
    for (std::size_t k = 0; k < kTips.size(); ++k) {
        EXPECT_LT((model.findEndEffectorLocationInGround(solved, kTips[k]) - goals[k]).norm(), 1e-4) << kTips[k];
    }
    return solved;
}

}  // namespace

// Oracle: goals produced by a known pose are reachable, so IK must find a pose that puts every
// fingertip on its goal (not necessarily the same angles: the hand is redundant).
TEST(FingertipIk, ReachesGoalsMadeByAKnownPose) {
    const model::ModelDescription arm = model::buildBodyModel(model::BuildOptions{});
    system::MultibodyModel model(arm);
    SimTK::State s = model.realizeTopology();
    model.setJointPosition(s, "elbow_flexion", 1.4);
    model.setJointPosition(s, "shoulder_flexion", 0.6);
    std::mt19937 rng(3);
    const std::vector<std::string> joints = fingerJoints(arm);
    ASSERT_EQ(joints.size(), 20u);
    SimTK::State known = s;
    for (const std::string& j : joints) {
        const model::Joint& joint = *arm.findJoint(j);
        std::uniform_real_distribution<double> mid(joint.lower + 0.25 * (joint.upper - joint.lower),
                                                   joint.lower + 0.75 * (joint.upper - joint.lower));
        model.setJointPosition(known, j, mid(rng));
    }
    control::FingertipIk ik(model, kTips, joints);
    const SimTK::State solved = solveForTipsOf(model, ik, joints, known, s);
    EXPECT_LT(ik.getLastError(), 1e-4);
    // The arm was locked: its joints did not move.
    EXPECT_DOUBLE_EQ(model.getJointPosition(solved, "elbow_flexion"), 1.4);
}

// Under LeakSanitizer (.ci/sanitize) this also checks that a rejected name leaks nothing: the
// marker goal was once allocated before the names were checked.
TEST(FingertipIk, UnknownNamesAreRejected) {
    system::MultibodyModel model(model::buildBodyModel(model::BuildOptions{}));
    EXPECT_THROW(control::FingertipIk(model, {"toe_tip"}, {"index_pip_flexion"}), InputError);
    EXPECT_THROW(control::FingertipIk(model, {"index_tip"}, {"knee_flexion"}), InputError);
}

// A constraint among bodies no IK joint moves (here a free box welded to Ground, as the grasp scene
// holds an object hanging from the palm before its release) is not the IK's to satisfy: violated
// by 10 um, more than the Assembler's tolerance, it must neither fail the IK nor move the box.
// Oracle: goals made by a known finger pose are reached.
TEST(FingertipIk, IgnoresConstraintsItCannotMove) {
    const model::ModelDescription arm = model::buildBodyModel(model::BuildOptions{});
    system::MultibodyModel model(arm);
    SimTK::MobilizedBody::Free box(model.updMatter().updGround(),
                                   SimTK::Body::Rigid(SimTK::MassProperties(0.1, SimTK::Vec3(0), SimTK::UnitInertia(1e-3))));
    SimTK::Constraint::Weld hold(model.updMatter().updGround(), SimTK::Transform(SimTK::Vec3(0.3, 0, 0)), box,
                                 SimTK::Transform());
    SimTK::State s = model.realizeTopology();
    box.setQToFitTranslation(s, SimTK::Vec3(0.3 + 1e-5, 0, 0));
    const std::vector<std::string> joints = fingerJoints(arm);
    SimTK::State known = s;
    for (const std::string& j : joints) {
        const model::Joint& joint = *arm.findJoint(j);
        model.setJointPosition(known, j, joint.lower + 0.4 * (joint.upper - joint.lower));
    }
    control::FingertipIk ik(model, kTips, joints);
    const SimTK::State solved = solveForTipsOf(model, ik, joints, known, s);
    EXPECT_DOUBLE_EQ(box.getBodyOriginLocation(solved)[0], 0.3 + 1e-5);
}

// Oracle: the per-goal distances are those of the returned pose, measured by forward kinematics.
// The index goal is moved 20 cm off, out of reach: its distance is large, the others stay met.
TEST(FingertipIk, LastDistancesAreThoseOfTheSolution) {
    const model::ModelDescription arm = model::buildBodyModel(model::BuildOptions{});
    system::MultibodyModel model(arm);
    SimTK::State s = model.realizeTopology();
    model.setJointPosition(s, "elbow_flexion", 1.4);
    model.getSystem().realize(s, SimTK::Stage::Position);
    const std::vector<std::string> joints = fingerJoints(arm);
    std::vector<SimTK::Vec3> goals;
    for (const std::string& tip : kTips) goals.push_back(model.findEndEffectorLocationInGround(s, tip));
    goals[1] += SimTK::Vec3(0, 0.2, 0);
    control::FingertipIk ik(model, kTips, joints);
    const SimTK::Vector q = ik.solve(s, goals);
    SimTK::State solved = s;
    for (std::size_t k = 0; k < joints.size(); ++k) model.setJointPosition(solved, joints[k], q[static_cast<int>(k)]);
    model.getSystem().realize(solved, SimTK::Stage::Position);
    ASSERT_EQ(ik.getLastDistances().size(), kTips.size());
    for (std::size_t k = 0; k < kTips.size(); ++k) {
        const double d = (model.findEndEffectorLocationInGround(solved, kTips[k]) - goals[k]).norm();
        EXPECT_NEAR(ik.getLastDistances()[k], d, 1e-9) << kTips[k];
    }
    EXPECT_GT(ik.getLastDistances()[1], 0.05);
}

namespace {

struct IkAnswer {
    std::vector<SimTK::Vec3> tips;
    double error = 0;
};

IkAnswer solveAndPlace(const system::MultibodyModel& model, control::FingertipIk& ik, const std::vector<std::string>& joints,
                       const SimTK::State& start, const std::vector<SimTK::Vec3>& goals) {
    const SimTK::Vector q = ik.solve(start, goals);
    SimTK::State solved = start;
    for (std::size_t k = 0; k < joints.size(); ++k) {
        const model::Joint& joint = *model.getDescription().findJoint(joints[k]);
        EXPECT_GE(q[static_cast<int>(k)], joint.lower - 1e-12) << joints[k];
        EXPECT_LE(q[static_cast<int>(k)], joint.upper + 1e-12) << joints[k];
        model.setJointPosition(solved, joints[k], q[static_cast<int>(k)]);
    }
    model.getSystem().realize(solved, SimTK::Stage::Position);
    IkAnswer answer{{}, ik.getLastError()};
    for (const std::string& tip : kTips) answer.tips.push_back(model.findEndEffectorLocationInGround(solved, tip));
    return answer;
}

// A random finger pose inside the middle of each joint's range, from an arm pose in front of the body.
SimTK::State makeRandomPose(const system::MultibodyModel& model, SimTK::State s, const std::vector<std::string>& joints,
                            std::mt19937& rng, double spread) {
    model.setJointPosition(s, "elbow_flexion", 1.4);
    model.setJointPosition(s, "shoulder_flexion", 0.6);
    for (const std::string& j : joints) {
        const model::Joint& joint = *model.getDescription().findJoint(j);
        const double mid = 0.5 * (joint.lower + joint.upper), half = 0.5 * spread * (joint.upper - joint.lower);
        model.setJointPosition(s, j, std::uniform_real_distribution<double>(mid - half, mid + half)(rng));
    }
    model.getSystem().realize(s, SimTK::Stage::Position);
    return s;
}

}  // namespace

// Second independent method as oracle: on random reachable goals (made by a random pose, solved
// from another random pose) damped least squares puts every fingertip within 1 um of its goal,
// inside each joint's range, and fits at least as well as Simbody's Assembler (which stops at its
// accuracy 1e-6, up to about half a millimetre from the goal here).
TEST(FingertipIk, AgreesWithTheAssemblerOnReachableGoals) {
    const model::ModelDescription arm = model::buildBodyModel(model::BuildOptions{});
    system::MultibodyModel model(arm);
    const SimTK::State initial = model.realizeTopology();
    const std::vector<std::string> joints = fingerJoints(arm);
    control::FingertipIk fast(model, kTips, joints);
    control::FingertipIk reference(model, kTips, joints, control::IkMethod::Assembler);
    std::mt19937 rng(11);
    for (int trial = 0; trial < 10; ++trial) {
        const SimTK::State known = makeRandomPose(model, initial, joints, rng, 0.8);
        const SimTK::State start = makeRandomPose(model, initial, joints, rng, 0.3);
        std::vector<SimTK::Vec3> goals;
        for (const std::string& tip : kTips) goals.push_back(model.findEndEffectorLocationInGround(known, tip));
        const IkAnswer a = solveAndPlace(model, fast, joints, start, goals), b = solveAndPlace(model, reference, joints, start, goals);
        for (std::size_t e = 0; e < kTips.size(); ++e) {
            EXPECT_LT((a.tips[e] - goals[e]).norm(), 1e-6) << "trial " << trial << " " << kTips[e];
            EXPECT_LT((b.tips[e] - goals[e]).norm(), 1e-3) << "trial " << trial << " " << kTips[e];
        }
        EXPECT_LE(a.error, b.error + 1e-9) << "trial " << trial;
    }
}

// Unreachable goals (each pushed 3 cm beyond a reachable one, into the palm's side or out of
// reach): both methods return a least-squares closest pose. Oracle: the Assembler's answer; the
// residual agrees within 1 um, or the fast one is the better fit. The optimum lies in a shallow
// valley (the residual moves by less than 1 um along 0.1 mm of fingertip travel), so where the two
// solvers stop in it depends on rounding (a clang build stops 0.11 mm apart, gcc's closer): the
// fingertips agree within 0.5 mm.
TEST(FingertipIk, FindsTheClosestPoseForUnreachableGoalsAsTheAssemblerDoes) {
    const model::ModelDescription arm = model::buildBodyModel(model::BuildOptions{});
    system::MultibodyModel model(arm);
    const SimTK::State initial = model.realizeTopology();
    const std::vector<std::string> joints = fingerJoints(arm);
    control::FingertipIk fast(model, kTips, joints);
    control::FingertipIk reference(model, kTips, joints, control::IkMethod::Assembler);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(-1, 1);
    for (int trial = 0; trial < 10; ++trial) {
        const SimTK::State known = makeRandomPose(model, initial, joints, rng, 0.8);
        const SimTK::State start = makeRandomPose(model, initial, joints, rng, 0.3);
        std::vector<SimTK::Vec3> goals;
        for (const std::string& tip : kTips) {
            const SimTK::UnitVec3 away(unit(rng), unit(rng), unit(rng));
            goals.push_back(model.findEndEffectorLocationInGround(known, tip) + 0.03 * away);
        }
        const IkAnswer a = solveAndPlace(model, fast, joints, start, goals), b = solveAndPlace(model, reference, joints, start, goals);
        EXPECT_GT(b.error, 1e-3) << "trial " << trial << ": the goals were meant to be out of reach";
        if (a.error < b.error - 1e-6) continue;  // a better least-squares fit than the reference found
        EXPECT_NEAR(a.error, b.error, 1e-6) << "trial " << trial;
        for (std::size_t e = 0; e < kTips.size(); ++e) EXPECT_LT((a.tips[e] - b.tips[e]).norm(), 5e-4) << "trial " << trial << " " << kTips[e];
    }
}

// An end-effector need not be a fingertip: a point fixed on any segment (model::SegmentPoint,
// here the radial side of the index's middle phalanx, the lateral pinch's contact) is placed by
// the joints from the palm out to its segment. Oracle: goals made by a known pose are reachable;
// both methods put both points on them, and a joint outboard of the segment (the index DIP) is
// left where it was.
TEST(FingertipIk, PlacesAPointOnAMiddlePhalanxAsItPlacesFingertips) {
    model::BuildOptions options;
    options.segmentPoints.push_back({"index_side", "index_middle", {0, -0.0134, 0.0081}});
    system::MultibodyModel model(model::buildBodyModel(options));
    SimTK::State s = model.realizeTopology();
    model.setJointPosition(s, "index_dip_flexion", 0.5);
    const std::vector<std::string> effectors{"thumb_tip", "index_side"};
    const std::vector<std::string> joints{"thumb_cmc_abduction", "thumb_cmc_flexion", "thumb_mcp_flexion", "thumb_ip_flexion",
                                          "index_mcp_abduction", "index_mcp_flexion", "index_pip_flexion"};
    SimTK::State known = s;
    const std::vector<double> knownAngles{0.35, -0.2, 0.1, 0.05, 0.05, 0.5, 1.0};
    for (std::size_t k = 0; k < joints.size(); ++k) model.setJointPosition(known, joints[k], knownAngles[k]);
    model.getSystem().realize(known, SimTK::Stage::Position);
    std::vector<SimTK::Vec3> goals;
    for (const std::string& e : effectors) goals.push_back(model.findEndEffectorLocationInGround(known, e));
    for (control::IkMethod method : {control::IkMethod::DampedLeastSquares, control::IkMethod::Assembler}) {
        control::FingertipIk ik(model, effectors, joints, method);
        const SimTK::Vector q = ik.solve(s, goals);
        SimTK::State solved = s;
        for (std::size_t k = 0; k < joints.size(); ++k) model.setJointPosition(solved, joints[k], q[static_cast<int>(k)]);
        model.getSystem().realize(solved, SimTK::Stage::Position);
        for (std::size_t e = 0; e < effectors.size(); ++e) {
            EXPECT_LT((model.findEndEffectorLocationInGround(solved, effectors[e]) - goals[e]).norm(), 1e-4) << effectors[e];
            EXPECT_LT(ik.getLastDistances()[e], 1e-4) << effectors[e];
        }
        EXPECT_DOUBLE_EQ(model.getJointPosition(solved, "index_dip_flexion"), 0.5);
    }
}
