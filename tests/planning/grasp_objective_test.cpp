// The planner's objective on a convex mesh and on a flat ellipsoid, both started turned like a box.
// Oracle for the mesh: the box of the same solid, a second method (closed-form box geometry, the
// box's start pose and the box's plan): a mesh of the phone must start where the phone starts and
// plan the same pinch, within the planner's own spread. For the ellipsoid: the box whose
// half-lengths are its semi-axes, and symmetry (the same solid, its axes labelled three ways).

#include "grasp_objective.h"

#include "graspsim/contact/convex_polytope.h"
#include "graspsim/planning/lateral_pinch.h"
#include "graspsim/planning/planned_scenario.h"
#include "graspsim/scenario/scenario_file.h"
#include "graspsim/system/simtk_conversion.h"

#include "scratch_folder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

using namespace graspsim;
using namespace graspsim::planning;

namespace {

// The box of half-lengths h as a closed, outward-facing mesh: 8 vertices, 12 triangles, centred
// at the origin. Vertex i has the sign bits (x, y, z) = (i & 4, i & 2, i & 1).
model::TriangleMesh makeBoxMesh(const SimTK::Vec3& h) {
    model::TriangleMesh mesh;
    for (int i = 0; i < 8; ++i) {
        mesh.vertices.push_back({(i & 4 ? 1 : -1) * h[0], (i & 2 ? 1 : -1) * h[1], (i & 1 ? 1 : -1) * h[2]});
    }
    mesh.triangles = {{1, 3, 2}, {1, 2, 0}, {4, 6, 7}, {4, 7, 5}, {0, 4, 5}, {0, 5, 1},
                      {3, 7, 6}, {3, 6, 2}, {2, 6, 4}, {2, 4, 0}, {1, 5, 7}, {1, 7, 3}};
    return mesh;
}

GraspRequest makeRequest(const contact::ContactShape& shape, GraspType type = GraspType::Pinch) {
    GraspRequest request;
    request.shape = shape;
    request.type = type;
    request.mass = 0.1;
    if (type == GraspType::Lateral) request.bodyOptions = addIndexRadialPoint(request.bodyOptions);  // as planGrasp
    return request;
}

void writeBoxObj(const std::string& path, const SimTK::Vec3& h) {
    std::ofstream out(path);
    for (const model::Vec3& v : makeBoxMesh(h).vertices) out << "v " << v[0] << ' ' << v[1] << ' ' << v[2] << '\n';
    for (const auto& t : makeBoxMesh(h).triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
}

const char* kPlannedPhone = R"(name: phone
object: {shape: box, mass: 0.1, size: [0.07, 0.14, 0.008]}
grasp: {type: pinch}
)";

// The flat ellipsoid's semi-axes (m) labelled three ways: its thin axis along z, x and y of its frame.
const SimTK::Vec3 kFlatEllipsoid[] = {{0.035, 0.07, 0.004}, {0.004, 0.035, 0.07}, {0.07, 0.004, 0.035}};

// The scenario of a planned grasp of `type` on `object` (a scenario file's object value), planned.
scenario::Scenario planScenario(const std::string& object, const std::string& type) {
    const std::string text = "name: flat\nobject: " + object + "\ngrasp: {type: " + type + "}\n";
    scenario::Scenario s = scenario::parseScenario(text, "flat.yaml");
    completeScenario(s);
    return s;
}

std::string formatEllipsoid(const SimTK::Vec3& semiAxes) {
    std::ostringstream text;
    text << "{shape: ellipsoid, mass: 0.1, semi_axes: [" << semiAxes[0] << ", " << semiAxes[1] << ", "
         << semiAxes[2] << "]}";
    return text.str();
}

// A planned scenario's goal for `effector` in G (m).
SimTK::Vec3 findGoal_G(const scenario::Scenario& s, const std::string& effector) {
    return system::toSimTKTransform(s.object.findPose(), "pose") * system::toSimTKVec3(s.goals.at(effector));
}

// The planned object's axis `k` in G.
SimTK::UnitVec3 findAxis_G(const scenario::Scenario& s, int k) {
    return system::toSimTKTransform(s.object.findPose(), "pose").R()(k);
}

int findThinAxis(const SimTK::Vec3& semiAxes) {
    return int(std::min_element(&semiAxes[0], &semiAxes[0] + 3) - &semiAxes[0]);
}

// Pinched across the thickness, the way round the box's start puts it: the thumb's goal on the
// thin axis's - side and the other pad's on its + side, both off the centre by over half the
// thickness.
void expectAcrossTheThickness(const scenario::Scenario& s, const SimTK::Vec3& semiAxes, const std::string& other) {
    const int thin = findThinAxis(semiAxes);
    EXPECT_LT(s.goals.at("thumb_tip")[thin], -semiAxes[thin] / 2) << semiAxes;
    EXPECT_GT(s.goals.at(other)[thin], semiAxes[thin] / 2) << semiAxes;
}

}  // namespace

