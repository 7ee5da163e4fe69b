#include "graspsim/grasp/limited_bushing.h"
#include "graspsim/grasp/limited_bushing_law.h"

#include <algorithm>

namespace graspsim::grasp {

namespace {

// The anchor's displacement at which the spring carries `load` (N m, N; clamped to the limits in force).
SimTK::Vec6 findPreloadDisplacement(const SimTK::Vec6& load, const SimTK::Vec6& lower, const SimTK::Vec6& upper,
                                    const SimTK::Vec6& stiffness, const std::optional<SimTK::Mat66>& stiffnessMatrix) {
    SimTK::Vec6 clamped;
    for (int k = 0; k < 6; ++k) clamped[k] = std::clamp(load[k], -lower[k], upper[k]);
    if (stiffnessMatrix) return -(stiffnessMatrix->invert() * clamped);
    SimTK::Vec6 e;
    for (int k = 0; k < 6; ++k) e[k] = -clamped[k] / stiffness[k];
    return e;
}

}  // namespace

// Defined apart from the element's law (limited_bushing.cpp): what the grasp switch asks of it.
// Order matters: enable (Instance), anchor at the current pose, then stiffness and limits, which
// move the anchor if the (zero) displacement were over them.
void LimitedBushing::engage(SimTK::State& state, const AttachmentEngagement& engagement) const {
    const SimTK::MobilizedBody& bodyO = getObjectBody();
    const SimTK::System& system = bodyO.getMatterSubsystem().getSystem();
    setFrames(state, engagement.X_HF, engagement.X_OM);
    setEnabled(state, true);
    system.realize(state, SimTK::Stage::Position);
    resetAnchor(state);
    const SimTK::MassProperties mp = bodyO.getBody().getDefaultRigidBodyMassProperties();
    const SimTK::Vec3 I = mp.calcCentralInertia().getMoments();
    const SimTK::Vec6 lower = engagement.lowerLimits.value_or(engagement.limits);
    SimTK::Vec6 stiffness = calcStiffnessForBound(getStiffness(), findLargerSide(lower, engagement.limits),
                                                  engagement.leverArm, engagement.penetrationBound);
    for (int k = 0; k < 6; ++k) {
        if (engagement.stiffness && (*engagement.stiffness)[k] > 0) stiffness[k] = (*engagement.stiffness)[k];
        if (engagement.stiffnessMatrix) stiffness[k] = (*engagement.stiffnessMatrix)(k, k);
    }
    if (engagement.stiffnessMatrix) {
        setStiffness(state, *engagement.stiffnessMatrix, calcCriticalDamping(stiffness, I, mp.getMass()));
    } else {
        setStiffness(state, stiffness, calcCriticalDamping(stiffness, I, mp.getMass()));
    }
    setLimits(state, lower, engagement.limits);
    for (int k = 0; k < 6; ++k) setAxisLocked(state, static_cast<BushingAxis>(k), engagement.lockedAxes[k]);
    if (engagement.preload) {
        setAnchorDisplacement(state, findPreloadDisplacement(*engagement.preload, findEffectiveLowerLimits(state),
                                                             findEffectiveLimits(state), stiffness, engagement.stiffnessMatrix));
    }
    system.realize(state, SimTK::Stage::Position);
}

}  // namespace graspsim::grasp
