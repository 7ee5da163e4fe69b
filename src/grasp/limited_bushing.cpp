#include "graspsim/grasp/limited_bushing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "graspsim/error.h"
#include "graspsim/grasp/limited_bushing_law.h"

namespace graspsim::grasp {

namespace {

const char* const kAxisNames[6] = {"rotation x",    "rotation y",    "rotation z",
                                   "translation x", "translation y", "translation z"};

// The per-state axis settings: one discrete variable, so setLimits(), setAxisLocked() and
// setStiffness() invalidate once. Stiffness and damping start at the constructor's values.
struct AxisSettings {
    SimTK::Vec6 limits = SimTK::Vec6(SimTK::Infinity);       // L+ (the upper side)
    SimTK::Vec6 lowerLimits = SimTK::Vec6(SimTK::Infinity);  // L-: the force stays >= -L-
    std::array<bool, 6> locked = {true, true, true, true, true, true};
    SimTK::Vec6 stiffness = SimTK::Vec6(0);  // the diagonal of stiffnessMatrix when coupled
    SimTK::Vec6 damping = SimTK::Vec6(0);
    bool coupled = false;
    SimTK::Mat66 stiffnessMatrix = SimTK::Mat66::getNaN();  // read only when coupled
};

// K e, the elastic force's magnitude per axis (the force on O is its negative).
SimTK::Vec6 calcElasticLoad(const AxisSettings& settings, const SimTK::Vec6& e) {
    if (settings.coupled) return settings.stiffnessMatrix * e;
    SimTK::Vec6 load;
    for (int k = 0; k < 6; ++k) load[k] = settings.stiffness[k] * e[k];
    return load;
}

void checkAxisValues(const SimTK::Vec6& values, const std::string& what, bool allowZero,
                     bool allowInfinity) {
    for (int k = 0; k < 6; ++k) {
        const double v = values[k];
        const bool ok = !std::isnan(v) && (allowZero ? v >= 0 : v > 0) &&
                        (allowInfinity || std::isfinite(v));
        if (!ok) {
            throw InputError("limited bushing " + what + " on " + kAxisNames[k] + " is " +
                             std::to_string(v) + "; accepted: " + (allowZero ? ">= 0" : "> 0") +
                             (allowInfinity ? " (infinity allowed)" : " and finite"));
        }
    }
}

// Where the element attaches: frame F on H and frame M on O (an Instance-stage variable, so
// that moving them re-realizes everything that depends on them).
struct BushingFrames {
    SimTK::Transform X_HF;
    SimTK::Transform X_OM;
};

// Relative state of M with respect to the anchor, as the law needs it.
struct BushingKinematics {
    SimTK::Rotation R_GA;  // anchor orientation in Ground
    SimTK::Vec3 p_GM;      // M's origin in Ground (m)
    SimTK::Vec6 e;         // displacement of M from A (rad, m; in A)
    SimTK::Vec6 r;         // velocity of M relative to F (rad/s, m/s; in A)
};

// The law's output on all six axes.
struct BushingResponse {
    SimTK::Vec6 slip;   // slip fractions s_k
    SimTK::Vec6 force;  // generalized force on O (N m, N; in A)
};

struct BushingEvaluation {
    BushingKinematics kinematics;
    BushingResponse response;
};

}  // namespace

class LimitedBushingImpl : public SimTK::Force::Custom::Implementation {
public:
    LimitedBushingImpl(const SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& H,
                       const SimTK::Transform& X_HF, const SimTK::MobilizedBody& O,
                       const SimTK::Transform& X_OM, const SimTK::Vec6& stiffness,
                       const SimTK::Vec6& damping)
        : forces_(forces), bodyH_(H), defaultFrames_{X_HF, X_OM}, bodyO_(O), stiffness_(stiffness),
          damping_(damping) {}

    const SimTK::Vec6& getStiffness() const { return stiffness_; }
    const SimTK::MobilizedBody& getBodyO() const { return bodyO_; }
    const SimTK::Vec6& getDamping() const { return damping_; }
    double getSlipOnsetWidth() const { return onsetWidth_; }
    void setSlipOnsetWidth(double width) { onsetWidth_ = width; }