// A flat ellipsoid starts as the box whose half-lengths are its semi-axes starts (thinnest axis
// along the squeeze, longest out of the hand), in a pinch and in a lateral pinch, however its
// axes are labelled. Oracles: the box's start pose; and symmetry, a second method: the one solid
// labelled three ways sits the same in G at the start, so its start cost is one number to
// round-off. Left unturned, it started with its frame's axes along G's, its thin axis along z_G
// nearly across the pinch, or along y_G, whose pinch was refused.
TEST(GraspObjective, AFlatEllipsoidStartsAsTheBoxOfItsSemiAxes) {
    for (const GraspType type : {GraspType::Pinch, GraspType::Lateral}) {
        const GraspTemplate graspTemplate = findGraspTemplate(type);
        std::vector<double> costs;
        for (const SimTK::Vec3& h : kFlatEllipsoid) {
            GraspObjective box(makeRequest(contact::ContactShape::box(h), type), graspTemplate);
            GraspObjective ellipsoid(makeRequest(contact::ContactShape::ellipsoid(h), type), graspTemplate);
            const SimTK::Transform X_GO_box = box.makePlan(box.getStart().data()).X_GO;
            const SimTK::Transform X_GO = ellipsoid.makePlan(ellipsoid.getStart().data()).X_GO;
            EXPECT_LT((X_GO.R().asMat33() - X_GO_box.R().asMat33()).norm(), 1e-15) << h;
            EXPECT_LT((X_GO.p() - X_GO_box.p()).norm(), 1e-15) << h;
            costs.push_back(ellipsoid.evaluate(ellipsoid.getStart().data()));
        }
        for (const double cost : costs) EXPECT_NEAR(cost, costs[0], 1e-9 * costs[0]) << int(type);
    }
}

