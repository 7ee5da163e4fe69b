#include "graspsim/grasp/limited_weld.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "graspsim/error.h"
#include "weld_axis_constraint.h"

namespace graspsim::grasp {

namespace {

const char* const kAxisNames[6] = {"rotation x",    "rotation y",    "rotation z",
                                   "translation x", "translation y", "translation z"};

// Instance stage: which constraints are on. direction[k] = 0 stuck, +-1 sliding that way;
// heldByLock: every axis stuck and O's mobilizer locked instead of the six constraints on.
struct WeldModes {
    bool enabled = false;
    bool heldByLock = false;
    std::array<int, 6> direction = {0, 0, 0, 0, 0, 0};
};

// Instance stage: where the weld attaches, frame F on H and frame M on O.
struct WeldFrames {
    SimTK::Transform X_HF;
    SimTK::Transform X_OM;
};

// Dynamics stage: what the sliding force and the witnesses read.
struct WeldSettings {
    SimTK::Vec6 limits = SimTK::Vec6(SimTK::Infinity);
    std::array<bool, 6> locked = {true, true, true, true, true, true};
};

SimTK::Vec6 findEffective(const WeldSettings& settings) {
    SimTK::Vec6 limits = settings.limits;
    for (int k = 0; k < 6; ++k) {
        if (settings.locked[k]) limits[k] = SimTK::Infinity;
    }
    return limits;
}

// Enabling or sticking projects the relative velocity away; Simbody's default accuracy would
// leave up to about 1e-3 of it.
constexpr double kProjectionAccuracy = 1e-12;

}  // namespace

// The sliding force, and the owner of the weld's state variables (allocated with the force).
class LimitedWeld::Elements : public SimTK::Force::Custom::Implementation {
public:
    Elements(const SimTK::SimbodyMatterSubsystem& matter, const SimTK::GeneralForceSubsystem& forces,
             const SimTK::MobilizedBody& H, const SimTK::Transform& X_HF, const SimTK::MobilizedBody& O,
             const SimTK::Transform& X_OM)
        : matter_(matter), forces_(forces), bodyH_(H), defaultFrames_{X_HF, X_OM}, bodyO_(O) {}

    void realizeTopology(SimTK::State& state) const override {
        modesIndex_ = forces_.allocateDiscreteVariable(state, SimTK::Stage::Instance,
                                                       new SimTK::Value<WeldModes>(WeldModes()));
        settingsIndex_ = forces_.allocateDiscreteVariable(state, SimTK::Stage::Dynamics,
                                                          new SimTK::Value<WeldSettings>(WeldSettings()));
        engagedIndex_ = forces_.allocateDiscreteVariable(state, SimTK::Stage::Dynamics,
                                                         new SimTK::Value<SimTK::Transform>());
        framesIndex_ = forces_.allocateDiscreteVariable(state, SimTK::Stage::Instance,
                                                        new SimTK::Value<WeldFrames>(defaultFrames_));
        lockReactionIndex_ = forces_.allocateLazyCacheEntry(state, SimTK::Stage::Acceleration,
                                                            new SimTK::Value<SimTK::Vec6>());
    }

    const WeldFrames& getFrames(const SimTK::State& s) const {
        return SimTK::Value<WeldFrames>::downcast(forces_.getDiscreteVariable(s, framesIndex_)).get();
    }
    void setFrames(SimTK::State& s, const WeldFrames& frames) const {
        SimTK::Value<WeldFrames>::updDowncast(forces_.updDiscreteVariable(s, framesIndex_)).upd() = frames;
    }

