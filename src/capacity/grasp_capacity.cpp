#include "graspsim/capacity/grasp_capacity.h"

#include "graspsim/capacity/load_direction.h"
#include "graspsim/capacity/overload.h"

#include "graspsim/capacity/settled_grasps.h"

#include "graspsim/error.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iterator>

namespace graspsim::capacity {

namespace {

constexpr double kGravity = 9.81;  // m/s^2, for the default rate only

GraspCapacity makeHeader(const simulation::SimulationOptions& options, const GraspCapacityRequest& request,
                         const scenario::Scenario& scenario, const char* method) {
    GraspCapacity c;
    c.directionName = request.directionName;
    c.direction = request.direction;
    c.torque = request.torque;
    c.method = method;
    c.contact = options.contact;
    if (options.contact == simulation::ContactModel::Compliant && scenario.friction.model != contact::FrictionModel::Regularized) {
        c.friction = scenario.friction.model;
    }
    if (options.contact == simulation::ContactModel::Compliant && scenario.contact.capsuleContact != contact::CapsuleContact::Deepest) {
        c.capsuleContact = scenario.contact.capsuleContact;
    }
    c.mode = options.mode;
    if (options.mode == simulation::SimulationMode::Approx) {
        const simulation::ApproxOptions approx = simulation::resolveApproxOptions(options.approx, scenario.approximation);
        c.realization = simulation::toString(approx.constraint) + " " + simulation::toString(approx.attach) + ", limits " +
                        grasp::toString(approx.limitModel) + ", release at " + simulation::toString(approx.releaseTrigger);
        if (approx.releaseGive) {  // the default's text stays as it was
            char give[48];
            std::snprintf(give, sizeof give, " (give %.3g mm)", 1e3 * *approx.releaseGive);
            c.realization += give;
        }
        if (approx.handBack != simulation::ApproxHandBack::Engaged) c.realization += ", hand back " + simulation::toString(approx.handBack);
        if (approx.releaseCreep && !*approx.releaseCreep) c.realization += ", creep watch off";
        if (approx.bushingGive != simulation::ApproxBushingGive::Stiff) c.realization += ", bushing give " + simulation::toString(approx.bushingGive);
    }
    c.start = findLoadStart(scenario);
    c.criteria = request.criteria;
    return c;
}

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

std::vector<GraspCapacityRequest> makeAllDirectionRequests() {
    std::vector<GraspCapacityRequest> requests;
    const std::vector<LoadDirection> axes = findAxisDirections();
    for (const bool torque : {false, true}) {
        for (const LoadDirection& d : axes) {
            if (torque && d.name[0] == '-') continue;
            GraspCapacityRequest r;
            r.direction = d.direction;
            r.directionName = d.name;
            r.torque = torque;
            requests.push_back(r);
        }
    }
    return requests;
}

double findDefaultRate(const scenario::Scenario& scenario, bool torque) {
    const double force = 2 * scenario.object.mass * kGravity;
    if (!torque) return force;
    double lever = 0;
    for (const auto& goal : scenario.goals) {
        const model::Vec3& p = goal.second;
        lever = std::max(lever, std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
    }
    return force * lever;
}

void checkLoadResistible(const scenario::Scenario& scenario, const GraspCapacityRequest& request,
                         const std::pair<std::string, std::string>& flags) {
    if (!request.torque || scenario.goals.size() != 2) return;
    const auto first = scenario.goals.begin(), second = std::next(first);
    const model::Transform X_GO = scenario.object.findPose();
    const model::Vec3 a = X_GO.xformFrameVecToBase(first->second), b = X_GO.xformFrameVecToBase(second->second);
    const SimTK::Vec3 line(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
    if (!(line.norm() > 0)) return;
    const double angle = std::acos(std::min(1.0, std::abs(~SimTK::Vec3(request.direction) * line) / line.norm()));
    if (angle > kPinchAxisTolerance) return;
    char degrees[32];
    std::snprintf(degrees, sizeof degrees, "%.3g", angle * 180 / SimTK::Pi);
    throw InputError(flags.first + " " + request.directionName + " " + flags.second + ": the axis is " + degrees + " deg from the line through the goals " +
                     first->first + " and " + second->first + "; two point contacts cannot resist a torque about it (no torsional "
                     "friction), so there is no capacity to measure; choose an axis more than 5 deg away");
}

double findLoadStart(const scenario::Scenario& scenario) { return scenario.simulation.settleTime + kLoadStartDelay; }

LoadedRunFactory makeGraspRuns(const scenario::Scenario& scenario, const simulation::SimulationOptions& options) {
    auto grasps = std::make_shared<SettledGrasps>(scenario, options);
    return [grasps](const simulation::LoadRampSpec& load) { return grasps->makeRun(load); };
}

GraspCapacity measureGraspCapacityRamp(SettledGrasps& grasps, const GraspCapacityRequest& request) {
    const scenario::Scenario& scenario = grasps.getScenario();
    const simulation::SimulationOptions& options = grasps.getOptions();
    const auto clock = std::chrono::steady_clock::now();
    GraspCapacity c = makeHeader(options, request, scenario, "ramp");
    c.rate = request.rate > 0 ? request.rate : findDefaultRate(scenario, request.torque);
    RampProtocol protocol;
    protocol.direction = request.direction;
    protocol.torque = request.torque;
    protocol.start = c.start;
    protocol.rate = c.rate;
    protocol.initial = request.initialLoad;
    protocol.maxDuration = request.maxRampDuration;
    protocol.sampleInterval = request.sampleInterval;
    protocol.criteria = request.criteria;
    c.trace = runRamp(makeGraspRuns(grasps), protocol);
    c.wallTime = secondsSince(clock);
    return c;
}

GraspCapacity measureGraspCapacityBisection(SettledGrasps& grasps, const GraspCapacityRequest& request, double guess, double hold) {
    const scenario::Scenario& scenario = grasps.getScenario();
    const simulation::SimulationOptions& options = grasps.getOptions();
    const auto clock = std::chrono::steady_clock::now();
    GraspCapacity c = makeHeader(options, request, scenario, "bisection");
    BisectionProtocol protocol;
    protocol.direction = request.direction;
    protocol.torque = request.torque;
    protocol.start = c.start;
    protocol.hold = hold;
    protocol.high = guess;
    c.hold = hold;
    protocol.tolerance = 0.02;
    protocol.sampleInterval = request.sampleInterval;
    protocol.criteria = request.criteria;
    c.bisection = runBisection(makeGraspRuns(grasps), protocol);
    c.wallTime = secondsSince(clock);
    return c;
}

GraspCapacity measureGraspCapacityConstant(SettledGrasps& grasps, const GraspCapacityRequest& request, double load, double hold) {
    const scenario::Scenario& scenario = grasps.getScenario();
    const simulation::SimulationOptions& options = grasps.getOptions();
    const auto clock = std::chrono::steady_clock::now();
    GraspCapacity c = makeHeader(options, request, scenario, "constant");
    c.load = load;
    c.hold = hold;
    OverloadProtocol protocol;
    protocol.direction = request.direction;
    protocol.torque = request.torque;
    protocol.start = c.start;
    protocol.load = load;
    protocol.hold = hold;
    protocol.criteria = request.criteria;
    c.trace = runOverload(makeGraspRuns(grasps), protocol);
    c.wallTime = secondsSince(clock);
    return c;
}

GraspCapacity measureGraspCapacityRamp(const scenario::Scenario& scenario, const simulation::SimulationOptions& options,
                                       const GraspCapacityRequest& request) {
    SettledGrasps grasps(scenario, options);
    return measureGraspCapacityRamp(grasps, request);
}

GraspCapacity measureGraspCapacityBisection(const scenario::Scenario& scenario, const simulation::SimulationOptions& options,
                                            const GraspCapacityRequest& request, double guess, double hold) {
    SettledGrasps grasps(scenario, options);
    return measureGraspCapacityBisection(grasps, request, guess, hold);
}

GraspCapacity measureGraspCapacityConstant(const scenario::Scenario& scenario, const simulation::SimulationOptions& options,
                                           const GraspCapacityRequest& request, double load, double hold) {
    SettledGrasps grasps(scenario, options);
    return measureGraspCapacityConstant(grasps, request, load, hold);
}

}  // namespace graspsim::capacity
