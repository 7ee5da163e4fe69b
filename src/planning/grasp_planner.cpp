#include "graspsim/planning/grasp_planner.h"

#include "grasp_objective.h"
#include "object_extents.h"

#include "graspsim/anthropometry/units.h"
#include "graspsim/contact/surface_point.h"
#include "graspsim/model/body_model.h"
#include "graspsim/planning/goal_reach.h"
#include "graspsim/planning/grasp_template.h"
#include "graspsim/planning/lateral_pinch.h"
#include "graspsim/planning/plan_rounding.h"
#include "graspsim/system/simtk_conversion.h"

#include <nlopt.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace graspsim::planning {

namespace {

std::string formatMm(double metres) {
    std::ostringstream out;
    out.precision(3);
    out << metres * 1000;
    return out.str() + " mm";
}

// Rounds to a multiple of `step`, so that written scenarios read as hand-written ones. The
// product carries float noise (1805 * 1e-4 = 0.18050000000000002), which finishAsWritten takes
// out of the finished plan. Not here: the search's re-planning rounds hang on these last bits
// (rounded exactly here, the shipped ball tripod is planned into another pose), and the plans
// stay what they were.
double roundTo(double value, double step) { return std::round(value / step) * step; }

// Rounds joint angles to 0.1 deg and the object's position to 0.1 mm and its orientation to
// 0.1 deg (as body-fixed X-Y-Z angles, the scenario's form).
void roundPlan(GraspPlan& plan) {
    const double degree = SimTK::Pi / 180;
    for (auto& [joint, angle] : plan.jointAngles) angle = roundTo(angle / degree, 0.1) * degree;
    SimTK::Vec3 xyz = plan.X_GO.R().convertRotationToBodyFixedXYZ();
    for (int i = 0; i < 3; ++i) xyz[i] = roundTo(xyz[i] / degree, 0.1) * degree;
    const SimTK::Rotation R(SimTK::BodyRotationSequence, xyz[0], SimTK::XAxis, xyz[1], SimTK::YAxis, xyz[2],
                            SimTK::ZAxis);
    SimTK::Vec3 p = plan.X_GO.p();
    for (int i = 0; i < 3; ++i) p[i] = roundTo(p[i], 1e-4);
    plan.X_GO = SimTK::Transform(R, p);
}

void checkFits(const GraspObjective& objective, GraspType type) {
    const double width = objective.getObjectWidth(), span = objective.getHandSpan();
    if (width > span) {
        throw NoGraspError("no " + toString(type) + " grasp: object width " + formatMm(width) +
                           " exceeds the hand's " + objective.getSpanName() + " span " + formatMm(span));
    }
}

// BOBYQA from the template's start; run twice, the second from the first's optimum, because
// the first trust region often ends early once the penetration penalties switch off.
int optimize(GraspObjective& objective, std::vector<double>& x) {
    int evaluations = 0;
    for (int round = 0; round < 2; ++round) {
        nlopt::opt opt(nlopt::LN_BOBYQA, static_cast<unsigned>(x.size()));
        opt.set_lower_bounds(objective.getLowerBounds());
        opt.set_upper_bounds(objective.getUpperBounds());
        opt.set_min_objective(
            [](unsigned, const double* v, double*, void* data) {
                return static_cast<GraspObjective*>(data)->evaluate(v);
            },
            &objective);
        opt.set_initial_step(objective.getInitialSteps());
        opt.set_maxeval(6000);
        opt.set_xtol_abs(1e-7);
        opt.set_ftol_abs(1e-9);
        double cost = 0;
        try {
            opt.optimize(x, cost);
        } catch (const nlopt::roundoff_limited&) {
            // the best point so far is in x: good enough to be checked
        }
        evaluations += opt.get_numevals();
    }
    return evaluations;
}

// The plan at the optimizer's x as a person would write it, with its checks' numbers.
GraspPlan finishPlan(const GraspRequest& request, GraspObjective& objective, const std::vector<double>& x) {
    GraspPlan plan = objective.makePlan(x.data());
    plan.kp = findGraspTemplate(request.type).kp;
    plan.pressDepth = request.pressDepth;
    roundPlan(plan);
    plan.goals = objective.findGoals(plan.jointAngles, plan.X_GO);
    plan.diagnostics = calcPlanDiagnostics(request, plan);
    plan.diagnostics.cost = objective.evaluate(x.data());
    return plan;
}

// Rounds of re-planning for fingers that cannot press their goals (the reach test), and the least
// gap a pad is asked for (m): at 0 the rounded plan could start with the pad inside the object.
constexpr int kReachRounds = 4;
constexpr double kLeastTargetGap = 0.0002;

// A finger short of its pressed goal by d needs to travel d less: its pad is aimed d nearer the
// surface and the plan is optimized again from where it stands. Returns whether any gap changed.
bool aimShortFingersNearer(const PlanDiagnostics& d, const PlanTolerances& tolerances, GraspObjective& objective) {
    bool changed = false;
    for (std::size_t i = 0; i < d.goals.size(); ++i) {
        const GoalCheck& g = d.goals[i];
        const double gap = objective.getTargetGap(i);
        const double missing = std::max(g.reachShortfall - tolerances.maxReachShortfall + kLeastTargetGap,
                                        tolerances.minCommandedPress - g.commandedPress + kLeastTargetGap);
        if (missing <= kLeastTargetGap || gap <= kLeastTargetGap) continue;
        objective.setTargetGap(i, std::max(kLeastTargetGap, gap - missing));
        changed = true;
    }
    return changed;
}

bool isReachable(const PlanDiagnostics& d, const PlanTolerances& tolerances) {
    for (const GoalCheck& g : d.goals) {
        if (g.reachShortfall > tolerances.maxReachShortfall || g.commandedPress < tolerances.minCommandedPress) return false;
    }
    return true;
}

}  // namespace

