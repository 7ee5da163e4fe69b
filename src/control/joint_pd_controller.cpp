#include "graspsim/control/joint_pd_controller.h"

#include "graspsim/error.h"

#include <algorithm>
#include <cmath>

namespace graspsim::control {

using SimTK::MobilizedBodyIndex;
using SimTK::State;
using SimTK::Vector;

namespace {

// The mobilized body whose single mobility is `joint`.
MobilizedBodyIndex findJointBody(const system::MultibodyModel& model, const std::string& joint) {
    model.getJointQIndex(joint);  // throws InputError for an unknown or fixed joint
    return model.getMobilizedBody(model.getDescription().findJoint(joint)->child).getMobilizedBodyIndex();
}

}  // namespace

namespace {

// Targets moving from `from` to `to` (rad) over [start, start + duration] (s); none when duration is 0.
struct TargetRamp {
    Vector from, to;
    double start = 0, duration = 0;
};

}  // namespace

class JointPdController::Implementation : public SimTK::Force::Custom::Implementation {
public:
    Implementation(const system::MultibodyModel& model, const std::vector<ControlledJoint>& joints,
                   const std::vector<std::string>& gravityBodies)
        : matter_(model.getMatter()), gravity_(model.getOptions().gravity) {
        for (const ControlledJoint& j : joints) {
            jointBodies_.push_back(findJointBody(model, j.name));
            gains_.push_back(j.gains);
        }
        for (const std::string& b : gravityBodies) weighedBodies_.push_back(model.getMobilizedBody(b).getMobilizedBodyIndex());
    }

    void realizeTopology(State& state) const override {
        Vector initial(static_cast<int>(jointBodies_.size()), 0.0);
        targetsIndex_ = matter_.allocateDiscreteVariable(state, SimTK::Stage::Dynamics, new SimTK::Value<Vector>(initial));
        // Report: a ramp starts at the targets' present value, so it changes nothing computed at its start.
        rampIndex_ = matter_.allocateDiscreteVariable(state, SimTK::Stage::Report, new SimTK::Value<TargetRamp>());
    }

    Vector getTargets(const State& s) const {
        const TargetRamp& ramp = SimTK::Value<TargetRamp>::downcast(matter_.getDiscreteVariable(s, rampIndex_)).get();
        if (!(ramp.duration > 0)) return SimTK::Value<Vector>::downcast(matter_.getDiscreteVariable(s, targetsIndex_)).get();
        const double tau = std::clamp((s.getTime() - ramp.start) / ramp.duration, 0.0, 1.0);
        return ramp.from + (tau * tau * (3 - 2 * tau)) * (ramp.to - ramp.from);
    }
    void setTargets(State& s, const Vector& targets) const {
        SimTK::Value<Vector>::updDowncast(matter_.updDiscreteVariable(s, targetsIndex_)).upd() = targets;
        SimTK::Value<TargetRamp>::updDowncast(matter_.updDiscreteVariable(s, rampIndex_)).upd() = TargetRamp();
    }
    void rampTargets(State& s, const Vector& targets, double duration) const {
        TargetRamp ramp{getTargets(s), targets, s.getTime(), duration};
        SimTK::Value<TargetRamp>::updDowncast(matter_.updDiscreteVariable(s, rampIndex_)).upd() = std::move(ramp);
    }
    double findAngle(const State& s, std::size_t k) const { return matter_.getMobilizedBody(jointBodies_[k]).getOneQ(s, 0); }

    void calcForce(const State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                   Vector& mobilityForces) const override {
        const Vector target = getTargets(s);
        const Vector holding = calcGravityHoldingForces(s);
        for (std::size_t k = 0; k < jointBodies_.size(); ++k) {
            const SimTK::MobilizedBody& mobod = matter_.getMobilizedBody(jointBodies_[k]);
            const double q = mobod.getOneQ(s, 0), u = mobod.getOneU(s, 0);
            const double tau = gains_[k].kp * (target[static_cast<int>(k)] - q) - gains_[k].kd * u +
                               holding[mobod.getFirstUIndex(s)];
            mobod.applyOneMobilityForce(s, SimTK::MobilizerUIndex(0), tau, mobilityForces);
        }
    }

    SimTK::Real calcPotentialEnergy(const State&) const override { return 0; }

private:
    // Generalized forces that cancel gravity on the weighed bodies: -J^T F_gravity.
    Vector calcGravityHoldingForces(const State& s) const {
        SimTK::Vector_<SimTK::SpatialVec> weights(matter_.getNumBodies(), SimTK::SpatialVec(SimTK::Vec3(0), SimTK::Vec3(0)));
        for (MobilizedBodyIndex b : weighedBodies_) {
            const SimTK::MobilizedBody& mobod = matter_.getMobilizedBody(b);
            const double m = mobod.getBodyMass(s);
            if (m == 0) continue;
            const SimTK::Vec3 p_BoCm_G = mobod.getBodyRotation(s) * mobod.getBodyMassCenterStation(s);
            const SimTK::Vec3 W = m * gravity_;
            weights[b] = SimTK::SpatialVec(p_BoCm_G % W, W);
        }
        Vector generalized;
        matter_.multiplyBySystemJacobianTranspose(s, weights, generalized);
        return -generalized;
    }

    const SimTK::SimbodyMatterSubsystem& matter_;
    SimTK::Vec3 gravity_;
    std::vector<MobilizedBodyIndex> jointBodies_;
    std::vector<PdGains> gains_;
    std::vector<MobilizedBodyIndex> weighedBodies_;
    mutable SimTK::DiscreteVariableIndex targetsIndex_, rampIndex_;
};

JointPdController::JointPdController(system::MultibodyModel& model, const std::vector<ControlledJoint>& joints,
                                     const std::vector<std::string>& gravityBodies) {
    for (const ControlledJoint& j : joints) {
        jointNames_.push_back(j.name);
        gains_.push_back(j.gains);
    }
    auto* impl = new Implementation(model, joints, gravityBodies);
    impl_ = impl;
    SimTK::Force::Custom(model.updForces(), impl);  // the subsystem takes ownership of impl
}

void JointPdController::setTargets(SimTK::State& state, const SimTK::Vector& targets) const {
    if (targets.size() != static_cast<int>(jointNames_.size())) {
        throw Error("JointPdController::setTargets: got " + std::to_string(targets.size()) + " targets for " +
                    std::to_string(jointNames_.size()) + " joints");
    }
    impl_->setTargets(state, targets);
}

void JointPdController::rampTargets(SimTK::State& state, const SimTK::Vector& targets, double duration) const {
    if (targets.size() != static_cast<int>(jointNames_.size()) || !(duration > 0) || !std::isfinite(duration)) {
        throw Error("JointPdController::rampTargets: got " + std::to_string(targets.size()) + " targets for " +
                    std::to_string(jointNames_.size()) + " joints over " + std::to_string(duration) + " s (needs > 0)");
    }
    impl_->rampTargets(state, targets, duration);
}

SimTK::Vector JointPdController::getTargets(const SimTK::State& state) const { return impl_->getTargets(state); }

SimTK::Vector JointPdController::findJointAngles(const SimTK::State& state) const {
    Vector q(static_cast<int>(jointNames_.size()));
    for (std::size_t k = 0; k < jointNames_.size(); ++k) q[static_cast<int>(k)] = impl_->findAngle(state, k);
    return q;
}

}  // namespace graspsim::control
