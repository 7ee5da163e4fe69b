#include "graspsim/control/joint_pd_controller.h"

#include "graspsim/error.h"

#include <algorithm>
#include <cmath>
#include <vector>

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

// One smoothstep of the targets from `from` to `to` (rad) over [start, start + duration] (s).
struct RampSegment {
    Vector from, to;
    double start = 0, duration = 0;
    double findEnd() const { return start + duration; }
};

// Targets as a function of time: `base` until the first segment starts, then each segment in turn
// (they do not overlap), holding the last one's end value. None while `segments` is empty.
struct TargetRamp {
    bool active = false;  // false: the targets last set (setTargets) hold
    Vector base;
    std::vector<RampSegment> segments;

    Vector findValue(double t) const {
        Vector value = base;
        for (const RampSegment& r : segments) {
            if (t <= r.start) break;
            const double tau = std::min(1.0, (t - r.start) / r.duration);
            value = r.from + (tau * tau * (3 - 2 * tau)) * (r.to - r.from);
        }
        return value;
    }
    // findValue(t)[k] without the whole vector: the last segment started by t sets the value
    // (the same arithmetic, element by element, so the same numbers).
    double findValue(double t, int k) const {
        const RampSegment* last = nullptr;
        for (const RampSegment& r : segments) {
            if (t <= r.start) break;
            last = &r;
        }
        if (last == nullptr) return base[k];
        const double tau = std::min(1.0, (t - last->start) / last->duration);
        return last->from[k] + (tau * tau * (3 - 2 * tau)) * (last->to[k] - last->from[k]);
    }
    // Drops the segments over by `t`, folding their end value into the base.
    void forgetBefore(double t) {
        while (!segments.empty() && segments.front().findEnd() <= t) {
            base = segments.front().to;
            segments.erase(segments.begin());
        }
    }
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
        // A function of q alone, yet every force evaluation (several per step for the rigid
        // stepper and the implicit joint impedance) would recompute it.
        holdingIndex_ = matter_.allocateLazyCacheEntry(state, SimTK::Stage::Position, new SimTK::Value<Vector>());
    }

    Vector getTargets(const State& s) const {
        const TargetRamp& ramp = SimTK::Value<TargetRamp>::downcast(matter_.getDiscreteVariable(s, rampIndex_)).get();
        if (!ramp.active) return SimTK::Value<Vector>::downcast(matter_.getDiscreteVariable(s, targetsIndex_)).get();
        return ramp.findValue(s.getTime());
    }
    void setTargets(State& s, const Vector& targets) const {
        SimTK::Value<Vector>::updDowncast(matter_.updDiscreteVariable(s, targetsIndex_)).upd() = targets;
        SimTK::Value<TargetRamp>::updDowncast(matter_.updDiscreteVariable(s, rampIndex_)).upd() = TargetRamp();
    }
    // The new segment starts after `delay` and after every segment already planned, from the value
    // the targets have then, so the targets do not change before it starts.
    void rampTargets(State& s, const Vector& targets, double duration, double delay) const {
        TargetRamp ramp = SimTK::Value<TargetRamp>::downcast(matter_.getDiscreteVariable(s, rampIndex_)).get();
        if (!ramp.active) ramp.base = getTargets(s);
        ramp.active = true;
        ramp.forgetBefore(s.getTime());
        double start = s.getTime() + delay;
        if (!ramp.segments.empty()) start = std::max(start, ramp.segments.back().findEnd());
        ramp.segments.push_back(RampSegment{ramp.findValue(start), targets, start, duration});
        SimTK::Value<TargetRamp>::updDowncast(matter_.updDiscreteVariable(s, rampIndex_)).upd() = std::move(ramp);
    }
    double findAngle(const State& s, std::size_t k) const { return matter_.getMobilizedBody(jointBodies_[k]).getOneQ(s, 0); }

    // The joints' q and u indices, fixed from the Model stage on (graspsim changes no Model-stage
    // variable during a run): looking them up through the mobilized bodies' handles at every
    // evaluation cost more than the torques.
    void realizeModel(State& s) const override {
        qIndices_.clear();
        uIndices_.clear();
        for (MobilizedBodyIndex b : jointBodies_) {
            const SimTK::MobilizedBody& mobod = matter_.getMobilizedBody(b);
            qIndices_.push_back(mobod.getFirstQIndex(s));
            uIndices_.push_back(mobod.getFirstUIndex(s));
        }
    }

    void calcForce(const State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                   Vector& mobilityForces) const override {
        const TargetRamp& ramp = SimTK::Value<TargetRamp>::downcast(matter_.getDiscreteVariable(s, rampIndex_)).get();
        const Vector& held = SimTK::Value<Vector>::downcast(matter_.getDiscreteVariable(s, targetsIndex_)).get();
        const Vector& holding = findGravityHoldingForces(s);
        const Vector &q = s.getQ(), &u = s.getU();
        for (std::size_t k = 0; k < jointBodies_.size(); ++k) {
            const int i = static_cast<int>(k), ui = uIndices_[k];
            const double target = ramp.active ? ramp.findValue(s.getTime(), i) : held[i];
            const double tau = gains_[k].kp * (target - q[qIndices_[k]]) - gains_[k].kd * u[ui] + holding[ui];
            mobilityForces[ui] += tau;
        }
    }

    SimTK::Real calcPotentialEnergy(const State&) const override { return 0; }