    void realizeTopology(SimTK::State& state) const override {
        enabledIndex_ = forces_.allocateDiscreteVariable(state, SimTK::Stage::Instance,
                                                         new SimTK::Value<bool>(true));
        settingsIndex_ = forces_.allocateDiscreteVariable(
            state, SimTK::Stage::Dynamics, new SimTK::Value<AxisSettings>(findDefaultSettings()));
        baseIndex_ = forces_.allocateDiscreteVariable(state, SimTK::Stage::Dynamics,
                                                      new SimTK::Value<SimTK::Transform>());
        framesIndex_ = forces_.allocateDiscreteVariable(
            state, SimTK::Stage::Instance, new SimTK::Value<BushingFrames>(defaultFrames_));
        zIndex_ = forces_.allocateZ(state, SimTK::Vector(6, 0.0));
        evaluationIndex_ = forces_.allocateLazyCacheEntry(state, SimTK::Stage::Dynamics,
                                                          new SimTK::Value<BushingEvaluation>());
    }

    // ---- state variables ----------------------------------------------------------------
    AxisSettings findDefaultSettings() const {
        AxisSettings settings;
        settings.stiffness = stiffness_;
        settings.damping = damping_;
        return settings;
    }
    bool isEnabled(const SimTK::State& s) const {
        return SimTK::Value<bool>::downcast(forces_.getDiscreteVariable(s, enabledIndex_)).get();
    }
    void setEnabled(SimTK::State& s, bool enabled) const {
        SimTK::Value<bool>::updDowncast(forces_.updDiscreteVariable(s, enabledIndex_)).upd() = enabled;
    }
    const BushingFrames& getFrames(const SimTK::State& s) const {
        return SimTK::Value<BushingFrames>::downcast(forces_.getDiscreteVariable(s, framesIndex_)).get();
    }
    void setFrames(SimTK::State& s, const BushingFrames& frames) const {
        SimTK::Value<BushingFrames>::updDowncast(forces_.updDiscreteVariable(s, framesIndex_)).upd() = frames;
    }
    const AxisSettings& getSettings(const SimTK::State& s) const {
        return SimTK::Value<AxisSettings>::downcast(forces_.getDiscreteVariable(s, settingsIndex_)).get();
    }
    // Writes the settings and, if positions are realized, moves the anchor so no axis holds
    // more elastic force than its new limit (the excess becomes slip at once).
    void setSettings(SimTK::State& s, const AxisSettings& settings) const {
        const bool canProject = s.getSystemStage() >= SimTK::Stage::Position;
        const SimTK::Transform X_FM = canProject ? findX_FM(s) : SimTK::Transform();
        SimTK::Vec6 e = canProject ? findDisplacement(s) : SimTK::Vec6(0);
        SimTK::Value<AxisSettings>::updDowncast(forces_.updDiscreteVariable(s, settingsIndex_))
            .upd() = settings;
        if (!canProject) return;
        const SimTK::Vec6 upper = applyAxisLocks(settings.limits, settings.locked);
        const SimTK::Vec6 lower = applyAxisLocks(settings.lowerLimits, settings.locked);
        bool changed = false;
        for (int k = 0; k < 6; ++k) {
            const double eMax = findLoadedSideLimit(lower[k], upper[k], e[k]) / settings.stiffness[k];
            if (std::abs(e[k]) > eMax) {
                e[k] = std::copysign(eMax, e[k]);
                changed = true;
            }
        }
        if (changed) placeAnchor(s, X_FM, e);
    }