// findVariables is makePlan's inverse: a plan's variables give that plan back, so the optimum of
// a box's smooth stand-in (the ellipsoid of its half-lengths, object_extents.h) starts the box's
// own optimization where the stand-in's ended. Oracles: the variables themselves (every one moved
// off the start: joints, position, a 1.6 rad turn) and the stand-in's object pose in G. A mesh
// of the box moved off its frame's origin starts elsewhere than its stand-in (the start places
// the shape frame), so only the pose is compared there.
TEST(GraspObjective, ThePlanOfASmoothStandInStartsTheShapeWhereItEnded) {
    const GraspTemplate lateral = findGraspTemplate(GraspType::Lateral);
    const SimTK::Vec3 h = kFlatEllipsoid[0];
    GraspObjective box(makeRequest(contact::ContactShape::box(h), GraspType::Lateral), lateral);
    GraspObjective standIn(makeRequest(contact::ContactShape::ellipsoid(h), GraspType::Lateral), lateral);
    std::vector<double> x = standIn.getStart();
    for (std::size_t k = 0; k < x.size(); ++k) x[k] += 0.3 * (standIn.getUpperBounds()[k] - x[k]);
    const SimTK::Vec3 turn(0.9, -0.6, 1.2);  // rad: the rotation vector, the last three variables
    for (int i = 0; i < 3; ++i) x[x.size() - 3 + i] = turn[i];
    const GraspPlan plan = standIn.makePlan(x.data());
    const std::vector<double> back = box.findVariables(plan.jointAngles, plan.X_GO);
    ASSERT_EQ(back.size(), x.size());
    for (std::size_t k = 0; k < x.size(); ++k) EXPECT_NEAR(back[k], x[k], 1e-12) << k;

    const SimTK::Vec3 centre(0.01, -0.02, 0.003);
    model::TriangleMesh moved = makeBoxMesh(h);
    for (model::Vec3& v : moved.vertices) {
        for (int i = 0; i < 3; ++i) v[i] += centre[i];
    }
    GraspRequest meshRequest = makeRequest(
        contact::ContactShape::convexMesh(contact::ConvexPolytope::build(moved, "moved box mesh")), GraspType::Lateral);
    GraspObjective mesh(meshRequest, lateral);
    GraspRequest meshStandIn = meshRequest;
    meshStandIn.shape = contact::ContactShape::ellipsoid(h);
    meshStandIn.X_OS = SimTK::Transform(centre);
    const GraspPlan meshPlan = GraspObjective(meshStandIn, lateral).makePlan(x.data());
    const SimTK::Transform X_GO = mesh.makePlan(mesh.findVariables(meshPlan.jointAngles, meshPlan.X_GO).data()).X_GO;
    EXPECT_LT((X_GO.R().asMat33() - meshPlan.X_GO.R().asMat33()).norm(), 1e-12);
    EXPECT_LT((X_GO.p() - meshPlan.X_GO.p()).norm(), 1e-12);
}

// The reported case: a pinch of a flat ellipsoid, planned on load, whichever of its axes the file
// makes the thin one. Oracles: the box of its semi-axes (a second method, the box's plan): the
// ellipsoid is pinched across its thickness with its thin axis in G within 10 deg of the box's
// (1.2 deg measured), the same way round; and symmetry: the three labellings' goals end within
// 2 mm of one another in G (0.4 mm measured). Before, the thin axis along y was refused ("the
// thumb_tip cannot press its goal") and along z pinched the other way round, 11 mm away.
TEST(GraspObjective, AFlatEllipsoidIsPinchedAsTheBoxOfItsSemiAxes) {
    const scenario::Scenario box = planScenario("{shape: box, mass: 0.1, size: [0.07, 0.14, 0.008]}", "pinch");
    const SimTK::UnitVec3 thin_G_box = findAxis_G(box, 2);
    std::vector<scenario::Scenario> plans;
    for (const SimTK::Vec3& h : kFlatEllipsoid) {
        ASSERT_NO_THROW(plans.push_back(planScenario(formatEllipsoid(h), "pinch"))) << h;
        expectAcrossTheThickness(plans.back(), h, "index_tip");
        EXPECT_GT(dot(findAxis_G(plans.back(), findThinAxis(h)), thin_G_box), std::cos(10 * SimTK::Pi / 180)) << h;
    }
    for (const std::string effector : {"thumb_tip", "index_tip"}) {
        for (const scenario::Scenario& plan : plans) {
            EXPECT_LT((findGoal_G(plan, effector) - findGoal_G(plans[0], effector)).norm(), 0.002) << effector;
        }
    }
}

// The same in a lateral pinch, with symmetry alone as oracle: the thin axis along z and along x give
// goals within 2 mm in G (0.2 mm measured, 8.5 mm before), each across the thickness. (The box of
// its semi-axes was refused then, the index's side 8.3 mm from it; it is planned now through this
// ellipsoid: LateralPinch.APhoneSizedBoxIsPinchedAcrossItsThicknessHoweverItsAxesAreLabelled.)
TEST(GraspObjective, AFlatEllipsoidsLateralPinchDoesNotDependOnItsAxesLabels) {
    const scenario::Scenario z = planScenario(formatEllipsoid(kFlatEllipsoid[0]), "lateral");
    const scenario::Scenario x = planScenario(formatEllipsoid(kFlatEllipsoid[1]), "lateral");
    expectAcrossTheThickness(z, kFlatEllipsoid[0], kIndexRadialEffector);
    expectAcrossTheThickness(x, kFlatEllipsoid[1], kIndexRadialEffector);
    for (const std::string effector : {"thumb_tip", kIndexRadialEffector}) {
        EXPECT_LT((findGoal_G(z, effector) - findGoal_G(x, effector)).norm(), 0.002) << effector;
    }
}

