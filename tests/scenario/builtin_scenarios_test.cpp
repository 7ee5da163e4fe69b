// The built-in scenarios against the geometry of the arm they drive. Oracle: forward kinematics
// of the model description (X_GC = X_GP * X_PJ * R(axis, q) down each joint chain) and the
// closed-form distances between spheres, boxes and capsules.

#include "graspsim/scenario/scenario_file.h"

#include "graspsim/model/body_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>

using namespace graspsim;
using namespace graspsim::scenario;
using model::Transform;

namespace {

// Fingertips must be this close to their goals in the grasp pose (m): near enough for the IK to
// close the gap in the approach, as the thesis's "almost in contact" poses.
constexpr double kFingertipGoalTolerance = 0.015;
// Goals lie on the surface to this (m); the parser allows 1 mm, the files round to 0.1 mm.
constexpr double kOnSurface = 0.001;

Vec3 subtract(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
// Axis i (0 = x, 1 = y, 2 = z) of frame F, in G.
Vec3 getAxis(const Transform& X_GF, int i) {
    Vec3 unit{0, 0, 0};
    unit[i] = 1;
    return X_GF.xformFrameVecToBase(unit);
}

Transform invert(const Transform& X_AB) {
    Transform X_BA;
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) X_BA.R[3 * i + k] = X_AB.R[3 * k + i];
    const Vec3 p = X_BA.xformFrameVecToBase(X_AB.p);
    X_BA.p = {-p[0], -p[1], -p[2]};
    return X_BA;
}

// Pose in ground of `body` for the joint angles `q` (rad; joints not in q at 0).
Transform calcBodyPose(const model::ModelDescription& m, const std::map<std::string, double>& q,
                       const std::string& body) {
    const model::Joint* joint = m.findParentJoint(body);
    if (!joint) return m.X_GR;
    const auto angle = q.find(joint->name);
    return calcBodyPose(m, q, joint->parent) * joint->X_PJ *
           Transform::axisAngle(joint->axis, angle == q.end() ? 0.0 : angle->second);
}

// Distance from point p_G to a box of half-lengths h at X_GB (m); negative inside.
double calcPointBoxDistance(const Transform& X_GB, const Vec3& h, const Vec3& p_G) {
    const Vec3 p = invert(X_GB).shiftFrameStationToBase(p_G);
    double outside = 0, inside = -INFINITY;
    for (int i = 0; i < 3; ++i) {
        const double d = std::abs(p[i]) - h[i];
        outside += d > 0 ? d * d : 0;
        inside = std::max(inside, d);
    }
    return inside > 0 ? std::sqrt(outside) : inside;
}

// Hand geometry in ground: a capsule is its axis segment and radius; a box its pose and half-lengths.
struct Capsule {
    std::string name;
    Vec3 a, b;
    double radius;
};
struct Box {
    std::string name;
    Transform X_GB;
    Vec3 halfLengths;
};

// The object as geometry in ground, with distance functions for points and capsules.
struct PlacedObject {
    ObjectSpec spec;
    Transform X_GO;