    // ---- anchor --------------------------------------------------------------------------
    // z: the anchor's slip since X_FA0, (rotation vector of R_A0A, p_A0A in A0).
    SimTK::Vec6 getAnchorSlip(const SimTK::State& s) const {
        const SimTK::Vector& z = forces_.getZ(s);
        SimTK::Vec6 slip;
        for (int i = 0; i < 6; ++i) slip[i] = z[int(zIndex_) + i];
        return slip;
    }
    SimTK::Transform findAnchorTransform(const SimTK::State& s) const {
        const SimTK::Transform& X_FA0 = SimTK::Value<SimTK::Transform>::downcast(forces_.getDiscreteVariable(s, baseIndex_)).get();
        const SimTK::Vec6 z = getAnchorSlip(s);
        return X_FA0 * SimTK::Transform(calcRotationFromVector(z.getSubVec<3>(0)), z.getSubVec<3>(3));
    }
    // Sets the anchor so that M's displacement from it is e. Re-bases the chart (X_FA0 := X_FA,
    // z := 0) so the rotation-vector slip starts again from zero.
    void placeAnchor(SimTK::State& s, const SimTK::Transform& X_FM, const SimTK::Vec6& e) const {
        const SimTK::Transform X_AM(calcRotationFromVector(e.getSubVec<3>(0)), e.getSubVec<3>(3));
        SimTK::Value<SimTK::Transform>::updDowncast(forces_.updDiscreteVariable(s, baseIndex_)).upd() = X_FM * ~X_AM;
        forces_.updZ(s)(int(zIndex_), 6) = 0;
    }
    void resetAnchor(SimTK::State& s) const { placeAnchor(s, findX_FM(s), SimTK::Vec6(0)); }
    void setAnchorDisplacement(SimTK::State& s, const SimTK::Vec6& e) const { placeAnchor(s, findX_FM(s), e); }