    const WeldModes& getModes(const SimTK::State& s) const {
        return SimTK::Value<WeldModes>::downcast(forces_.getDiscreteVariable(s, modesIndex_)).get();
    }
    WeldModes& updModes(SimTK::State& s) const {
        return SimTK::Value<WeldModes>::updDowncast(forces_.updDiscreteVariable(s, modesIndex_)).upd();
    }
    const WeldSettings& getSettings(const SimTK::State& s) const {
        return SimTK::Value<WeldSettings>::downcast(forces_.getDiscreteVariable(s, settingsIndex_)).get();
    }
    WeldSettings& updSettings(SimTK::State& s) const {
        return SimTK::Value<WeldSettings>::updDowncast(forces_.updDiscreteVariable(s, settingsIndex_)).upd();
    }
    const SimTK::Transform& getEngaged(const SimTK::State& s) const {
        return SimTK::Value<SimTK::Transform>::downcast(forces_.getDiscreteVariable(s, engagedIndex_)).get();
    }
    void setEngaged(SimTK::State& s, const SimTK::Transform& X_FM) const {
        SimTK::Value<SimTK::Transform>::updDowncast(forces_.updDiscreteVariable(s, engagedIndex_)).upd() = X_FM;
    }

    SimTK::Rotation findR_GM(const SimTK::State& s) const { return bodyO_.getBodyRotation(s) * getFrames(s).X_OM.R(); }
    SimTK::Vec3 findP_GM(const SimTK::State& s) const { return bodyO_.getBodyTransform(s) * getFrames(s).X_OM.p(); }
    SimTK::Transform findX_FM(const SimTK::State& s) const {
        const WeldFrames& frames = getFrames(s);
        return ~(bodyH_.getBodyTransform(s) * frames.X_HF) * (bodyO_.getBodyTransform(s) * frames.X_OM);
    }

    // r: O's motion relative to H along M's axes (the quantity each stuck constraint zeroes).
    SimTK::Vec6 findSlipVelocity(const SimTK::State& s) const {
        const SimTK::Rotation R_GM = findR_GM(s);
        const SimTK::Vec3 p_GM = findP_GM(s);
        const SimTK::SpatialVec& V_GH = bodyH_.getBodyVelocity(s);
        const SimTK::SpatialVec& V_GO = bodyO_.getBodyVelocity(s);
        const SimTK::Vec3 v_M = V_GO[1] + V_GO[0] % (p_GM - bodyO_.getBodyOriginLocation(s));
        const SimTK::Vec3 v_C = V_GH[1] + V_GH[0] % (p_GM - bodyH_.getBodyOriginLocation(s));
        SimTK::Vec6 r;
        r.updSubVec<3>(0) = ~R_GM * (V_GO[0] - V_GH[0]);
        r.updSubVec<3>(3) = ~R_GM * (v_M - v_C);
        return r;
    }

    // While held by the lock, the reaction on O along M's axes (N m about M's origin, N): minus the
    // lock's motion forces (Simbody's prescribed-motion multipliers tau enter as M udot = f - tau,
    // like constraint multipliers), which for O's Free mobilizer are the moment about its outboard
    // frame's origin and the force, both in its inboard frame on H. Computed once per
    // realization: the six witnesses all read it.
    const SimTK::Vec6& findLockReaction(const SimTK::State& s) const {
        if (forces_.isCacheValueRealized(s, lockReactionIndex_)) {
            return SimTK::Value<SimTK::Vec6>::downcast(forces_.getCacheEntry(s, lockReactionIndex_)).get();
        }
        SimTK::Vector tau;
        matter_.findMotionForces(s, tau);
        const int u0 = bodyO_.getFirstUIndex(s);
        const SimTK::Rotation R_GF = bodyH_.getBodyRotation(s) * bodyO_.getInboardFrame(s).R();
        const SimTK::Vec3 m_G = -(R_GF * SimTK::Vec3(tau[u0], tau[u0 + 1], tau[u0 + 2]));
        const SimTK::Vec3 f_G = -(R_GF * SimTK::Vec3(tau[u0 + 3], tau[u0 + 4], tau[u0 + 5]));
        const SimTK::Vec3 p_GMobilizer = bodyO_.getBodyTransform(s) * bodyO_.getOutboardFrame(s).p();
        const SimTK::Rotation R_GM = findR_GM(s);
        SimTK::Vec6& f = SimTK::Value<SimTK::Vec6>::updDowncast(forces_.updCacheEntry(s, lockReactionIndex_)).upd();
        f.updSubVec<3>(0) = ~R_GM * (m_G + (p_GMobilizer - findP_GM(s)) % f_G);
        f.updSubVec<3>(3) = ~R_GM * f_G;
        forces_.markCacheValueRealized(s, lockReactionIndex_);
        return f;
    }