    double calcDistance(const Vec3& p_G) const {
        if (spec.shape == ObjectShape::Sphere) return norm(subtract(p_G, X_GO.p)) - spec.radius;
        return calcPointBoxDistance(X_GO, {spec.size[0] / 2, spec.size[1] / 2, spec.size[2] / 2}, p_G);
    }
    // The distance from a point to a convex object is convex along a segment: ternary search
    // finds its minimum exactly (to 1e-12 of the segment).
    double calcDistance(const Capsule& c) const {
        auto at = [&](double t) {
            return calcDistance({c.a[0] + t * (c.b[0] - c.a[0]), c.a[1] + t * (c.b[1] - c.a[1]),
                                 c.a[2] + t * (c.b[2] - c.a[2])});
        };
        double lo = 0, hi = 1;
        for (int i = 0; i < 100; ++i) {
            const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
            if (at(m1) < at(m2)) {
                hi = m2;
            } else {
                lo = m1;
            }
        }
        return at((lo + hi) / 2) - c.radius;
    }
};

// Separating-axis test between two boxes: true when some face normal or edge cross product
// separates them by more than `gap` (m).
bool areBoxesSeparated(const Box& A, const Transform& X_GO, const Vec3& hO, double gap) {
    std::vector<Vec3> axes;
    for (int i = 0; i < 3; ++i) {
        axes.push_back(getAxis(A.X_GB, i));
        axes.push_back(getAxis(X_GO, i));
    }
    for (int i = 0; i < 6; i += 2)
        for (int k = 1; k < 6; k += 2) {
            const Vec3& u = axes[i];
            const Vec3& v = axes[k];
            const Vec3 c{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
            if (norm(c) > 1e-9) axes.push_back({c[0] / norm(c), c[1] / norm(c), c[2] / norm(c)});
        }
    // Half the extent of a box projected on n.
    auto radius = [](const Transform& X, const Vec3& h, const Vec3& n) {
        double r = 0;
        for (int i = 0; i < 3; ++i) r += h[i] * std::abs(dot(n, getAxis(X, i)));
        return r;
    };
    for (const Vec3& n : axes) {
        const double centres = std::abs(dot(n, subtract(X_GO.p, A.X_GB.p)));
        if (centres - radius(A.X_GB, A.halfLengths, n) - radius(X_GO, hO, n) > gap) return true;
    }
    return false;
}

// The arm in the scenario's grasp pose.
struct PosedArm {
    model::ModelDescription model;
    std::map<std::string, Transform> X_GB;  // every body

    explicit PosedArm(const Scenario& scenario) : model(model::buildBodyModel(scenario.bodyOptions)) {
        for (const model::Body& body : model.bodies) {
            X_GB[body.name] = calcBodyPose(model, scenario.graspPose, body.name);
        }
    }
    Vec3 findEndEffector(const std::string& name) const {
        const model::EndEffector* e = model.findEndEffector(name);
        return X_GB.at(e->body).shiftFrameStationToBase(e->p_BE);
    }
    std::vector<Capsule> getHandCapsules() const;
    std::vector<Box> getPalmBoxes() const;
};

std::vector<Capsule> PosedArm::getHandCapsules() const {
    std::vector<Capsule> capsules;
    for (const model::Body& body : model.bodies) {
        if (body.segment != "hand") continue;
        for (const model::Geometry& g : body.geometry) {
            if (g.type != model::Geometry::Type::Capsule) continue;
            const Transform X_GG = X_GB.at(body.name) * g.X_BG;  // capsule axis along its frame's z
            capsules.push_back({g.name, X_GG.shiftFrameStationToBase({0, 0, -g.length / 2}),
                                X_GG.shiftFrameStationToBase({0, 0, g.length / 2}), g.radius});
        }
    }
    return capsules;
}

std::vector<Box> PosedArm::getPalmBoxes() const {
    std::vector<Box> boxes;
    for (const model::Geometry& g : model.findBody("palm")->geometry) {
        if (g.type == model::Geometry::Type::Box) boxes.push_back({g.name, X_GB.at("palm") * g.X_BG, g.halfLengths});
    }
    return boxes;
}

class BuiltinScenario : public ::testing::TestWithParam<std::string> {
protected:
    const Scenario scenario = findBuiltinScenario(GetParam());
    const PosedArm arm{scenario};
    const PlacedObject object{scenario.object, scenario.object.findPose()};

    Vec3 findGoalInGround(const std::string& effector) const {
        return object.X_GO.shiftFrameStationToBase(scenario.goals.at(effector));
    }
};

}  // namespace

TEST_P(BuiltinScenario, FingertipsAreNearTheirGoalsInTheGraspPose) {
    for (const auto& [effector, goal] : scenario.goals) {
        const Vec3 p_GE = arm.findEndEffector(effector);
        const double distance = norm(subtract(p_GE, findGoalInGround(effector)));
        std::cout << "[" << scenario.name << "] " << effector << ": " << distance * 1000 << " mm from its goal, "
                  << object.calcDistance(p_GE) * 1000 << " mm off the surface\n";
        EXPECT_LT(distance, kFingertipGoalTolerance) << effector;
        // "Almost touching": outside the object, not pressed into it yet.
        EXPECT_GT(object.calcDistance(p_GE), 0) << effector;
    }
}

TEST_P(BuiltinScenario, GoalsLieOnTheObjectsSurface) {
    const ObjectSpec& o = scenario.object;
    for (const auto& [effector, p] : scenario.goals) {
        if (o.shape == ObjectShape::Sphere) {
            EXPECT_NEAR(norm(p), o.radius, kOnSurface) << effector;
        } else {
            // On a face: one coordinate at a half-length, the others within theirs.
            int onFace = 0;
            for (int i = 0; i < 3; ++i) {
                EXPECT_LE(std::abs(p[i]), o.size[i] / 2 + kOnSurface) << effector;
                onFace += std::abs(std::abs(p[i]) - o.size[i] / 2) <= kOnSurface;
            }
            EXPECT_GE(onFace, 1) << effector;
        }
    }
}

TEST_P(BuiltinScenario, ObjectTouchesNoPartOfTheHand) {
    for (const Capsule& capsule : arm.getHandCapsules()) {
        EXPECT_GT(object.calcDistance(capsule), 0) << capsule.name;
    }
    const Vec3 h{scenario.object.size[0] / 2, scenario.object.size[1] / 2, scenario.object.size[2] / 2};
    for (const Box& box : arm.getPalmBoxes()) {
        if (scenario.object.shape == ObjectShape::Sphere) {
            const double centreToBox = calcPointBoxDistance(box.X_GB, box.halfLengths, object.X_GO.p);
            EXPECT_GT(centreToBox, scenario.object.radius) << box.name;
        } else {
            EXPECT_TRUE(areBoxesSeparated(box, object.X_GO, h, 0)) << box.name;
        }
    }
}

TEST_P(BuiltinScenario, GraspPoseRespectsTheRangesOfMotion) {
    for (const auto& [name, angle] : scenario.graspPose) {
        const model::Joint* joint = arm.model.findJoint(name);
        ASSERT_NE(joint, nullptr) << name;
        EXPECT_GE(angle, joint->lower) << name;
        EXPECT_LE(angle, joint->upper) << name;
    }
}

TEST_P(BuiltinScenario, EmbeddedCopyIsTheFileInModels) {
    const Scenario file = loadScenarioFile(GRASPSIM_SOURCE_DIR "/models/scenarios/" + GetParam() + ".yaml");
    EXPECT_EQ(file.name, scenario.name);
    EXPECT_EQ(file.graspPose, scenario.graspPose);
    EXPECT_EQ(file.goals, scenario.goals);
    EXPECT_EQ(file.object.position, scenario.object.position);
    EXPECT_EQ(file.object.orientation, scenario.object.orientation);
    EXPECT_EQ(file.perturbations.size(), scenario.perturbations.size());
    EXPECT_EQ(file.contact.effectiveStiffness, scenario.contact.effectiveStiffness);
    EXPECT_EQ(file.controller.kp, scenario.controller.kp);
    EXPECT_EQ(file.simulation.duration, scenario.simulation.duration);
}

INSTANTIATE_TEST_SUITE_P(Thesis, BuiltinScenario, ::testing::Values("ball-clutch", "phone-pinch"),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                             return std::string(param.param == "ball-clutch" ? "BallClutch" : "PhonePinch");
                         });