double findPlannedPressDepth(const scenario::Scenario& scenario) {
    // A goal pressed past half the object's thickness would pass its centre (the reader refuses
    // it): a thin object (a card in a lateral pinch) is pressed half that deep.
    const double halfThickness = scenario.object.findHalfThickness(), press = scenario.controller.pressDepth;
    return press < halfThickness ? press : roundToTenthMillimetre(halfThickness / 2);
}

GraspRequest makeGraspRequest(const scenario::Scenario& scenario, GraspType type) {
    const model::ModelDescription object = scenario::buildObjectModel(scenario.object);
    const model::Geometry& geometry = object.bodies.front().geometry.front();
    GraspRequest request;
    request.bodyOptions = scenario.bodyOptions;
    request.shape = contact::ContactShape::fromGeometry(geometry);
    request.X_OS = contact::findGeometryPose(geometry);
    request.type = type;
    request.gravity = system::toSimTKVec3(scenario.world.gravity);
    request.pressDepth = findPlannedPressDepth(scenario);
    request.mass = scenario.object.mass;
    return request;
}

namespace {

// The request with the plan's added end-effectors in its body model.
GraspRequest withSegmentPoints(GraspRequest request, const std::vector<model::SegmentPoint>& points) {
    for (const model::SegmentPoint& point : points) {
        auto& own = request.bodyOptions.segmentPoints;
        const bool present = std::any_of(own.begin(), own.end(), [&](const auto& p) { return p.name == point.name; });
        if (!present) own.push_back(point);
    }
    return request;
}

}  // namespace

