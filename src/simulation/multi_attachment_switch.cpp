#include "graspsim/simulation/multi_attachment_switch.h"

#include "graspsim/error.h"
#include "graspsim/grasp/limited_bushing_law.h"
#include "graspsim/grasp/multi_attachment.h"
#include "graspsim/model/body_model.h"
#include "graspsim/simulation/grasp_switch.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace graspsim::simulation {

namespace {

// One point contact (or none) cannot hold an object against a general load.
constexpr int kMinAttachedFingers = 2;

// The bodies from an end-effector's body up to (not including) the palm.
std::vector<std::string> findDigitBodies(const model::ModelDescription& d, const std::string& endEffector) {
    std::vector<std::string> bodies;
    std::string body = d.findEndEffector(endEffector)->body;
    while (d.findBody(body)->role != model::BodyRole::Palm) {
        bodies.push_back(body);
        const model::Joint* j = d.findParentJoint(body);
        if (!j) throw Error("end-effector '" + endEffector + "' does not hang from a palm");
        body = j->parent;
    }
    return bodies;
}

std::string format(const char* pattern, double a, double b = 0) {
    char buffer[200];
    std::snprintf(buffer, sizeof buffer, pattern, a, b);
    return buffer;
}

// Eq. 4.1-4.3 over one finger's contacts; the force is the one on the object (b), in Ground.
// The part's site: the centroid of the contacts, the object's outward normal their mean -n.
grasp::FingerLoad calcFingerLoad(const std::vector<const contact::ContactReport*>& contacts) {
    grasp::FingerLoad load;
    if (contacts.empty()) return load;
    SimTK::Vec3 centroid(0), inward(0);
    for (const contact::ContactReport* c : contacts) {
        const SimTK::Vec3 f = c->normalForce * SimTK::Vec3(c->n_G) + c->frictionForce_G;
        load.force_G += f;
        load.normalForce += ~f * SimTK::Vec3(c->n_G);
        centroid += c->p_G;
        inward += SimTK::Vec3(c->n_G);
    }
    centroid /= static_cast<double>(contacts.size());
    load.atContact = inward.norm() > 0;
    load.contact_G = centroid;
    if (load.atContact) load.normal_G = -inward / inward.norm();
    for (const contact::ContactReport* c : contacts) load.armRadius += (c->p_G - centroid).norm();
    load.armRadius /= static_cast<double>(contacts.size());
    load.normalForce = std::max(0.0, load.normalForce);
    return load;
}

}  // namespace

MultiAttachmentSwitch::MultiAttachmentSwitch(const ApproximationContext& context, double slideLimit, double penetrationBound)
    : context_(context), slideLimit_(slideLimit), penetrationBound_(penetrationBound) {
    const model::ModelDescription& d = context.model.getDescription();
    const contact::CompliantContactForce& contacts = context.contacts;
    for (const std::string& endEffector : context.goals.getEndEffectors()) {
        fingerBodies_.push_back(findDigitBodies(d, endEffector));
        fingerPairs_.emplace_back();
    }
    for (int p = 0; p < contacts.getNumPairs(); ++p) {
        const int finger = findFinger(contacts.getPair(p).a.bodyName);
        if (finger >= 0) fingerPairs_[static_cast<std::size_t>(finger)].push_back(p);
    }
}

int MultiAttachmentSwitch::findFinger(const std::string& body) const {
    for (std::size_t i = 0; i < fingerBodies_.size(); ++i) {
        if (std::find(fingerBodies_[i].begin(), fingerBodies_[i].end(), body) != fingerBodies_[i].end()) {
            return static_cast<int>(i);
        }
    }
    return -1;
}

const contact::ContactReport* MultiAttachmentSwitch::findSlidingContact(const std::vector<contact::ContactReport>& reports) const {
    const double limit = context_.contactParameters.transitionVelocity;
    for (const contact::ContactReport& c : reports) {
        if (findFinger(c.bodyA) >= 0 && !(c.slipVelocity_G.norm() < limit)) return &c;
    }
    return nullptr;
}

