#include "graspsim/planning/planned_scenario.h"

#include "graspsim/planning/plan_rounding.h"
#include "graspsim/scenario/scenario_file.h"
#include "graspsim/scenario/scenario_writer.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace graspsim::planning {

scenario::Scenario applyPlan(const scenario::Scenario& base, const GraspPlan& plan) {
    scenario::Scenario s = base;
    s.graspPose.clear();
    for (const auto& [joint, angle] : plan.jointAngles) {
        if (angle != 0) s.graspPose[joint] = angle;  // the file lists only the joints that move
    }
    s.goals.clear();
    for (const auto& [effector, p_OP] : plan.goals) s.goals[effector] = {p_OP[0], p_OP[1], p_OP[2]};
    // The plan's orientation is at 0.1 deg (planGrasp rounds it): the angles recovered from its
    // rotation are rounded again, or the file would show their float noise (97.60000000000001).
    const SimTK::Vec3 xyz = findRoundedOrientation(plan.X_GO.R());
    s.object.position = {plan.X_GO.p()[0], plan.X_GO.p()[1], plan.X_GO.p()[2]};
    s.object.orientation = {xyz[0], xyz[1], xyz[2]};
    s.controller.kp = plan.kp;
    if (plan.capsuleContact == contact::CapsuleContact::Ends) s.contact.capsuleContact = plan.capsuleContact;
    s.bodyOptions.segmentPoints = plan.segmentPoints;
    // as planned: within a thin object's half-thickness, deeper where the fingers would not press
    s.controller.pressDepth = plan.pressDepth > 0 ? plan.pressDepth : findPlannedPressDepth(s);
    return s;
}

scenario::Scenario planScenario(const scenario::Scenario& base, GraspType type) {
    return applyPlan(base, planGrasp(makeGraspRequest(base, type)));
}

void completeScenario(scenario::Scenario& scenario) {
    if (scenario.graspType.empty()) return;
    const GraspType type = parseGraspType(scenario.graspType, scenario.source + ": field 'grasp.type'");
    try {
        const bool kpGiven = scenario.controller.kpGiven;
        const double kp = scenario.controller.kp;
        scenario = planScenario(scenario, type);
        if (kpGiven) scenario.controller.kp = kp;  // the file's gain stays; otherwise the plan's
    } catch (const NoGraspError& e) {
        throw NoGraspError(scenario.source + ": " + e.what());
    }
    scenario.graspType.clear();
}

scenario::Scenario loadScenario(const std::string& nameOrPath) {
    scenario::Scenario scenario = scenario::loadScenario(nameOrPath);
    completeScenario(scenario);
    return scenario;
}

std::string formatPlannedScenario(const scenario::Scenario& planned, const GraspPlan& plan) {
    const PlanDiagnostics& d = plan.diagnostics;
    std::ostringstream header;
    char line[256];
    header << "Planned by graspsim grasp plan: grasp type " << toString(plan.type)
           << " (Feix et al. 2016, The GRASP Taxonomy of Human Grasp Types).\n";
    std::snprintf(line, sizeof line, "Object width %.1f mm, hand span %.1f mm; deepest segment %.2f mm%s%s.\n",
                  d.objectWidth * 1000, d.handSpan * 1000, d.maxPenetration * 1000,
                  d.deepestSegment.empty() ? "" : " (", d.deepestSegment.empty() ? "" : (d.deepestSegment + ")").c_str());
    header << line;
    for (const GoalCheck& g : d.goals) {
        std::snprintf(line, sizeof line, "  %s pad %.2f mm off the surface, facing it within %.0f deg, IK %.2f mm short of its pressed goal, %.2f mm inside; steady press %.2f mm, %.2f mm once released\n",
                      g.effector.c_str(), g.gap * 1000, g.misalignment * 180 / SimTK::Pi, g.reachShortfall * 1000,
                      g.commandedPress * 1000, g.steadyPress * 1000, g.releasedPress * 1000);
        header << line;
    }
    if (d.goals.size() == 2) {  // their Q is round-off: nothing resists a turn about the contact line
        header << "Force closure: " << describeAntipodal(d) << ".";
    } else {
        std::snprintf(line, sizeof line, "Grasp quality Q = %.3g (smallest singular value, unit normal forces).", d.quality);
        header << line;
    }
    return scenario::formatScenarioYaml(planned, header.str());
}

}  // namespace graspsim::planning
