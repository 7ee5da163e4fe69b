#include "graspsim/capacity/compliance_prediction.h"

#include "graspsim/error.h"
#include "graspsim/integration/simbody_stepper.h"
#include "graspsim/simulation/grasp_experiment.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace graspsim::capacity {

namespace {

Eigen::Vector3d toEigen(const SimTK::Vec3& v) { return {v[0], v[1], v[2]}; }

// Each finger joint's stiffness K_q (N m/rad), by mobilizer: PD gain + passive spring, + the limit
// stop's stiffness past a limit (the stop then pushes back at that rate).
std::map<SimTK::MobilizedBodyIndex, double> findFingerJointStiffness(const simulation::GraspScene& scene,
                                                                     const SimTK::State& state) {
    const std::vector<SimTK::MobilizedBodyIndex>& fingers = scene.getFingerMobilizers();
    const SimTK::SimbodyMatterSubsystem& matter = scene.getModel().getMatter();
    std::map<SimTK::MobilizedBodyIndex, double> stiffness;
    for (const system::JointImpedance& j : scene.findJointImpedances()) {
        if (std::find(fingers.begin(), fingers.end(), j.mobod) == fingers.end()) continue;
        double k = j.stiffness;
        if (!j.stop.isEmptyHandle()) {
            const double q = matter.getMobilizedBody(j.mobod).getOneQ(state, 0);
            if (q < j.stop.getLowerBound(state) || q > j.stop.getUpperBound(state)) k += j.stop.getStiffness(state);
        }
        stiffness[j.mobod] = k;
    }
    return stiffness;
}

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
    d.segment<3>(r.torque ? 0 : 3) = toEigen(SimTK::Vec3(r.direction));
    return d;
}

std::string formatLoad(double value, const char* unit) {
    if (!std::isfinite(value)) return "none";
    char text[32];
    std::snprintf(text, sizeof text, "%.4g%s", value, unit);
    return text;
}

}  // namespace

Eigen::Matrix3d calcFingerCompliance(const simulation::GraspScene& scene, const SimTK::State& state,
                                     const std::string& body, const SimTK::Vec3& p_G) {
    scene.getSystem().realize(state, SimTK::Stage::Position);
    const SimTK::SimbodyMatterSubsystem& matter = scene.getModel().getMatter();
    const SimTK::MobilizedBody& segment = scene.getModel().getMobilizedBody(body);
    SimTK::Matrix J;
    matter.calcStationJacobian(state, segment.getMobilizedBodyIndex(), segment.findStationAtGroundPoint(state, p_G), J);
    Eigen::Matrix3d compliance = Eigen::Matrix3d::Zero();
    for (const auto& [mobod, k] : findFingerJointStiffness(scene, state)) {
        const int u = int(matter.getMobilizedBody(mobod).getFirstUIndex(state));
        const Eigen::Vector3d column(J(0, u), J(1, u), J(2, u));
        if (k > 0) compliance += column * column.transpose() / k;
    }
    return compliance;
}

std::vector<grasp::CompliantContact> findCompliantContacts(const simulation::GraspScene& scene, const SimTK::State& state,
                                                           const CompliancePredictionSettings& settings) {
    scene.getSystem().realize(state, SimTK::Stage::Velocity);
    std::vector<grasp::CompliantContact> contacts;
    for (const contact::ContactReport& r : scene.findContactReports(state)) {
        if (!(r.normalForce > 0) || !(r.depth > 0)) continue;
        grasp::CompliantContact c;
        c.p_GC = toEigen(r.p_G);
        c.n_G = toEigen(SimTK::Vec3(r.n_G));
        c.force_G = r.normalForce * c.n_G + toEigen(r.frictionForce_G);
        c.normalStiffness = 1.5 * r.normalForce / r.depth;
        c.tangentialStiffness = settings.tangentialStiffnessRatio * c.normalStiffness;
        c.fingerCompliance_G = calcFingerCompliance(scene, state, r.bodyA, r.p_G);
        contacts.push_back(c);
    }
    return contacts;
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
    LoadStartGrasp grasp;
    grasp.contacts = findCompliantContacts(scene, state, settings);
    for (const contact::ContactReport& r : scene.findContactReports(state)) {
        if (r.normalForce > 0 && r.depth > 0) grasp.bodies.push_back(r.bodyA);
    }
    if (grasp.contacts.empty()) throw NumericalError("compliance prediction: no contact at the load's start");
    grasp.p_GO = toEigen(scene.getObject().getBodyOriginLocation(state));
    return grasp;
}

std::vector<CompliancePrediction> predictGraspCapacities(const scenario::Scenario& scenario,
                                                         const simulation::SimulationOptions& options,
                                                         const std::vector<GraspCapacityRequest>& requests,
                                                         const CompliancePredictionSettings& settings) {
    const LoadStartGrasp grasp = findLoadStartGrasp(scenario, options, settings);
    std::vector<CompliancePrediction> predictions;
    for (const GraspCapacityRequest& r : requests) {
        grasp::CompliantCapacityOptions o;
        o.slipDistance = settings.slipDistance;
        CompliancePrediction p{r, {}, {}};
        o.mu = scenario.contact.dynamicFriction;
        p.dynamicFriction = grasp::calcCompliantCapacity(grasp.contacts, grasp.p_GO, toLoadDirection(r), o);
        o.mu = scenario.contact.staticFriction;
        p.staticFriction = grasp::calcCompliantCapacity(grasp.contacts, grasp.p_GO, toLoadDirection(r), o);
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
           describe(p.dynamicFriction) + "; mu_s: " + describe(p.staticFriction);
}

}  // namespace graspsim::capacity