std::string MultiAttachmentSwitch::engage(SimTK::State& state, const std::vector<contact::ContactReport>& reports) const {
    std::vector<std::vector<const contact::ContactReport*>> perFinger(fingerBodies_.size());
    for (const contact::ContactReport& c : reports) {
        const int finger = findFinger(c.bodyA);
        if (finger >= 0) perFinger[static_cast<std::size_t>(finger)].push_back(&c);
    }
    // Only the goal digits' pairs: the palm and digits without a goal stay in ordinary contact.
    std::vector<int> replaced;
    for (const std::vector<int>& pairs : fingerPairs_) replaced.insert(replaced.end(), pairs.begin(), pairs.end());
    context_.contacts.setPairsEnabled(state, replaced, false);
    grasp::AttachmentEngagement engagement;
    engagement.mu = context_.contactParameters.dynamicFriction;
    engagement.penetrationBound = penetrationBound_;
    std::string text = "multi: tangent limits";
    for (std::size_t i = 0; i < perFinger.size(); ++i) {
        grasp::FingerLoad load = calcFingerLoad(perFinger[i]);
        load.tangentHint_G = context_.gravity_G;  // the main load: exact along it
        engagement.fingers.push_back(load);
        text += " " + context_.goals.getEndEffectors()[i] + format(" %.4g N", engagement.mu * load.normalForce);
    }
    context_.multi->engage(state, engagement);
    return text;
}

std::string MultiAttachmentSwitch::update(SimTK::State& state, double quality, std::vector<GraspEvent>& events) const {
    const grasp::MultiAttachment& multi = *context_.multi;
    context_.model.getSystem().realize(state, SimTK::Stage::Velocity);
    std::vector<std::pair<int, std::string>> leaving;
    for (int i = 0; i < multi.getNumParts(); ++i) {
        if (!multi.isAttached(state, i)) continue;
        const std::string reason = describeDetach(state, i);
        if (!reason.empty()) leaving.emplace_back(i, reason);
    }
    for (const auto& [i, reason] : leaving) {
        multi.detach(state, i);
        context_.contacts.setPairsEnabled(state, fingerPairs_[static_cast<std::size_t>(i)], true);
        events.push_back({state.getTime(), GraspEventKind::Detach, quality, context_.goals.getEndEffectors()[static_cast<std::size_t>(i)] + ": " + reason});
    }
    const int attached = multi.countAttached(state);
    if (attached >= kMinAttachedFingers) return {};
    return format("%.0f finger(s) still attached (at least %.0f needed)", attached, kMinAttachedFingers);
}

// Empty while finger i still holds; needs Stage::Velocity.
std::string MultiAttachmentSwitch::describeDetach(const SimTK::State& state, int finger) const {
    const grasp::MultiAttachment& multi = *context_.multi;
    const double pressing = multi.findPressingForce(state, finger);
    if (!(pressing > 0)) return format("stopped pressing (normal force %.4g N)", pressing);
    const double slide = multi.findSlide(state, finger);
    if (slide > slideLimit_) return format("slid %.4g m on the object (limit %.4g m)", slide, slideLimit_);
    const double distance = context_.goals.findDistance(state, static_cast<std::size_t>(finger));
    const double tolerance = context_.heldTolerance;
    if (distance > tolerance) return format("fingertip %.4g m from its goal (held tolerance %.4g m)", distance, tolerance);
    return {};
}

double MultiAttachmentSwitch::findSmallestPressing(const SimTK::State& state) const {
    const grasp::MultiAttachment& multi = *context_.multi;
    double smallest = SimTK::Infinity;
    for (int i = 0; i < multi.getNumParts(); ++i) {
        if (multi.isAttached(state, i)) smallest = std::min(smallest, multi.findPressingForce(state, i));
    }
    return smallest;
}

void MultiAttachmentSwitch::release(SimTK::State& state) const {
    context_.multi->detachAll(state);
    const contact::CompliantContactForce& contacts = context_.contacts;
    contacts.setPairsEnabled(state, contacts.findAllPairIndices(), true);
}

}  // namespace graspsim::simulation