namespace {

// Optimizes from x, then re-plans fingers that cannot press their goals (the reach test).
GraspPlan optimizeReachable(const GraspRequest& request, const PlanTolerances& tolerances, GraspObjective& objective,
                            std::vector<double>& x, int& evaluations) {
    evaluations += optimize(objective, x);
    GraspPlan plan = finishPlan(request, objective, x);
    for (int round = 0; round < kReachRounds && !isReachable(plan.diagnostics, tolerances); ++round) {
        if (!aimShortFingersNearer(plan.diagnostics, tolerances, objective)) break;
        evaluations += optimize(objective, x);
        plan = finishPlan(request, objective, x);
    }
    return plan;
}

// A plan of a shape with edges (a box, a convex mesh) that fails a check is made again from the
// optimum of the shape's smooth stand-in, the ellipsoid of its extents (object_extents.h),
// optimized from the same start; kept, with its objective and variables, if it passes every check.
// A plan that passes stays as it was (the shipped key-lateral.yaml is such a box).
//
// Why: the surface normal jumps at an edge, and a segment crossing one is pushed out through one
// face or the other, so the cost has creases along the edges that BOBYQA's quadratic models do
// not see. A start that must turn the object far meets them: the lateral template's thumb pad and
// index side sit side by side (the line between them 77 deg off the directions they face), so a
// flat object starts across both digits, and its grasp lies about 100 deg away. The 70 x 140 x
// 8 mm box stopped with both pads on one of its edges (cost 665, the index's side 8.3 mm off),
// where the ellipsoid of its half-lengths turns through to a pinch (cost 3.5); from that pinch the
// box's own optimum costs 5.2 and holds.
void replanThroughSmoothStandIn(const GraspRequest& request, const PlanTolerances& tolerances,
                                const GraspTemplate& graspTemplate, GraspObjective& objective,
                                std::vector<double>& x, GraspPlan& plan, int& evaluations) {
    if (!hasEdges(request.shape) || findFailedCheck(plan.diagnostics, tolerances).empty()) return;
    const SmoothStandIn standIn = findSmoothStandIn(request.shape);
    GraspRequest smooth = request;
    smooth.shape = standIn.shape;
    smooth.X_OS = request.X_OS * standIn.X_SE;
    GraspObjective smoothObjective(smooth, graspTemplate);
    std::vector<double> start = smoothObjective.getStart();
    evaluations += optimize(smoothObjective, start);
    const GraspPlan smoothPlan = smoothObjective.makePlan(start.data());

    GraspObjective fresh(request, graspTemplate);  // the first search's re-aimed pad gaps left behind
    std::vector<double> y = fresh.findVariables(smoothPlan.jointAngles, smoothPlan.X_GO);
    const GraspPlan replanned = optimizeReachable(request, tolerances, fresh, y, evaluations);
    if (!findFailedCheck(replanned.diagnostics, tolerances).empty()) return;
    plan = replanned;
    x = y;
    objective = fresh;
}

// The press depth (m) that leaves every goal finger at least half the requested press while the
// object is held (its steady press, against the passive springs): the requested one raised by
// what the weakest finger lacks, rounded up to 0.1 mm, at most by half, and never past a quarter
// of the object's width (a thin object's press, findPlannedPressDepth). The springs take the
// same millimetres from a finger whatever the press, so a deeper press adds to every finger's
// press alike. Not for the release: the prediction leaves out friction, which carries the weight
// of a small ball in a tripod, and would press such grasps deeper for nothing.
double findPressForWeakestFinger(const PlanDiagnostics& d, double requested, double objectWidth) {
    double weakest = SimTK::Infinity;
    for (const GoalCheck& g : d.goals) weakest = std::min(weakest, g.steadyPress);
    const double missing = requested / 2 - weakest;
    if (!(missing > 0)) return requested;
    const double raised = fromTenthMillimetres(std::ceil((requested + missing) / 1e-4 - 1e-6));
    const double thin = fromTenthMillimetres(std::floor(objectWidth / 4 / 1e-4 + 1e-6));
    const double press = std::min({raised, 1.5 * requested, thin});
    return press > requested + 1e-9 ? press : requested;
}

// The finished plan as its scenario file reads it back: each rounded number the exact double of
// its written decimal (plan_rounding.h), and the checks' numbers for those.
void finishAsWritten(const GraspRequest& request, GraspPlan& plan) {
    snapToWrittenDecimals(plan);
    GraspRequest written = request;
    written.bodyOptions.segmentPoints = plan.segmentPoints;  // the plan's press depth is taken from the plan
    const PlanDiagnostics search = plan.diagnostics;
    plan.diagnostics = calcPlanDiagnostics(written, plan);
    plan.diagnostics.evaluations = search.evaluations;
    plan.diagnostics.cost = search.cost;
}

// The least a goal finger of `d` is predicted to press once the object is released (m).
double findWeakestReleasedPress(const PlanDiagnostics& d) {
    double weakest = SimTK::Infinity;
    for (const GoalCheck& g : d.goals) weakest = std::min(weakest, g.releasedPress);
    return weakest;
}

}  // namespace

