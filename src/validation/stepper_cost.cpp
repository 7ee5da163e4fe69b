#include "graspsim/validation/stepper_cost.h"

#include "graspsim/simulation/grasp_experiment.h"
#include "graspsim/simulation/grasp_scene.h"
#include "graspsim/simulation/grasp_simulation.h"

#include "run_timing.h"

#include <algorithm>
#include <cstdio>

namespace graspsim::validation {

namespace {

// µs per evaluation of the contact element's force alone at `state` (realized through Velocity):
// best of five batches.
double timeContactForce(const simulation::GraspScene& scene, const SimTK::State& source, int realizations) {
    const contact::CompliantContactForce& contacts = scene.getCompliantContacts();
    SimTK::State state = source;
    scene.getSystem().realize(state, SimTK::Stage::Velocity);
    SimTK::Vector_<SimTK::SpatialVec> bodyForces(scene.getModel().getMatter().getNumBodies());
    SimTK::Vector_<SimTK::Vec3> particles;
    SimTK::Vector mobility(state.getNU());
    double best = 1e300;
    for (int batch = 0; batch < 5; ++batch) {
        const double start = readWallClock();
        for (int k = 0; k < realizations; ++k) {
            bodyForces.setToZero();
            mobility.setToZero();
            contacts.calcForceContribution(state, bodyForces, particles, mobility);
        }
        best = std::min(best, 1e6 * (readWallClock() - start) / realizations);
    }
    return best;
}

double perSecond(long count, double simTime) { return count >= 0 && simTime > 0 ? static_cast<double>(count) / simTime : -1; }

void fillCounts(const integration::IntegrationStatistics& s, double simTime, StepperCost& row) {
    row.stepsPerSimSecond = perSecond(s.steps, simTime);
    row.evaluationsPerSimSecond = perSecond(s.rhsEvaluations, simTime);
    row.jacobiansPerSimSecond = perSecond(s.jacobianEvaluations, simTime);
    row.factorizationsPerSimSecond = perSecond(s.linearSolverSetups, simTime);
    row.newtonPerSimSecond = perSecond(s.newtonIterations, simTime);
    row.restartsPerSimSecond = perSecond(s.restarts, simTime);
}

}  // namespace

StepperCost measureFullContactStepper(const scenario::Scenario& scenario, simulation::IntegratorChoice integrator,
                                      double duration, int realizations) {
    StepperCost row;
    row.scenario = scenario.name;
    row.run = integrator == simulation::IntegratorChoice::SimbodyCpodes ? "full, cpodes" : "full, " + simulation::toString(integrator);
    simulation::SimulationOptions options;
    options.duration = duration;
    options.integrator = integrator;
    double realizeUs = 0, contactUs = 0, observing = 0;
    const simulation::SampleObserver observe = [&](const simulation::GraspExperiment& experiment, const SimTK::State& state) {
        if (state.getTime() < duration - 1e-9) return;
        const simulation::GraspScene& scene = experiment.getScene();
        const double start = readWallClock();
        realizeUs = timeRealization(scene.getSystem(), state, realizations);
        contactUs = timeContactForce(scene, state, realizations);
        observing += readWallClock() - start;
    };
    const simulation::SimulationSummary s = simulation::runGraspSimulation(scenario, options, {}, observe).summary;
    const double wall = s.wallTime - observing;
    row.wallPerSimSecond = s.simTime > 0 ? wall / s.simTime : 0;
    fillCounts(s.integratorStatistics, s.simTime, row);
    if (s.steps <= 0) return row;
    const double steps = static_cast<double>(s.steps);
    const double evaluationsPerStep = static_cast<double>(s.integratorStatistics.rhsEvaluations) / steps;
    row.stepUs = 1e6 * wall / steps;
    row.dynamicsUs = evaluationsPerStep * realizeUs;
    row.contactUs = evaluationsPerStep * contactUs;
    const double linear = s.integratorStatistics.linearSolveSeconds;
    row.linearSolveUs = linear >= 0 ? 1e6 * linear / steps : -1;
    row.ikUs = s.ikUsPerStep;
    row.restUs = row.stepUs - row.dynamicsUs - std::max(row.linearSolveUs, 0.0) - row.ikUs;
    return row;
}

StepperCost measureHeldFullContact(const scenario::Scenario& scenario, simulation::IntegratorChoice integrator, double warmUp,
                                   double held) {
    StepperCost row;
    row.scenario = scenario.name;
    row.run = "full, " + simulation::toString(integrator) + ", held";
    simulation::SimulationOptions options;
    options.integrator = integrator;
    const double heldStart = scenario.simulation.settleTime + warmUp;
    options.duration = heldStart + held;
    double startWall = -1, startTime = 0, endWall = 0, endTime = 0;
    const simulation::SampleObserver observe = [&](const simulation::GraspExperiment&, const SimTK::State& state) {
        const double now = readWallClock();
        if (startWall < 0 && state.getTime() >= heldStart - 1e-9) {
            startWall = now;
            startTime = state.getTime();
        }
        endWall = now;
        endTime = state.getTime();
    };
    simulation::runGraspSimulation(scenario, options, {}, observe);
    if (startWall >= 0 && endTime > startTime) row.wallPerSimSecond = (endWall - startWall) / (endTime - startTime);
    return row;
}

namespace {

// A count or time, "-" where unknown.
std::string cell(double value, int width, int decimals) {
    char buffer[32];
    if (value < 0) {
        std::snprintf(buffer, sizeof buffer, "%*s", width, "-");
    } else {
        std::snprintf(buffer, sizeof buffer, "%*.*f", width, decimals, value);
    }
    return buffer;
}

}  // namespace

std::string formatStepperTable(const std::vector<StepperCost>& rows) {
    std::string text = "Full contact per stepper, the approximation and the floor, side by side:\n";
    char head[256];
    std::snprintf(head, sizeof head, "%-12s %-26s %9s %7s %7s %6s %6s %7s %8s | %7s %7s %7s %7s %6s %6s\n", "experiment", "run",
                  "wall/sim", "steps", "evals", "jac", "LU", "newton", "restarts", "step", "dynamic", "contact", "linear", "IK",
                  "rest");
    text += head;
    for (const StepperCost& r : rows) {
        char name[64];
        std::snprintf(name, sizeof name, "%-12s %-26s", r.scenario.c_str(), r.run.c_str());
        text += std::string(name) + cell(r.wallPerSimSecond, 10, 4) + cell(r.stepsPerSimSecond, 8, 0) +
                cell(r.evaluationsPerSimSecond, 8, 0) + cell(r.jacobiansPerSimSecond, 7, 0) +
                cell(r.factorizationsPerSimSecond, 7, 0) + cell(r.newtonPerSimSecond, 8, 0) + cell(r.restartsPerSimSecond, 9, 0) +
                " |" + cell(r.stepUs, 8, 0) + cell(r.dynamicsUs, 8, 0) + cell(r.contactUs, 8, 0) + cell(r.linearSolveUs, 8, 0) +
                cell(r.ikUs, 7, 1) + cell(r.restUs, 7, 0) + "\n";
    }
    return text + "(wall/sim: wall s per simulated s over the whole run (full: closing, contact and hold; held: the\n"
                  " grasp held, from settle_time + 1 s on, the phase MuJoCo's peer bench times; approx: the 20 s hold,\n"
                  " CPodes unless named; floor: its 20 s); then per simulated second: steps, dynamics evaluations, Jacobian builds, LU\n"
                  " factorizations, Newton iterations, integrator restarts; right of |, per step in µs: dynamics = evaluations\n"
                  " per step x one evaluation at the run's end (contact included), contact = the same for the contact force\n"
                  " alone, linear = the stepper's own clock for its matrix, LU and solves, IK, rest = step - dynamics -\n"
                  " linear - IK (output samples, events, the stepper); '-': not reported by that integrator or not\n"
                  " measured for that run)\n\n";
}

}  // namespace graspsim::validation
