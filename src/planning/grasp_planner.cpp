#include "graspsim/planning/grasp_planner.h"

#include "grasp_objective.h"

#include "graspsim/model/body_model.h"
#include "graspsim/planning/grasp_template.h"
#include "graspsim/planning/lateral_pinch.h"

#include <nlopt.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace graspsim::planning {

namespace {

std::string formatMm(double metres) {
    std::ostringstream out;
    out.precision(3);
    out << metres * 1000;
    return out.str() + " mm";
}

// Rounds to a multiple of `step`, so that written scenarios read as hand-written ones.
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

}  // namespace

GraspRequest makeGraspRequest(const scenario::Scenario& scenario, GraspType type) {
    const model::ModelDescription object = scenario::buildObjectModel(scenario.object);
    const model::Geometry& geometry = object.bodies.front().geometry.front();
    GraspRequest request;
    request.bodyOptions = scenario.bodyOptions;
    request.shape = contact::ContactShape::fromGeometry(geometry);
    request.X_OS = contact::findGeometryPose(geometry);
    request.type = type;
    request.gravity = SimTK::Vec3(scenario.world.gravity[0], scenario.world.gravity[1], scenario.world.gravity[2]);
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

GraspPlan planGrasp(const GraspRequest& givenRequest, const PlanTolerances& tolerances) {
    givenRequest.shape.validate("the object");
    GraspRequest request = givenRequest;
    if (request.type == GraspType::Lateral) request.bodyOptions = addIndexRadialPoint(request.bodyOptions);
    const GraspTemplate graspTemplate = findGraspTemplate(request.type);
    GraspObjective objective(request, graspTemplate);
    checkFits(objective, request.type);

    std::vector<double> x = objective.getStart();
    const int evaluations = optimize(objective, x);

    GraspPlan plan = objective.makePlan(x.data());
    roundPlan(plan);
    plan.goals = objective.findGoals(plan.jointAngles, plan.X_GO);
    plan.kp = graspTemplate.kp;
    plan.segmentPoints = request.bodyOptions.segmentPoints;
    plan.diagnostics = calcPlanDiagnostics(request, plan);
    plan.diagnostics.evaluations = evaluations;
    plan.diagnostics.cost = objective.evaluate(x.data());
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

PlanDiagnostics calcPlanDiagnostics(const GraspRequest& request, const GraspPlan& plan) {
    GraspTemplate graspTemplate = findGraspTemplate(request.type);
    graspTemplate.goalEffectors = plan.goalEffectors;
    const GraspObjective objective(withSegmentPoints(request, plan.segmentPoints), graspTemplate);
    return objective.calcDiagnostics(plan.jointAngles, plan.X_GO);
}

}  // namespace graspsim::planning