    // ---- kinematics and law --------------------------------------------------------------
    SimTK::Transform findX_FM(const SimTK::State& s) const {
        const BushingFrames& frames = getFrames(s);
        const SimTK::Transform X_GF = bodyH_.getBodyTransform(s) * frames.X_HF;
        const SimTK::Transform X_GM = bodyO_.getBodyTransform(s) * frames.X_OM;
        return ~X_GF * X_GM;
    }
    SimTK::Vec6 findDisplacement(const SimTK::State& s) const { return calcDisplacement(findAnchorTransform(s), findX_FM(s)); }
    static SimTK::Vec6 calcDisplacement(const SimTK::Transform& X_FA, const SimTK::Transform& X_FM) {
        const SimTK::Transform X_AM = ~X_FA * X_FM;
        SimTK::Vec6 e;
        e.updSubVec<3>(0) = calcRotationVector(X_AM.R());
        e.updSubVec<3>(3) = X_AM.p();
        return e;
    }
    BushingKinematics findKinematics(const SimTK::State& s) const {
        BushingKinematics k;
        const SimTK::Transform X_GH = bodyH_.getBodyTransform(s);
        const SimTK::Transform X_GO = bodyO_.getBodyTransform(s);
        const SimTK::Transform X_FA = findAnchorTransform(s);
        const BushingFrames& frames = getFrames(s);
        k.R_GA = X_GH.R() * frames.X_HF.R() * X_FA.R();
        k.p_GM = X_GO * frames.X_OM.p();
        k.e = calcDisplacement(X_FA, findX_FM(s));
        // Velocity of O's material point at M relative to H's coincident point: the rate of
        // p_FM taken in F. Using the coincident point keeps H's rotation out of the slip.
        const SimTK::SpatialVec& V_GH = bodyH_.getBodyVelocity(s);
        const SimTK::SpatialVec& V_GO = bodyO_.getBodyVelocity(s);
        const SimTK::Vec3 v_GH_M = V_GH[1] + V_GH[0] % (k.p_GM - X_GH.p());
        const SimTK::Vec3 v_GO_M = V_GO[1] + V_GO[0] % (k.p_GM - X_GO.p());
        k.r.updSubVec<3>(0) = ~k.R_GA * (V_GO[0] - V_GH[0]);
        k.r.updSubVec<3>(3) = ~k.R_GA * (v_GO_M - v_GH_M);
        return k;
    }
    BushingResponse calcResponse(const SimTK::State& s, const BushingKinematics& k) const {
        const AxisSettings& settings = getSettings(s);
        const SimTK::Vec6 upper = applyAxisLocks(settings.limits, settings.locked);
        const SimTK::Vec6 lower = applyAxisLocks(settings.lowerLimits, settings.locked);
        // The per-axis law in terms of the elastic load (K e)_k, a unit stiffness: the same numbers
        // as K_k and e_k for a diagonal K (K_k > 0), and the coupled matrix's load otherwise.
        const SimTK::Vec6 load = calcElasticLoad(settings, k.e);
        BushingResponse response;
        for (int i = 0; i < 6; ++i) {
            response.slip[i] = calcTwoSidedSlipFraction(1, lower[i], upper[i], onsetWidth_, load[i], k.r[i]);
            const double edot = (1 - response.slip[i]) * k.r[i];
            response.force[i] = calcTwoSidedAxisForce(1, settings.damping[i], lower[i], upper[i], load[i], edot);
        }
        return response;
    }
    // Kinematics and response in `s`, once per realization: calcForce, realizeDynamics and the
    // accessors below (the grasp switch's Q at every check) all read them. Needs Stage::Velocity.
    const BushingEvaluation& findEvaluation(const SimTK::State& s) const {
        if (forces_.isCacheValueRealized(s, evaluationIndex_)) {
            return SimTK::Value<BushingEvaluation>::downcast(forces_.getCacheEntry(s, evaluationIndex_)).get();
        }
        BushingEvaluation& evaluation =
            SimTK::Value<BushingEvaluation>::updDowncast(forces_.updCacheEntry(s, evaluationIndex_)).upd();
        evaluation.kinematics = findKinematics(s);
        evaluation.response = calcResponse(s, evaluation.kinematics);
        forces_.markCacheValueRealized(s, evaluationIndex_);
        return evaluation;
    }
    SimTK::SpatialVec findWrench(const SimTK::State& s) const {
        if (!isEnabled(s)) return SimTK::SpatialVec(SimTK::Vec3(0), SimTK::Vec3(0));
        const BushingEvaluation& evaluation = findEvaluation(s);
        const SimTK::Vec6& f = evaluation.response.force;
        const SimTK::Rotation& R_GA = evaluation.kinematics.R_GA;
        return SimTK::SpatialVec(R_GA * f.getSubVec<3>(0), R_GA * f.getSubVec<3>(3));
    }
    bool isSliding(const SimTK::State& s, int axis) const {
        if (!isEnabled(s)) return false;
        return findEvaluation(s).response.slip[axis] >= 0.5;
    }
    SimTK::Vec6 findGeneralizedForce(const SimTK::State& s) const {
        if (!isEnabled(s)) return SimTK::Vec6(0);
        return findEvaluation(s).response.force;
    }

    // ---- Force::Custom -------------------------------------------------------------------
    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override {
        if (!isEnabled(s)) return;
        const BushingEvaluation& evaluation = findEvaluation(s);
        const BushingKinematics& k = evaluation.kinematics;
        const SimTK::Vec6& f = evaluation.response.force;
        const SimTK::Vec3 M_G = k.R_GA * f.getSubVec<3>(0);
        const SimTK::Vec3 F_G = k.R_GA * f.getSubVec<3>(3);
        // Both bodies take the force at M's origin, so the pair adds no spurious moment.
        const SimTK::Vec3 p_OM_G = k.p_GM - bodyO_.getBodyOriginLocation(s);
        const SimTK::Vec3 p_HM_G = k.p_GM - bodyH_.getBodyOriginLocation(s);
        bodyForces[bodyO_.getMobilizedBodyIndex()] += SimTK::SpatialVec(M_G + p_OM_G % F_G, F_G);
        bodyForces[bodyH_.getMobilizedBodyIndex()] -= SimTK::SpatialVec(M_G + p_HM_G % F_G, F_G);
    }