    // Generalized force of the sliding axes on O (N m, N; along M's axes).
    SimTK::Vec6 findSlidingForce(const SimTK::State& s) const {
        SimTK::Vec6 f(0);
        const WeldModes& modes = getModes(s);
        if (!modes.enabled) return f;
        const SimTK::Vec6 limits = findEffective(getSettings(s));
        for (int k = 0; k < 6; ++k) {
            if (modes.direction[k] != 0) f[k] = -modes.direction[k] * limits[k];
        }
        return f;
    }

    // Ground-frame spatial force on O at M's origin for generalized force f along M's axes.
    SimTK::SpatialVec toWrench(const SimTK::State& s, const SimTK::Vec6& f) const {
        const SimTK::Rotation R_GM = findR_GM(s);
        return SimTK::SpatialVec(R_GM * f.getSubVec<3>(0), R_GM * f.getSubVec<3>(3));
    }

    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override {
        const SimTK::Vec6 f = findSlidingForce(s);
        if (f == SimTK::Vec6(0)) return;
        const SimTK::SpatialVec W = toWrench(s, f);
        const SimTK::Vec3 p_GM = findP_GM(s);
        // Both bodies take the force at M's origin, so the pair adds no spurious moment.
        const SimTK::Vec3 p_OM = p_GM - bodyO_.getBodyOriginLocation(s);
        const SimTK::Vec3 p_HM = p_GM - bodyH_.getBodyOriginLocation(s);
        bodyForces[bodyO_.getMobilizedBodyIndex()] += SimTK::SpatialVec(W[0] + p_OM % W[1], W[1]);
        bodyForces[bodyH_.getMobilizedBodyIndex()] -= SimTK::SpatialVec(W[0] + p_HM % W[1], W[1]);
    }

    // Sliding friction dissipates; nothing is stored.
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }

private:
    const SimTK::SimbodyMatterSubsystem& matter_;
    const SimTK::GeneralForceSubsystem& forces_;
    SimTK::MobilizedBody bodyH_;
    WeldFrames defaultFrames_;
    SimTK::MobilizedBody bodyO_;
    mutable SimTK::DiscreteVariableIndex modesIndex_;
    mutable SimTK::DiscreteVariableIndex settingsIndex_;
    mutable SimTK::DiscreteVariableIndex engagedIndex_;
    mutable SimTK::DiscreteVariableIndex framesIndex_;
    mutable SimTK::CacheEntryIndex lockReactionIndex_;
};

// One witness per axis, negative while the axis's mode is consistent: stuck, |lambda| - L;
// sliding, -s r. Its rise through zero is the switch (see the header).
class LimitedWeld::AxisEvent : public SimTK::TriggeredEventHandler {
public:
    AxisEvent(const LimitedWeld& weld, int axis)
        : SimTK::TriggeredEventHandler(SimTK::Stage::Acceleration), weld_(weld), axis_(axis) {
        getTriggerInfo().setTriggerOnRisingSignTransition(true);
        getTriggerInfo().setTriggerOnFallingSignTransition(false);
    }