GraspPlan planGrasp(const GraspRequest& givenRequest, const PlanTolerances& tolerances) {
    givenRequest.shape.validate("the object");
    GraspRequest request = givenRequest;
    if (request.type == GraspType::Lateral) request.bodyOptions = addIndexRadialPoint(request.bodyOptions);
    const GraspTemplate graspTemplate = findGraspTemplate(request.type);
    GraspObjective objective(request, graspTemplate);
    checkFits(objective, request.type);

    std::vector<double> x = objective.getStart();
    int evaluations = 0;
    GraspPlan plan = optimizeReachable(request, tolerances, objective, x, evaluations);
    replanThroughSmoothStandIn(request, tolerances, graspTemplate, objective, x, plan, evaluations);
    if (plan.goalEffectors.size() >= 3 && findWeakestReleasedPress(plan.diagnostics) < request.pressDepth / 2) {
        // A finger the release would leave with less than half the press: planned again, from
        // the template's start, with the release term in the cost (from the first plan's
        // optimum BOBYQA stays in its basin: the 1.90 m man's sphere kept three fingers that let
        // go), and kept if the new plan passes every check.
        objective.setReleaseBalanced(true);
        std::vector<double> balanced = objective.getStart();
        GraspPlan repaired = optimizeReachable(request, tolerances, objective, balanced, evaluations);
        if (findFailedCheck(repaired.diagnostics, tolerances).empty()) {
            plan = repaired;
            x = balanced;
        } else {
            objective.setReleaseBalanced(false);
        }
    }
    const double press = findPressForWeakestFinger(plan.diagnostics, request.pressDepth, objective.getObjectWidth());
    if (press > request.pressDepth) {
        // Only the controller presses deeper: the pose stays, and so does the press the plan
        // was made for if the deeper one would fail a check (a goal out of the IK's reach).
        GraspRequest deeper = request;
        deeper.pressDepth = press;
        objective.setPressDepth(press);
        GraspPlan pressed = finishPlan(deeper, objective, x);
        if (findFailedCheck(pressed.diagnostics, tolerances).empty()) {
            request = deeper;
            plan = pressed;
        } else {
            objective.setPressDepth(request.pressDepth);
        }
    }
    plan.kp = graspTemplate.kp;
    plan.capsuleContact = graspTemplate.capsuleContact;
    plan.pressDepth = request.pressDepth;
    plan.segmentPoints = request.bodyOptions.segmentPoints;
    plan.diagnostics.evaluations = evaluations;
    finishAsWritten(request, plan);
    const std::string failed = findFailedCheck(plan.diagnostics, tolerances);
    if (!failed.empty()) {
        throw NoGraspError("no " + toString(request.type) + " grasp found: " + failed + " (object width " +
                           formatMm(objective.getObjectWidth()) + ", the hand's " + objective.getSpanName() + " span " +
                           formatMm(objective.getHandSpan()) + ")");
    }
    return plan;
}