private:
    const Vector& findGravityHoldingForces(const State& s) const {
        auto& cached = SimTK::Value<Vector>::updDowncast(matter_.updCacheEntry(s, holdingIndex_));
        if (!matter_.isCacheValueRealized(s, holdingIndex_)) {
            cached.upd() = calcGravityHoldingForces(s);
            matter_.markCacheValueRealized(s, holdingIndex_);
        }
        return cached.get();
    }

    // Generalized forces that cancel gravity on the weighed bodies: -J^T F_gravity.
    Vector calcGravityHoldingForces(const State& s) const {
        SimTK::Vector_<SimTK::SpatialVec> weights(matter_.getNumBodies(), SimTK::SpatialVec(SimTK::Vec3(0), SimTK::Vec3(0)));
        for (MobilizedBodyIndex b : weighedBodies_) {
            const SimTK::MobilizedBody& mobod = matter_.getMobilizedBody(b);
            const SimTK::MassProperties& mass = mobod.getBodyMassProperties(s);
            const double m = mass.getMass();
            if (m == 0) continue;
            const SimTK::Vec3 p_BoCm_G = mobod.getBodyRotation(s) * mass.getMassCenter();
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
    mutable SimTK::CacheEntryIndex holdingIndex_;
    mutable std::vector<int> qIndices_, uIndices_;  // per joint, from realizeModel
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

void JointPdController::rampTargets(SimTK::State& state, const SimTK::Vector& targets, double duration, double delay) const {
    const bool timesOk = duration > 0 && std::isfinite(duration) && delay >= 0 && std::isfinite(delay);
    if (targets.size() != static_cast<int>(jointNames_.size()) || !timesOk) {
        throw Error("JointPdController::rampTargets: got " + std::to_string(targets.size()) + " targets for " +
                    std::to_string(jointNames_.size()) + " joints over " + std::to_string(duration) + " s after " +
                    std::to_string(delay) + " s (needs a duration > 0 and a delay >= 0)");
    }
    impl_->rampTargets(state, targets, duration, delay);
}

SimTK::Vector JointPdController::getTargets(const SimTK::State& state) const { return impl_->getTargets(state); }

SimTK::Vector JointPdController::findJointAngles(const SimTK::State& state) const {
    Vector q(static_cast<int>(jointNames_.size()));
    for (std::size_t k = 0; k < jointNames_.size(); ++k) q[static_cast<int>(k)] = impl_->findAngle(state, k);
    return q;
}

}  // namespace graspsim::control