    SimTK::Real getValue(const SimTK::State& state) const override {
        const WeldModes& modes = weld_.elements_->getModes(state);
        const double limit = findEffective(weld_.elements_->getSettings(state))[axis_];
        if (!modes.enabled || limit == SimTK::Infinity) return -1;
        const int direction = modes.direction[axis_];
        if (direction == 0) return std::abs(weld_.findMultiplier(state, axis_)) - limit;
        return -direction * weld_.elements_->findSlipVelocity(state)[axis_];
    }

    void handleEvent(SimTK::State& state, SimTK::Real, bool& shouldTerminate) const override {
        shouldTerminate = false;
        weld_.handleAxisEvent(state, axis_);
    }

private:
    const LimitedWeld& weld_;
    int axis_;
};

LimitedWeld::LimitedWeld(SimTK::MultibodySystem& system, SimTK::SimbodyMatterSubsystem& matter,
                         SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& bodyH,
                         const SimTK::Transform& X_HF, const SimTK::MobilizedBody& bodyO,
                         const SimTK::Transform& X_OM)
    : system_(system),
      bodyO_(bodyO),
      lockable_(SimTK::MobilizedBody::Free::isInstanceOf(bodyO) &&
                bodyO.getParentMobilizedBody().getMobilizedBodyIndex() == bodyH.getMobilizedBodyIndex()) {
    if (bodyH.getMobilizedBodyIndex() == bodyO.getMobilizedBodyIndex()) {
        throw InputError("limited weld: body H and body O are the same body (index " +
                         std::to_string(int(bodyH.getMobilizedBodyIndex())) + ")");
    }
    elements_ = new Elements(matter, forces, bodyH, X_HF, bodyO, X_OM);
    force_ = SimTK::Force::Custom(forces, elements_);
    for (int k = 0; k < 6; ++k) {
        const Elements* elements = elements_;
        const auto findX_OM = [elements](const SimTK::State& s) -> const SimTK::Transform& {
            return elements->getFrames(s).X_OM;
        };
        constraints_[k] = SimTK::Constraint::Custom(new WeldAxisConstraint(matter, bodyH, bodyO, findX_OM, k));
        constraints_[k].setDisabledByDefault(true);
        system.addEventHandler(new AxisEvent(*this, k));
    }
}

bool LimitedWeld::isEnabled(const SimTK::State& state) const { return elements_->getModes(state).enabled; }

void LimitedWeld::setEnabled(SimTK::State& state, bool enabled) const {
    if (isHeldByLock(state)) holdByConstraints(state);
    WeldModes& modes = elements_->updModes(state);
    modes.enabled = enabled;
    modes.direction.fill(0);
    for (const SimTK::Constraint::Custom& c : constraints_) {
        if (enabled) {
            c.enable(state);
        } else {
            c.disable(state);
        }
    }
    if (!enabled) return;
    system_.realize(state, SimTK::Stage::Position);
    elements_->setEngaged(state, elements_->findX_FM(state));
    system_.realize(state, SimTK::Stage::Velocity);
    system_.projectU(state, kProjectionAccuracy);
    releaseOverloadedAxes(state);
}

bool LimitedWeld::isHeldByLock(const SimTK::State& state) const { return elements_->getModes(state).heldByLock; }

void LimitedWeld::setFrames(SimTK::State& state, const SimTK::Transform& X_HF, const SimTK::Transform& X_OM) const {
    elements_->setFrames(state, WeldFrames{X_HF, X_OM});
}

const SimTK::Transform& LimitedWeld::getFrameOnH(const SimTK::State& state) const {
    return elements_->getFrames(state).X_HF;
}

const SimTK::Transform& LimitedWeld::getFrameOnO(const SimTK::State& state) const {
    return elements_->getFrames(state).X_OM;
}

const SimTK::Vec6& LimitedWeld::getLimits(const SimTK::State& state) const {
    return elements_->getSettings(state).limits;
}