std::string findFailedCheck(const PlanDiagnostics& d, const PlanTolerances& tolerances) {
    for (const GoalCheck& goal : d.goals) {
        if (goal.gap < tolerances.minGap || goal.gap > tolerances.maxGap) {
            return "the " + goal.effector + " pad ends " + formatMm(goal.gap) + " from the surface (accepted: " +
                   formatMm(tolerances.minGap) + " to " + formatMm(tolerances.maxGap) + ")";
        }
        if (goal.misalignment > tolerances.maxMisalignment) {
            std::ostringstream out;
            out << "the " << goal.effector << " pad faces " << std::lround(goal.misalignment * 180 / SimTK::Pi)
                << " deg away from the surface (accepted: "
                << std::lround(tolerances.maxMisalignment * 180 / SimTK::Pi) << " deg)";
            return out.str();
        }
    }
    for (const GoalCheck& goal : d.goals) {
        if (goal.reachShortfall > tolerances.maxReachShortfall) {
            return "the " + goal.effector + " cannot press its goal: the controller's IK ends " +
                   formatMm(goal.reachShortfall) + " from it (accepted: " + formatMm(tolerances.maxReachShortfall) + ")";
        }
        if (goal.commandedPress < tolerances.minCommandedPress) {
            char depth[64];
            std::snprintf(depth, sizeof depth, "%.2f mm inside the object (needed: %.2f mm)", goal.commandedPress * 1000,
                          tolerances.minCommandedPress * 1000);
            return "the " + goal.effector + " cannot press its goal: the controller's IK puts its pad " + depth;
        }
    }
    if (d.maxPenetration > tolerances.maxPenetration) {
        return "segment '" + d.deepestSegment + "' is " + formatMm(d.maxPenetration) + " inside the object (accepted: " +
               formatMm(tolerances.maxPenetration) + ")";
    }
    if (d.goals.size() == 2 && !d.antipodal) {
        return "the goal contacts do not hold the object (not antipodal: the line between them leaves a friction cone)";
    }
    if (d.goals.size() > 2 && !(d.quality > 1e-6)) {
        std::ostringstream out;
        out << "the goal contacts do not hold the object (grasp quality Q = " << d.quality << ", not > 0)";
        return out.str();
    }
    return "";
}

std::string describeAntipodal(const PlanDiagnostics& d) {
    char text[128];
    std::snprintf(text, sizeof text, "%santipodal (contact line %.1f deg off the normals, friction cone %.1f deg)",
                  d.antipodal ? "" : "not ", d.antipodalAngle / anthropometry::fromDegrees(1.0),
                  d.frictionConeAngle / anthropometry::fromDegrees(1.0));
    return text;
}

PlanDiagnostics calcPlanDiagnostics(const GraspRequest& givenRequest, const GraspPlan& plan) {
    GraspTemplate graspTemplate = findGraspTemplate(givenRequest.type);
    graspTemplate.goalEffectors = plan.goalEffectors;
    GraspRequest request = withSegmentPoints(givenRequest, plan.segmentPoints);
    if (plan.pressDepth > 0) request.pressDepth = plan.pressDepth;
    const GraspObjective objective(request, graspTemplate);
    PlanDiagnostics d = objective.calcDiagnostics(plan.jointAngles, plan.X_GO);
    // The goals as the controller presses them at t = 0 (simulation/grasp_scene.cpp).
    std::vector<PressedGoal> pressed;
    for (const std::string& effector : plan.goalEffectors) {
        const SimTK::Vec3& p_OP = plan.goals.at(effector);
        const SimTK::Vec3 n_O = request.X_OS.R() * contact::findSurfacePoint(request.shape, ~request.X_OS * p_OP).n_S;
        pressed.push_back({effector, plan.X_GO * (p_OP - request.pressDepth * n_O)});
    }
    const GoalReachResult reach = calcGoalReach(request.bodyOptions, plan.jointAngles, pressed, plan.kp);
    const SimTK::Transform X_GS = plan.X_GO * request.X_OS;
    for (std::size_t i = 0; i < d.goals.size() && i < reach.goals.size(); ++i) {
        d.goals[i].reachShortfall = reach.goals[i].shortfall;
        d.goals[i].commandedPress = -contact::findSurfacePoint(request.shape, ~X_GS * reach.goals[i].p_GE).distance;
        d.goals[i].steadyPress = objective.calcEffectorBodyDepth(reach.steadyAngles, plan.X_GO, d.goals[i].effector);
    }
    const std::vector<double> released = objective.calcReleasedPress(plan.jointAngles, plan.X_GO);
    for (std::size_t i = 0; i < d.goals.size() && i < released.size(); ++i) d.goals[i].releasedPress = released[i];
    return d;
}

}  // namespace graspsim::planning
