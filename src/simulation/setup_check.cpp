#include "graspsim/simulation/setup_check.h"

#include "graspsim/contact/contact_shape.h"
#include "graspsim/contact/shape_contact.h"
#include "graspsim/error.h"
#include "graspsim/simulation/grasp_experiment.h"
#include "graspsim/simulation/grasp_scene.h"

#include <algorithm>
#include <cstdio>

namespace graspsim::simulation {

namespace {

// The deepest contact between one segment geometry at X_GS and the object's geometries; 0 if none.
double findDeepestContact(const model::Geometry& segment, const SimTK::Transform& X_GS,
                          const model::Body& object, const SimTK::Transform& X_GO) {
    double deepest = 0;
    for (const model::Geometry& o : object.geometry) {
        for (const contact::ContactPoint& c : contact::findContacts(segment, X_GS, o, X_GO * contact::findGeometryPose(o))) {
            deepest = std::max(deepest, c.depth);
        }
    }
    return deepest;
}

// Every segment geometry of the arm and hand that overlaps the object, deepest first.
std::vector<SegmentOverlap> findOverlaps(const GraspScene& scene, const SimTK::State& state) {
    const model::ModelDescription objectModel = scenario::buildObjectModel(scene.getScenario().object);
    const model::Body& object = objectModel.bodies.at(0);
    const SimTK::Transform& X_GO = scene.getObject().getBodyTransform(state);
    std::vector<SegmentOverlap> overlaps;
    for (const model::Body& body : scene.getModel().getDescription().bodies) {
        if (body.isVirtual()) continue;
        const SimTK::Transform& X_GB = scene.getModel().getMobilizedBody(body.name).getBodyTransform(state);
        for (const model::Geometry& g : body.geometry) {
            const double depth = findDeepestContact(g, X_GB * contact::findGeometryPose(g), object, X_GO);
            if (depth > 0) overlaps.push_back({body.name, g.name, depth});
        }
    }
    std::stable_sort(overlaps.begin(), overlaps.end(),
                     [](const SegmentOverlap& a, const SegmentOverlap& b) { return a.depth > b.depth; });
    return overlaps;
}

std::string formatMm(double metres) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f mm", metres * 1000);
    return text;
}

}  // namespace

SetupCheck calcSetupCheck(const GraspScene& scene, const SimTK::State& state) {
    scene.getSystem().realize(state, SimTK::Stage::Position);
    SetupCheck check;
    check.overlaps = findOverlaps(scene, state);
    if (!check.overlaps.empty()) check.initialPenetration = check.overlaps.front().depth;
    const std::vector<double>& distances = scene.getController().getIk().getLastDistances();
    const std::vector<std::string>& endEffectors = scene.getGoalEndEffectors();
    for (std::size_t k = 0; k < endEffectors.size(); ++k) {
        check.goals.push_back({endEffectors[k], k < distances.size() ? distances[k] : 0.0});
    }
    return check;
}

void requireSetup(const SetupCheck& check, const std::string& where) {
    const std::string prefix = where + ": at t = 0 ";
    if (check.initialPenetration > kMaxInitialPenetration) {
        const SegmentOverlap& o = check.overlaps.front();
        throw InputError(prefix + "segment '" + o.body + "' (geometry " + o.geometry + ") is " + formatMm(o.depth) +
                         " inside the object (limit " + formatMm(kMaxInitialPenetration) +
                         "); change grasp_pose or the object's position, or plan the grasp (grasp: {type: ...})");
    }
    const auto farthest = std::max_element(check.goals.begin(), check.goals.end(),
                                           [](const GoalReach& a, const GoalReach& b) { return a.distance < b.distance; });
    if (farthest != check.goals.end() && farthest->distance > kGoalReachTolerance) {
        throw InputError(prefix + "goal '" + farthest->endEffector + "' is out of reach: the fingertip IK from grasp_pose "
                         "ends " + formatMm(farthest->distance) + " from it (limit " + formatMm(kGoalReachTolerance) +
                         "); move the goal or change grasp_pose");
    }
}

// The whole run's system, approximation and loads included: a run checked here must not fail on
// its options once its folder exists.
SetupCheck checkScenarioSetup(const scenario::Scenario& scenario, const SimulationOptions& options) {
    GraspExperiment experiment(scenario, options);
    experiment.makeInitialState();  // checks the initial state
    return experiment.getScene().getSetupCheck();
}

}  // namespace graspsim::simulation