void LimitedWeld::setLimits(SimTK::State& state, const SimTK::Vec6& limits) const {
    for (int k = 0; k < 6; ++k) {
        if (std::isnan(limits[k]) || limits[k] < 0) {
            throw InputError(std::string("limited weld limit on ") + kAxisNames[k] + " is " +
                             std::to_string(limits[k]) + "; accepted: >= 0 (infinity allowed)");
        }
    }
    const bool canCheck = state.getSystemStage() >= SimTK::Stage::Position;
    elements_->updSettings(state).limits = limits;
    if (canCheck && isEnabled(state)) releaseOverloadedAxes(state);
}

bool LimitedWeld::isAxisLocked(const SimTK::State& state, WeldAxis axis) const {
    return elements_->getSettings(state).locked[toIndex(axis)];
}

// Locking a sliding axis makes it stick where it is (its slip rate is projected away).
void LimitedWeld::setAxisLocked(SimTK::State& state, WeldAxis axis, bool locked) const {
    const bool canCheck = state.getSystemStage() >= SimTK::Stage::Position;
    elements_->updSettings(state).locked[toIndex(axis)] = locked;
    if (locked && isSliding(state, axis)) {
        stick(state, toIndex(axis));
        if (canCheck) {
            system_.realize(state, SimTK::Stage::Velocity);
            system_.projectU(state, kProjectionAccuracy);
        }
    }
    if (canCheck && isEnabled(state)) releaseOverloadedAxes(state);
}

SimTK::Vec6 LimitedWeld::findEffectiveLimits(const SimTK::State& state) const {
    return findEffective(elements_->getSettings(state));
}

bool LimitedWeld::isSliding(const SimTK::State& state, WeldAxis axis) const {
    return getSlideDirection(state, axis) != 0;
}

int LimitedWeld::getSlideDirection(const SimTK::State& state, WeldAxis axis) const {
    const WeldModes& modes = elements_->getModes(state);
    return modes.enabled ? modes.direction[toIndex(axis)] : 0;
}

SimTK::Vec6 LimitedWeld::findSlipVelocity(const SimTK::State& state) const {
    return elements_->findSlipVelocity(state);
}

SimTK::Vec6 LimitedWeld::findGeneralizedForce(const SimTK::State& state) const {
    SimTK::Vec6 f = elements_->findSlidingForce(state);
    if (!isEnabled(state)) return f;
    for (int k = 0; k < 6; ++k) {
        if (elements_->getModes(state).direction[k] == 0) f[k] = -findMultiplier(state, k);
    }
    return f;
}

SimTK::SpatialVec LimitedWeld::findWrench(const SimTK::State& state) const {
    return elements_->toWrench(state, findGeneralizedForce(state));
}

const SimTK::Transform& LimitedWeld::findEngagedTransform(const SimTK::State& state) const {
    return elements_->getEngaged(state);
}

SimTK::Transform LimitedWeld::findTransform(const SimTK::State& state) const { return elements_->findX_FM(state); }

void LimitedWeld::engage(SimTK::State& state, const AttachmentEngagement& engagement) const {
    if (engagement.lowerLimits && *engagement.lowerLimits != engagement.limits) {
        throw InputError("limited weld: two-sided (asymmetric) limits are not supported; use the bushing");
    }
    setFrames(state, engagement.X_HF, engagement.X_OM);
    setLimits(state, engagement.limits);
    for (int k = 0; k < 6; ++k) setAxisLocked(state, static_cast<WeldAxis>(k), engagement.lockedAxes[k]);
    setEnabled(state, true);  // last: axes over their limits start sliding at once
    system_.realize(state, SimTK::Stage::Position);
}

SimTK::SpatialVec LimitedWeld::findReactionOnObject(const SimTK::State& state) const {
    return shiftToObjectOrigin(findWrench(state), bodyO_.getBodyTransform(state).R(), getFrameOnO(state).p());
}

// The constraint's multiplier, or what it would be (minus the reaction) while the lock holds.
double LimitedWeld::findMultiplier(const SimTK::State& state, int axis) const {
    if (isHeldByLock(state)) return -elements_->findLockReaction(state)[axis];
    return constraints_[axis].getMultipliersAsVector(state)[0];
}