TEST(BuiltinScenarios, EveryFileInModelsScenariosIsBuiltIn) {
    const std::vector<std::string> names = getBuiltinScenarioNames();
    for (const auto& entry : std::filesystem::directory_iterator(GRASPSIM_SOURCE_DIR "/models/scenarios")) {
        if (entry.path().extension() != ".yaml") continue;
        const std::string name = entry.path().stem().string();
        EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name << " is not embedded";
    }
}

TEST(BuiltinScenarios, BallClutchThumbOpposesTheFingers) {
    const Scenario s = findBuiltinScenario("ball-clutch");
    Vec3 fingers{0, 0, 0};
    for (const char* tip : {"index_tip", "middle_tip", "ring_tip", "little_tip"}) {
        for (int i = 0; i < 3; ++i) fingers[i] += s.goals.at(tip)[i] / s.object.radius;
    }
    const Vec3& thumb = s.goals.at("thumb_tip");
    // Cosine between the thumb's direction from the centre and the fingers' mean direction.
    EXPECT_LT(dot(thumb, fingers) / (norm(thumb) * norm(fingers)), -0.5);
}

TEST(BuiltinScenarios, PhonePinchThumbAndIndexAreOnOppositeFacesAcrossTheThickness) {
    const Scenario s = findBuiltinScenario("phone-pinch");
    const double halfThickness = s.object.size[2] / 2;  // the phone's thin axis is its z
    EXPECT_NEAR(s.goals.at("index_tip")[2], halfThickness, kOnSurface);
    EXPECT_NEAR(s.goals.at("thumb_tip")[2], -halfThickness, kOnSurface);
    // Across the thickness: the two goals nearly face each other (in-plane offset < 5 mm).
    EXPECT_LT(std::hypot(s.goals.at("index_tip")[0] - s.goals.at("thumb_tip")[0],
                         s.goals.at("index_tip")[1] - s.goals.at("thumb_tip")[1]),
              0.005);
}