// A mesh of the phone starts where the phone does (thinnest axis along the squeeze, longest out
// of the hand): the cost at the start, with the mesh's exact double vertices, is the box's to
// round-off. Left unturned, the mesh started edge-on to the pads and its plan put both pads on
// edges, where no press goes into the object. Also with the thickness along x.
TEST(GraspObjective, AMeshOfABoxStartsWhereTheBoxStarts) {
    const GraspTemplate pinch = findGraspTemplate(GraspType::Pinch);
    for (const SimTK::Vec3& h : {SimTK::Vec3(0.035, 0.07, 0.004), SimTK::Vec3(0.004, 0.035, 0.07)}) {
        const auto polytope = contact::ConvexPolytope::build(makeBoxMesh(h), "box mesh");
        GraspObjective box(makeRequest(contact::ContactShape::box(h)), pinch);
        GraspObjective mesh(makeRequest(contact::ContactShape::convexMesh(polytope)), pinch);
        ASSERT_EQ(mesh.getStart(), box.getStart());
        const double boxCost = box.evaluate(box.getStart().data());
        EXPECT_NEAR(mesh.evaluate(mesh.getStart().data()), boxCost, 1e-12 * boxCost) << h;
    }
}

// The reported case: a scenario file pinching a mesh of the phone (an OBJ, read in single
// precision, so a solid 3e-10 m larger) is planned on load, as the same file with the box is.
// Second method: the box's plan. Both pinch across the thickness, thumb on the -z face, and the
// goals end within 5 mm of each other in G. Not closer: the plan is that sensitive to round-off
// (BOBYQA stops at its evaluation budget, the phone free to slide in the pinch): a box 1e-15 m
// larger moves its own goals 3.3 mm in G (20 mm along the face, the phone turned 12 deg).
class GraspObjectiveMesh : public graspsim::testing::ScratchFolder {};

TEST_F(GraspObjectiveMesh, AScenarioPinchingAMeshOfThePhonePlansAsTheBox) {
    writeBoxObj((dir_ / "phone.obj").string(), {0.035, 0.07, 0.004});
    std::string meshText = kPlannedPhone;
    meshText.replace(meshText.find("shape: box"), 10, "shape: mesh, mesh: phone.obj");
    meshText.replace(meshText.find(", size: [0.07, 0.14, 0.008]"), 27, "");
    std::ofstream((dir_ / "mesh.yaml").string()) << meshText;

    scenario::Scenario box = scenario::parseScenario(kPlannedPhone, "box.yaml");
    scenario::Scenario mesh = scenario::loadScenarioFile((dir_ / "mesh.yaml").string());
    completeScenario(box);
    ASSERT_NO_THROW(completeScenario(mesh));  // before: "the thumb_tip cannot press its goal"
    const SimTK::Transform X_GO_box = system::toSimTKTransform(box.object.findPose(), "box pose");
    const SimTK::Transform X_GO_mesh = system::toSimTKTransform(mesh.object.findPose(), "mesh pose");
    ASSERT_EQ(mesh.goals.size(), 2u);
    for (const auto& [effector, goal] : box.goals) {
        const SimTK::Vec3 p_O = system::toSimTKVec3(mesh.goals.at(effector));
        EXPECT_NEAR(p_O[2], goal[2], 1e-4) << effector << ": the same face";
        const SimTK::Vec3 p_G_box = X_GO_box * system::toSimTKVec3(goal), p_G_mesh = X_GO_mesh * p_O;
        EXPECT_LT((p_G_mesh - p_G_box).norm(), 0.005) << effector;
    }
    EXPECT_LT(mesh.goals.at("thumb_tip")[2], 0);
}