    // zdot is a Dynamics-stage result (writable while realizing Dynamics), so every integrator
    // sees the anchor as one more continuous state.
    void realizeDynamics(const SimTK::State& s) const override {
        SimTK::Vector& zdot = forces_.updZDot(s);
        zdot(int(zIndex_), 6) = 0;
        if (!isEnabled(s)) return;
        const BushingEvaluation& evaluation = findEvaluation(s);
        const BushingKinematics& k = evaluation.kinematics;
        const BushingResponse& response = evaluation.response;
        SimTK::Vec3 w_A0A_A, v_A0A_A;  // the anchor's own motion in F (= in A0), in A
        for (int i = 0; i < 3; ++i) {
            w_A0A_A[i] = response.slip[i] * k.r[i];
            v_A0A_A[i] = response.slip[i + 3] * k.r[i + 3];
        }
        const SimTK::Vec3 zRotation = getAnchorSlip(s).getSubVec<3>(0);
        const SimTK::Vec3 zRotationDot = calcRotationVectorRate(zRotation, w_A0A_A);
        const SimTK::Vec3 zPositionDot = calcRotationFromVector(zRotation) * v_A0A_A;
        for (int i = 0; i < 3; ++i) {
            zdot[int(zIndex_) + i] = zRotationDot[i];
            zdot[int(zIndex_) + 3 + i] = zPositionDot[i];
        }
    }

