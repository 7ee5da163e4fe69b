#include "graspsim/capacity/compliance_prediction.h"

#include "graspsim/error.h"
#include "graspsim/model/model_description.h"
#include "graspsim/integration/simbody_stepper.h"
#include "graspsim/simulation/grasp_experiment.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Eigen/Dense>

namespace graspsim::capacity {

namespace {

Eigen::Vector3d toEigen(const SimTK::Vec3& v) { return {v[0], v[1], v[2]}; }

// Columns of the station Jacobian of `body`'s material point at p_G over the finger mobilizers
// (3 x n, in G).
Eigen::MatrixXd calcFingerJacobian(const simulation::GraspScene& scene, const SimTK::State& state,
                                   const std::string& body, const SimTK::Vec3& p_G) {
    const SimTK::SimbodyMatterSubsystem& matter = scene.getModel().getMatter();
    const SimTK::MobilizedBody& segment = scene.getModel().getMobilizedBody(body);
    SimTK::Matrix J;
    matter.calcStationJacobian(state, segment.getMobilizedBodyIndex(), segment.findStationAtGroundPoint(state, p_G), J);
    const std::vector<SimTK::MobilizedBodyIndex>& fingers = scene.getFingerMobilizers();
    Eigen::MatrixXd columns(3, fingers.size());
    for (std::size_t k = 0; k < fingers.size(); ++k) {
        const int u = int(matter.getMobilizedBody(fingers[k]).getFirstUIndex(state));
        columns.col(Eigen::Index(k)) << J(0, u), J(1, u), J(2, u);
    }
    return columns;
}

// The PD gains' joint stiffness where the IK follows the finger in its null space: kp J_E^+ J_E
// over each goal end-effector's chain (file comment).
Eigen::MatrixXd calcFollowedPdStiffness(const simulation::GraspScene& scene, const SimTK::State& state,
                                        const Eigen::VectorXd& kp) {
    const model::ModelDescription& d = scene.getModel().getDescription();
    Eigen::MatrixXd stiffness = Eigen::MatrixXd::Zero(kp.size(), kp.size());
    Eigen::VectorXd covered = Eigen::VectorXd::Zero(kp.size());
    for (const std::string& name : scene.getGoalEndEffectors()) {
        const model::EndEffector& e = *d.findEndEffector(name);
        const SimTK::MobilizedBody& body = scene.getModel().getMobilizedBody(e.body);
        const SimTK::Vec3 p_G = body.findStationLocationInGround(state, SimTK::Vec3(e.p_BE[0], e.p_BE[1], e.p_BE[2]));
        const Eigen::MatrixXd J = calcFingerJacobian(scene, state, e.body, p_G);
        const Eigen::MatrixXd projector = J.completeOrthogonalDecomposition().pseudoInverse() * J;
        const Eigen::VectorXd root = kp.cwiseSqrt();
        stiffness += root.asDiagonal() * projector * root.asDiagonal();
        for (Eigen::Index k = 0; k < J.cols(); ++k) covered[k] += J.col(k).norm() > 0 ? 1 : 0;
    }
    for (Eigen::Index k = 0; k < kp.size(); ++k) {
        if (covered[k] == 0) stiffness(k, k) += kp[k];  // a finger without a goal: plain PD
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

grasp::CompliantRamp runCreepRamp(const scenario::Scenario& scenario, LoadStartGrasp start, const GraspCapacityRequest& r,
                                  const CompliancePredictionSettings& settings) {
    for (grasp::CompliantContact& c : start.contacts) c.tangentialStiffness = settings.creepTangentialStiffnessRatio * c.normalStiffness;
    grasp::CompliantRampOptions o;
    o.rate = r.rate > 0 ? r.rate : findDefaultRate(scenario, r.torque);
    o.slipDistance = settings.slipDistance;
    o.maxLoad = o.rate * r.maxRampDuration;
    return grasp::runCompliantRamp(start.contacts, start.p_GO, toLoadDirection(r), scenario.contact, o);
}

}  // namespace

Eigen::MatrixXd calcFingerJointStiffness(const simulation::GraspScene& scene, const SimTK::State& state,
                                         const CompliancePredictionSettings& settings) {
    scene.getSystem().realize(state, SimTK::Stage::Position);
    const std::vector<SimTK::MobilizedBodyIndex>& fingers = scene.getFingerMobilizers();
    const model::ModelDescription& d = scene.getModel().getDescription();
    Eigen::VectorXd kp = Eigen::VectorXd::Zero(fingers.size()), passive = Eigen::VectorXd::Zero(fingers.size());
    for (const system::JointImpedance& j : scene.findJointImpedances()) {
        const auto it = std::find(fingers.begin(), fingers.end(), j.mobod);
        if (it == fingers.end()) continue;
        const std::size_t k = std::size_t(it - fingers.begin());
        const SimTK::MobilizedBody& mobod = scene.getModel().getMatter().getMobilizedBody(j.mobod);
        for (const model::Joint& joint : d.joints) {
            if (scene.getModel().getMobilizedBody(joint.child).getMobilizedBodyIndex() == j.mobod) passive[Eigen::Index(k)] = joint.stiffness;
        }
        kp[Eigen::Index(k)] = j.stiffness - passive[Eigen::Index(k)];
        const double q = mobod.getOneQ(state, 0);
        if (!j.stop.isEmptyHandle() && (q < j.stop.getLowerBound(state) || q > j.stop.getUpperBound(state))) {
            passive[Eigen::Index(k)] += j.stop.getStiffness(state);
        }
    }
    Eigen::MatrixXd pd = settings.ikFollowsNullSpace ? calcFollowedPdStiffness(scene, state, kp) : Eigen::MatrixXd(kp.asDiagonal());
    return pd + Eigen::MatrixXd(passive.asDiagonal());
}

Eigen::Matrix3d calcFingerCompliance(const simulation::GraspScene& scene, const SimTK::State& state,
                                     const Eigen::MatrixXd& jointStiffness, const std::string& body, const SimTK::Vec3& p_G) {
    scene.getSystem().realize(state, SimTK::Stage::Position);
    const Eigen::MatrixXd J = calcFingerJacobian(scene, state, body, p_G);
    return J * jointStiffness.ldlt().solve(J.transpose());
}

std::vector<grasp::CompliantContact> findCompliantContacts(const simulation::GraspScene& scene, const SimTK::State& state,
                                                           const CompliancePredictionSettings& settings) {
    scene.getSystem().realize(state, SimTK::Stage::Velocity);
    const Eigen::MatrixXd jointStiffness = calcFingerJointStiffness(scene, state, settings);
    std::vector<grasp::CompliantContact> contacts;
    for (const contact::ContactReport& r : scene.findContactReports(state)) {
        if (!(r.normalForce > 0) || !(r.depth > 0)) continue;
        grasp::CompliantContact c;
        c.p_GC = toEigen(r.p_G);
        c.n_G = toEigen(SimTK::Vec3(r.n_G));
        c.force_G = r.normalForce * c.n_G + toEigen(r.frictionForce_G);
        c.normalStiffness = 1.5 * r.normalForce / r.depth;
        c.tangentialStiffness = settings.tangentialStiffnessRatio * c.normalStiffness;
        c.fingerCompliance_G = calcFingerCompliance(scene, state, jointStiffness, r.bodyA, r.p_G);
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
    LoadStartGrasp start;
    start.contacts = findCompliantContacts(scene, state, settings);
    for (const contact::ContactReport& r : scene.findContactReports(state)) {
        if (r.normalForce > 0 && r.depth > 0) start.bodies.push_back(r.bodyA);
    }
    if (start.contacts.empty()) throw NumericalError("compliance prediction: no contact at the load's start");
    start.p_GO = toEigen(scene.getObject().findMassCenterLocationInGround(state));
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
        o.slipDistance = settings.slipDistance;
        CompliancePrediction p{r, {}, {}, {}};
        o.mu = scenario.contact.dynamicFriction;
        p.dynamicFriction = grasp::calcCompliantCapacity(start.contacts, start.p_GO, toLoadDirection(r), o);
        o.mu = scenario.contact.staticFriction;
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
           describe(p.dynamicFriction) + "; mu_s: " + describe(p.staticFriction) + "; creep ramp: " + describe(p.creep.capacity);
}

}  // namespace graspsim::capacity