// The integrator localized the switch of `axis`; at the event |lambda| ~ L (stuck) or r ~ 0
// (sliding).
void LimitedWeld::handleAxisEvent(SimTK::State& state, int axis) const {
    if (!isEnabled(state)) return;
    system_.realize(state, SimTK::Stage::Acceleration);
    if (elements_->getModes(state).direction[axis] == 0) {
        const double lambda = findMultiplier(state, axis);
        slide(state, axis, lambda >= 0 ? 1 : -1);
    } else {
        // The slip stopped: try to hold the axis; if that needs more than L, it slides back the
        // way the excess pushes (releaseOverloadedAxes below).
        stick(state, axis);
        system_.realize(state, SimTK::Stage::Velocity);
        system_.projectU(state, kProjectionAccuracy);
    }
    releaseOverloadedAxes(state);
}

void LimitedWeld::stick(SimTK::State& state, int axis) const {
    elements_->updModes(state).direction[axis] = 0;
    constraints_[axis].enable(state);
}

void LimitedWeld::slide(SimTK::State& state, int axis, int direction) const {
    if (isHeldByLock(state)) holdByConstraints(state);
    elements_->updModes(state).direction[axis] = direction;
    constraints_[axis].disable(state);
}

// Every axis stuck: the same rigid attachment as the six constraints, with no multipliers to solve
// for. The relative velocity is already zero (projected when the axes stuck), so the lock's u = 0
// changes nothing but round-off.
void LimitedWeld::holdByLock(SimTK::State& state) const {
    for (const SimTK::Constraint::Custom& c : constraints_) c.disable(state);
    bodyO_.lock(state, SimTK::Motion::Position);
    elements_->updModes(state).heldByLock = true;
}

void LimitedWeld::holdByConstraints(SimTK::State& state) const {
    bodyO_.unlock(state);
    WeldModes& modes = elements_->updModes(state);
    modes.heldByLock = false;
    for (int k = 0; k < 6; ++k) {
        if (modes.direction[k] == 0) constraints_[k].enable(state);
    }
}

// Stuck axes over their limit start sliding, the most overloaded first (releasing one changes
// the others' reactions); if none is sliding after that, the lock takes over from the constraints.
void LimitedWeld::releaseOverloadedAxes(SimTK::State& state) const {
    for (int pass = 0; pass < 6; ++pass) {
        system_.realize(state, SimTK::Stage::Acceleration);
        const SimTK::Vec6 limits = findEffectiveLimits(state);
        int worst = -1;
        double worstExcess = 0;
        for (int k = 0; k < 6; ++k) {
            if (elements_->getModes(state).direction[k] != 0 || limits[k] == SimTK::Infinity) continue;
            const double excess = std::abs(findMultiplier(state, k)) - limits[k] * (1 + 1e-9);
            if (excess > worstExcess) {
                worst = k;
                worstExcess = excess;
            }
        }
        if (worst < 0) break;
        slide(state, worst, findMultiplier(state, worst) >= 0 ? 1 : -1);
    }
    const std::array<int, 6>& direction = elements_->getModes(state).direction;
    const bool allStuck = std::all_of(direction.begin(), direction.end(), [](int d) { return d == 0; });
    if (lockable_ && allStuck && !isHeldByLock(state)) holdByLock(state);
    system_.realize(state, SimTK::Stage::Acceleration);
}

std::optional<SingleConstraintState> LimitedWeld::findSingleConstraintState(const SimTK::State& state) const {
    if (!isEngaged(state)) return std::nullopt;
    const SimTK::Vec6 limits = findEffectiveLimits(state);
    return SingleConstraintState{getFrameOnO(state), limits, findGeneralizedForce(state), findWrench(state), limits};
}

}  // namespace graspsim::grasp
