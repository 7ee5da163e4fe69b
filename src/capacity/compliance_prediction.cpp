#include "graspsim/capacity/compliance_prediction.h"

#include "graspsim/error.h"
#include "graspsim/integration/simbody_stepper.h"
#include "graspsim/simulation/finger_compliance.h"
#include "graspsim/simulation/grasp_experiment.h"
#include "graspsim/system/simtk_conversion.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Eigen/Dense>

namespace graspsim::capacity {

namespace {

SimTK::State runToLoadStart(simulation::GraspExperiment& experiment, const scenario::Scenario& scenario,
                            integration::Stepper& stepper) {
    const simulation::GraspScene& scene = experiment.getScene();
    stepper.initialize(experiment.makeInitialState());
    stepper.stepTo(scene.getReleaseTime());
    SimTK::State released = stepper.getState();
    scene.releaseObject(released);
    stepper.initialize(released);
    stepper.stepTo(findLoadStart(scenario));
    return stepper.getState();
}

Eigen::Matrix<double, 6, 1> toLoadDirection(const GraspCapacityRequest& r) {
    Eigen::Matrix<double, 6, 1> d = Eigen::Matrix<double, 6, 1>::Zero();
    d.segment<3>(r.torque ? 0 : 3) = system::toEigenVector(SimTK::Vec3(r.direction));
    return d;
}

std::string formatLoad(double value, const char* unit) {
    if (!std::isfinite(value)) return "none";
    char text[32];
    std::snprintf(text, sizeof text, "%.4g%s", value, unit);
    return text;
}

grasp::CompliantRamp runCreepRamp(const scenario::Scenario& scenario, LoadStartGrasp start, const GraspCapacityRequest& r,
                                  const CompliancePredictionSettings& settings) {
    for (grasp::CompliantContact& c : start.contacts) c.tangentialStiffness = settings.creepTangentialStiffnessRatio * c.normalStiffness;
    grasp::CompliantRampOptions o;
    o.rate = r.rate > 0 ? r.rate : findDefaultRate(scenario, r.torque);
    o.slipDistance = r.criteria.slip;
    o.maxLoad = o.rate * r.maxRampDuration;
    return grasp::runCompliantRamp(start.contacts, start.p_GO, toLoadDirection(r), scenario.contact, o);
}

}  // namespace

simulation::FingerComplianceSettings toFingerSettings(const CompliancePredictionSettings& settings) {
    simulation::FingerComplianceSettings f;
    f.tangentialStiffnessRatio = settings.tangentialStiffnessRatio;
    f.ikFollowsNullSpace = settings.ikFollowsNullSpace;
    f.tangentialByNormalForce = settings.tangentialByNormalForce;
    f.rolling = settings.rolling;
    return f;
}

LoadStartGrasp findLoadStartGrasp(const scenario::Scenario& scenario, simulation::SimulationOptions options,
                                  const CompliancePredictionSettings& settings) {
    options.mode = simulation::SimulationMode::Full;
    options.contact = simulation::ContactModel::Compliant;
    simulation::GraspExperiment experiment(scenario, options);
    const double accuracy = options.accuracy > 0 ? options.accuracy : scenario.simulation.accuracy;
    integration::SimbodyCpodesStepper stepper(experiment.getScene().getSystem(), accuracy);
    const SimTK::State state = runToLoadStart(experiment, scenario, stepper);
    const simulation::GraspScene& scene = experiment.getScene();
    LoadStartGrasp start;
    scene.getSystem().realize(state, SimTK::Stage::Velocity);
    const std::vector<contact::ContactReport> reports = scene.findContactReports(state);
    start.contacts = simulation::makeFingerCompliance(scene).findCompliantContacts(state, reports, toFingerSettings(settings));
    for (const contact::ContactReport& r : reports) {
        if (r.normalForce > 0 && r.depth > 0) start.bodies.push_back(r.bodyA);
    }
    if (start.contacts.empty()) throw NumericalError("compliance prediction: no contact at the load's start");
    start.p_GO = system::toEigenVector(scene.getObject().findMassCenterLocationInGround(state));
    const SimTK::Transform& X_GO = scene.getObject().getBodyTransform(state);
    for (const SimTK::Vec3& p_OT : scene.getSurfaceGoals()) start.goals_G.push_back(system::toEigenVector(X_GO * p_OT));
    return start;
}

std::vector<CompliancePrediction> predictGraspCapacities(const scenario::Scenario& scenario,
                                                         const simulation::SimulationOptions& options,
                                                         const std::vector<GraspCapacityRequest>& requests,
                                                         const CompliancePredictionSettings& settings) {
    const LoadStartGrasp start = findLoadStartGrasp(scenario, options, settings);
    std::vector<CompliancePrediction> predictions;
    for (const GraspCapacityRequest& r : requests) {
        grasp::CompliantCapacityOptions o;
        o.slipDistance = r.criteria.slip;
        o.slipPoints_G = start.goals_G;  // where the ramp measures the slip
        CompliancePrediction p{r, {}, {}, {}};
        o.mu = scenario.contact.dynamicFriction;
        p.dynamicFriction = grasp::calcCompliantCapacity(start.contacts, start.p_GO, toLoadDirection(r), o);
        o.mu = scenario.contact.staticFriction;  // breaks loose at mu_s, slides at mu_d
        o.kineticMu = std::min(scenario.contact.dynamicFriction, o.mu);
        p.staticFriction = grasp::calcCompliantCapacity(start.contacts, start.p_GO, toLoadDirection(r), o);
        p.creep = runCreepRamp(scenario, start, r, settings);
        predictions.push_back(p);
    }
    return predictions;
}

std::string describePrediction(const CompliancePrediction& p) {
    const char* unit = p.request.torque ? " N m" : " N";
    const auto describe = [&](const grasp::CompliantCapacity& c) {
        int opened = 0, slid = 0;
        for (const grasp::CompliantCapacityEvent& e : c.events) {
            opened += e.state == grasp::CompliantContactState::Open;
            slid += e.state == grasp::CompliantContactState::Sliding;
        }
        std::string events;
        for (const grasp::CompliantCapacityEvent& e : c.events) {
            if (e.load > std::min(c.ultimate, 1e3)) break;
            events += std::string(events.empty() ? "" : " ") + "c" + std::to_string(e.contact) +
                      (e.state == grasp::CompliantContactState::Open ? " opens " : " slides ") + formatLoad(e.load, "");
        }
        return "first slip " + formatLoad(c.firstSlip, unit) + ", onset " + formatLoad(c.onset, unit) + ", ultimate " +
               formatLoad(c.ultimate, unit) + " (" + std::to_string(slid) + " slid, " + std::to_string(opened) + " opened: " +
               events + ")";
    };
    return p.request.directionName + (p.request.torque ? " torque" : " force") + " (compliance model): mu_d: " +
           describe(p.dynamicFriction) + "; mu_s (sliding at mu_d): " + describe(p.staticFriction) + "; creep ramp: " + describe(p.creep.capacity);
}

}  // namespace graspsim::capacity