    // Elastic energy (1/2) e^T K e only; slip dissipates and is not recoverable.
    SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override {
        if (!isEnabled(s)) return 0;
        const SimTK::Vec6 e = findDisplacement(s);
        const AxisSettings& settings = getSettings(s);
        if (settings.coupled) return 0.5 * (~e * calcElasticLoad(settings, e));
        double energy = 0;
        for (int k = 0; k < 6; ++k) energy += 0.5 * settings.stiffness[k] * e[k] * e[k];
        return energy;
    }

private:
    const SimTK::GeneralForceSubsystem& forces_;
    SimTK::MobilizedBody bodyH_;
    BushingFrames defaultFrames_;
    SimTK::MobilizedBody bodyO_;
    SimTK::Vec6 stiffness_;
    SimTK::Vec6 damping_;
    double onsetWidth_ = 0.01;
    mutable SimTK::DiscreteVariableIndex enabledIndex_;
    mutable SimTK::DiscreteVariableIndex settingsIndex_;
    mutable SimTK::DiscreteVariableIndex baseIndex_;
    mutable SimTK::DiscreteVariableIndex framesIndex_;
    mutable SimTK::CacheEntryIndex evaluationIndex_;
    mutable SimTK::ZIndex zIndex_;
};

namespace {

const LimitedBushingImpl& asBushingImpl(const SimTK::Force::Custom::Implementation& impl) {
    return static_cast<const LimitedBushingImpl&>(impl);
}

LimitedBushingImpl* makeBushingImpl(SimTK::GeneralForceSubsystem& forces,
                                    const SimTK::MobilizedBody& H, const SimTK::Transform& X_HF,
                                    const SimTK::MobilizedBody& O, const SimTK::Transform& X_OM,
                                    const SimTK::Vec6& stiffness, const SimTK::Vec6& damping) {
    checkAxisValues(stiffness, "stiffness", false, false);
    checkAxisValues(damping, "damping", true, false);
    if (H.getMobilizedBodyIndex() == O.getMobilizedBodyIndex()) {
        throw InputError("limited bushing: body H and body O are the same body (index " +
                         std::to_string(int(H.getMobilizedBodyIndex())) + ")");
    }
    return new LimitedBushingImpl(forces, H, X_HF, O, X_OM, stiffness, damping);
}

}  // namespace

LimitedBushing::LimitedBushing(SimTK::GeneralForceSubsystem& forces,
                               const SimTK::MobilizedBody& bodyH, const SimTK::Transform& X_HF,
                               const SimTK::MobilizedBody& bodyO, const SimTK::Transform& X_OM,
                               const SimTK::Vec6& stiffness, const SimTK::Vec6& damping)
    : SimTK::Force::Custom(
          forces, makeBushingImpl(forces, bodyH, X_HF, bodyO, X_OM, stiffness, damping)) {}

const SimTK::Vec6& LimitedBushing::getStiffness() const {
    return asBushingImpl(getImplementation()).getStiffness();
}
const SimTK::MobilizedBody& LimitedBushing::getObjectBody() const {
    return asBushingImpl(getImplementation()).getBodyO();
}
const SimTK::Vec6& LimitedBushing::getDamping() const {
    return asBushingImpl(getImplementation()).getDamping();
}
double LimitedBushing::getSlipOnsetWidth() const {
    return asBushingImpl(getImplementation()).getSlipOnsetWidth();
}
void LimitedBushing::setSlipOnsetWidth(double width) {
    if (!(width > 0 && width <= 1)) {
        throw InputError("limited bushing slip onset width is " + std::to_string(width) +
                         "; accepted: (0, 1]");
    }
    static_cast<LimitedBushingImpl&>(updImplementation()).setSlipOnsetWidth(width);
}

bool LimitedBushing::isEnabled(const SimTK::State& state) const {
    return asBushingImpl(getImplementation()).isEnabled(state);
}
void LimitedBushing::setEnabled(SimTK::State& state, bool enabled) const {
    asBushingImpl(getImplementation()).setEnabled(state, enabled);
}

const SimTK::Vec6& LimitedBushing::getLimits(const SimTK::State& state) const {
    return asBushingImpl(getImplementation()).getSettings(state).limits;
}
const SimTK::Vec6& LimitedBushing::getLowerLimits(const SimTK::State& state) const {
    return asBushingImpl(getImplementation()).getSettings(state).lowerLimits;
}
void LimitedBushing::setLimits(SimTK::State& state, const SimTK::Vec6& limits) const { setLimits(state, limits, limits); }
void LimitedBushing::setLimits(SimTK::State& state, const SimTK::Vec6& lower, const SimTK::Vec6& upper) const {
    checkAxisValues(lower, "lower limit", true, true);
    checkAxisValues(upper, "limit", true, true);
    const LimitedBushingImpl& bushingImpl = asBushingImpl(getImplementation());
    AxisSettings settings = bushingImpl.getSettings(state);
    settings.limits = upper;
    settings.lowerLimits = lower;
    bushingImpl.setSettings(state, settings);
}
const SimTK::Vec6& LimitedBushing::getStiffness(const SimTK::State& state) const {
    return asBushingImpl(getImplementation()).getSettings(state).stiffness;
}
const SimTK::Vec6& LimitedBushing::getDamping(const SimTK::State& state) const {
    return asBushingImpl(getImplementation()).getSettings(state).damping;
}
void LimitedBushing::setStiffness(SimTK::State& state, const SimTK::Vec6& stiffness,
                                  const SimTK::Vec6& damping) const {
    checkAxisValues(stiffness, "stiffness", false, false);
    checkAxisValues(damping, "damping", true, false);
    const LimitedBushingImpl& bushingImpl = asBushingImpl(getImplementation());
    AxisSettings settings = bushingImpl.getSettings(state);
    settings.stiffness = stiffness;
    settings.damping = damping;
    settings.coupled = false;
    bushingImpl.setSettings(state, settings);
}
void LimitedBushing::setStiffness(SimTK::State& state, const SimTK::Mat66& stiffness, const SimTK::Vec6& damping) const {
    checkStiffnessMatrix(stiffness);
    checkAxisValues(damping, "damping", true, false);
    const LimitedBushingImpl& bushingImpl = asBushingImpl(getImplementation());
    AxisSettings settings = bushingImpl.getSettings(state);
    for (int k = 0; k < 6; ++k) settings.stiffness[k] = stiffness(k, k);
    settings.damping = damping;
    settings.coupled = true;
    settings.stiffnessMatrix = stiffness;
    bushingImpl.setSettings(state, settings);
}
SimTK::Mat66 LimitedBushing::findStiffnessMatrix(const SimTK::State& state) const {
    const AxisSettings& settings = asBushingImpl(getImplementation()).getSettings(state);
    if (settings.coupled) return settings.stiffnessMatrix;
    SimTK::Mat66 K;
    for (int r = 0; r < 6; ++r) {
        for (int c = 0; c < 6; ++c) K(r, c) = r == c ? settings.stiffness[r] : 0.0;
    }
    return K;
}
bool LimitedBushing::isAxisLocked(const SimTK::State& state, BushingAxis axis) const {
    return asBushingImpl(getImplementation()).getSettings(state).locked[toIndex(axis)];
}
void LimitedBushing::setAxisLocked(SimTK::State& state, BushingAxis axis, bool locked) const {
    const LimitedBushingImpl& bushingImpl = asBushingImpl(getImplementation());
    AxisSettings settings = bushingImpl.getSettings(state);
    settings.locked[toIndex(axis)] = locked;
    bushingImpl.setSettings(state, settings);
}
SimTK::Vec6 LimitedBushing::findEffectiveLimits(const SimTK::State& state) const {
    const AxisSettings& settings = asBushingImpl(getImplementation()).getSettings(state);
    return applyAxisLocks(settings.limits, settings.locked);
}
SimTK::Vec6 LimitedBushing::findEffectiveLowerLimits(const SimTK::State& state) const {
    const AxisSettings& settings = asBushingImpl(getImplementation()).getSettings(state);
    return applyAxisLocks(settings.lowerLimits, settings.locked);
}

void LimitedBushing::setFrames(SimTK::State& state, const SimTK::Transform& X_HF,
                               const SimTK::Transform& X_OM) const {
    asBushingImpl(getImplementation()).setFrames(state, BushingFrames{X_HF, X_OM});
}
const SimTK::Transform& LimitedBushing::getFrameOnH(const SimTK::State& state) const {
    return asBushingImpl(getImplementation()).getFrames(state).X_HF;
}
const SimTK::Transform& LimitedBushing::getFrameOnO(const SimTK::State& state) const {
    return asBushingImpl(getImplementation()).getFrames(state).X_OM;
}

void LimitedBushing::resetAnchor(SimTK::State& state) const {
    asBushingImpl(getImplementation()).resetAnchor(state);
}
void LimitedBushing::setAnchorDisplacement(SimTK::State& state, const SimTK::Vec6& e) const {
    asBushingImpl(getImplementation()).setAnchorDisplacement(state, e);
}
SimTK::Transform LimitedBushing::findAnchorTransform(const SimTK::State& state) const {
    return asBushingImpl(getImplementation()).findAnchorTransform(state);
}
SimTK::Vec6 LimitedBushing::findDisplacement(const SimTK::State& state) const {
    return asBushingImpl(getImplementation()).findDisplacement(state);
}
SimTK::Vec6 LimitedBushing::findGeneralizedForce(const SimTK::State& state) const {
    return asBushingImpl(getImplementation()).findGeneralizedForce(state);
}
SimTK::SpatialVec LimitedBushing::findWrench(const SimTK::State& state) const {
    return asBushingImpl(getImplementation()).findWrench(state);
}
bool LimitedBushing::isSliding(const SimTK::State& state, BushingAxis axis) const {
    return asBushingImpl(getImplementation()).isSliding(state, toIndex(axis));
}

SimTK::SpatialVec LimitedBushing::findReactionOnObject(const SimTK::State& state) const {
    const SimTK::MobilizedBody& bodyO = getObjectBody();
    return shiftToObjectOrigin(findWrench(state), bodyO.getBodyTransform(state).R(), getFrameOnO(state).p());
}

std::optional<SingleConstraintState> LimitedBushing::findSingleConstraintState(const SimTK::State& state) const {
    if (!isEngaged(state)) return std::nullopt;
    return SingleConstraintState{getFrameOnO(state), findEffectiveLimits(state), findGeneralizedForce(state), findWrench(state),
                                 findEffectiveLowerLimits(state)};
}

}  // namespace graspsim::grasp
