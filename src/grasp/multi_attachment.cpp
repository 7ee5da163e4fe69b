#include "graspsim/grasp/multi_attachment.h"

#include "graspsim/error.h"
#include "graspsim/grasp/limited_bushing_law.h"

#include <cmath>

#include <string>

namespace graspsim::grasp {

namespace {

constexpr int kNormal = toIndex(BushingAxis::TranslationZ);

// z axis along the outward normal n; x along the hint's tangent part, y = z x x.
SimTK::Rotation makeSiteRotation(const SimTK::UnitVec3& n, const SimTK::Vec3& hint) {
    const SimTK::Vec3 tangent = hint - (~hint * n) * n;
    if (tangent.norm() == 0 || !(tangent.norm() > 1e-9 * hint.norm())) return SimTK::Rotation(n, SimTK::ZAxis);
    return SimTK::Rotation(n, SimTK::ZAxis, tangent, SimTK::XAxis);
}

SimTK::Transform makeSiteTransform(const AttachmentSite& site) {
    return SimTK::Transform(makeSiteRotation(site.n_O, site.tangentHint_O), site.p_OS);
}

}  // namespace

MultiAttachment::MultiAttachment(SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& object,
                                 const std::vector<AttachmentSite>& sites, const SimTK::Vec6& stiffness,
                                 const SimTK::Vec6& damping) {
    if (sites.empty()) throw InputError("multi attachment: no attachment site (one per finger is needed)");
    for (const AttachmentSite& site : sites) {
        X_OS_.push_back(makeSiteTransform(site));
        fingers_.push_back(site.finger);
        parts_.emplace_back(forces, site.finger, SimTK::Transform(), object, X_OS_.back(), stiffness, damping);
        p_FA_attached_.emplace_back(forces, SimTK::Stage::Position, SimTK::Vec3(0));
    }
    object_ = object;
}

void MultiAttachment::checkPart(int i) const {
    if (i < 0 || i >= getNumParts()) {
        throw InputError("multi attachment: part " + std::to_string(i) + " does not exist (" +
                         std::to_string(getNumParts()) + " parts)");
    }
}

const LimitedBushing& MultiAttachment::getPart(int i) const {
    checkPart(i);
    return parts_[static_cast<std::size_t>(i)];
}

const SimTK::Transform& MultiAttachment::getSiteTransform(int i) const {
    checkPart(i);
    return X_OS_[static_cast<std::size_t>(i)];
}

void MultiAttachment::detachAll(SimTK::State& state) const {
    for (const LimitedBushing& part : parts_) part.setEnabled(state, false);
}

// Order matters: enable (Instance), anchor at the current pose, preload, then the limits, which
// turn any preload beyond them into slip at once (a finger whose contact was already sliding).
void MultiAttachment::attach(SimTK::State& state, int i, const FingerLoad& load, double mu) const {
    const LimitedBushing& part = getPart(i);
    const SimTK::MultibodySystem& system = SimTK::MultibodySystem::downcast(object_.getMatterSubsystem().getSystem());
    part.setEnabled(state, true);
    system.realize(state, SimTK::Stage::Position);
    const SimTK::Transform X_GO = object_.getBodyTransform(state);
    SimTK::Transform X_OS = getSiteTransform(i);
    if (load.atContact) {
        const SimTK::UnitVec3 n_G(load.normal_G);
        X_OS = ~X_GO * SimTK::Transform(makeSiteRotation(n_G, load.tangentHint_G), load.contact_G);
    }
    const SimTK::Transform X_HF = ~fingers_[static_cast<std::size_t>(i)].getBodyTransform(state) * X_GO * X_OS;
    part.setFrames(state, X_HF, X_OS);  // an Instance-stage change
    system.realize(state, SimTK::Stage::Position);
    part.resetAnchor(state);
    // The anchor frame A is the site frame S now; the part's force on O is -K e, so the preload
    // displacement is e = -f_A / K per translation axis.
    const SimTK::Rotation R_GA = X_GO.R() * X_OS.R();
    const SimTK::Vec3 f_A = ~R_GA * load.force_G;
    SimTK::Vec6 e(0);
    for (int k = 0; k < 3; ++k) e[3 + k] = -f_A[k] / part.getStiffness(state)[3 + k];
    part.setAnchorDisplacement(state, e);
    const double linear = mu * load.normalForce, angular = mu * load.armRadius * load.normalForce;
    part.setLimits(state, SimTK::Vec6(angular, angular, angular, linear, linear, linear));
    for (int k = 0; k < 6; ++k) part.setAxisLocked(state, static_cast<BushingAxis>(k), k == kNormal);
    p_FA_attached_[static_cast<std::size_t>(i)].setValue(state, part.findAnchorTransform(state).p());
}

void MultiAttachment::detach(SimTK::State& state, int i) const { getPart(i).setEnabled(state, false); }

bool MultiAttachment::isAttached(const SimTK::State& state, int i) const { return getPart(i).isEnabled(state); }

int MultiAttachment::countAttached(const SimTK::State& state) const {
    int n = 0;
    for (const LimitedBushing& part : parts_) n += part.isEnabled(state) ? 1 : 0;
    return n;
}

// The part's force on O along S's z (outward): pressing pushes O inward, so the pressing force is
// its negative.
double MultiAttachment::findPressingForce(const SimTK::State& state, int i) const {
    return -getPart(i).findGeneralizedForce(state)[kNormal];
}

double MultiAttachment::findSlide(const SimTK::State& state, int i) const {
    return (getPart(i).findAnchorTransform(state).p() - p_FA_attached_[static_cast<std::size_t>(i)].getValue(state)).norm();
}

void MultiAttachment::engage(SimTK::State& state, const AttachmentEngagement& engagement) const {
    if (engagement.fingers.size() != parts_.size()) {
        throw InputError("multi attachment: " + std::to_string(engagement.fingers.size()) + " finger loads for " +
                         std::to_string(getNumParts()) + " parts (one per part is needed)");
    }
    for (int i = 0; i < getNumParts(); ++i) {
        const FingerLoad& load = engagement.fingers[static_cast<std::size_t>(i)];
        stiffenPart(state, i, load, engagement.mu, engagement.penetrationBound);
        attach(state, i, load, engagement.mu);
    }
}

// As the palm bushing's (LimitedBushing::engage): the elastic displacement under the part's largest
// expected load stays within penetrationBound / (2 sqrt 3) per axis. The loads: its friction limits
// on the tangent and rotation axes, and on the locked normal axis its pressing force at attachment.
void MultiAttachment::stiffenPart(SimTK::State& state, int i, const FingerLoad& load, double mu,
                                  double penetrationBound) const {
    const LimitedBushing& part = getPart(i);
    const double tangent = mu * load.normalForce, moment = mu * load.armRadius * load.normalForce;
    const SimTK::Vec6 loads(moment, moment, moment, tangent, tangent, load.normalForce);  // z: the object's normal
    const SimTK::Vec6 stiffness = calcStiffnessForBound(part.getStiffness(), loads, load.armRadius, penetrationBound);
    SimTK::Vec6 damping = part.getDamping();
    for (int k = 0; k < 6; ++k) damping[k] *= std::sqrt(stiffness[k] / part.getStiffness()[k]);
    part.setStiffness(state, stiffness, damping);
}

SimTK::SpatialVec MultiAttachment::findReactionOnObject(const SimTK::State& state) const {
    const SimTK::Rotation& R_GO = object_.getBodyTransform(state).R();
    SimTK::SpatialVec W(SimTK::Vec3(0), SimTK::Vec3(0));
    for (const LimitedBushing& part : parts_) {
        if (part.isEnabled(state)) W += shiftToObjectOrigin(part.findWrench(state), R_GO, part.getFrameOnO(state).p());
    }
    return W;
}

bool MultiAttachment::isSliding(const SimTK::State& state, BushingAxis axis) const {
    for (const LimitedBushing& part : parts_) {
        if (part.isSliding(state, axis)) return true;
    }
    return false;
}

}  // namespace graspsim::grasp
