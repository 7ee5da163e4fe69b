#include "graspsim/simulation/engaged_grasp_tracker.h"

#include "graspsim/grasp/grasp_quality.h"
#include "graspsim/grasp/wrench_distribution.h"
#include "graspsim/simulation/contact_grasp_quality.h"
#include "graspsim/system/simtk_conversion.h"

#include <algorithm>
#include <iterator>
#include <numeric>

namespace graspsim::simulation {

namespace {

grasp::ObjectFrame toObjectFrame(const SimTK::Transform& X_GO) {
    grasp::ObjectFrame frame;
    frame.R_GO = system::toEigenMatrix(X_GO.R());
    frame.p_GO = system::toEigenVector(X_GO.p());
    return frame;
}

}  // namespace

EngagedGraspTracker::EngagedGraspTracker(const ApproximationContext& context) : context_(&context) {}

void EngagedGraspTracker::capture(const SimTK::State& state, const std::vector<contact::ContactReport>& reports) {
    const SimTK::Transform& X_GH = context_->palm.getBodyTransform(state);
    const SimTK::Transform& X_GO = context_->object.getBodyTransform(state);
    tracked_.clear();
    depthAtEngage_.clear();
    penetration_.atEngage = 0;
    for (const contact::ContactReport& c : reports) {
        depthAtEngage_[c.pairIndex] = std::max(depthAtEngage_[c.pairIndex], c.depth);
        penetration_.atEngage = std::max(penetration_.atEngage, c.depth);
        if (!(c.normalForce > 0)) continue;
        const SimTK::Vec3 f_G = c.normalForce * SimTK::Vec3(c.n_G) + c.frictionForce_G;
        tracked_.push_back({~X_GH * c.p_G, ~X_GO.R() * f_G, ~X_GO.R() * SimTK::Vec3(c.n_G)});
    }
    penetration_.maxWhileEngaged = std::max(penetration_.maxWhileEngaged, penetration_.atEngage);
}

// The constraint's wrench on the object with its moment taken about O's origin (the centre of
// mass), where the grasp quality takes moments. A weld's reaction is a Lagrange multiplier
// (Acceleration), a bushing's a force of the state (Velocity): realizing only what the attachment
// needs spares a forward-dynamics solve per check.
SimTK::SpatialVec EngagedGraspTracker::findConstraintWrench(const SimTK::State& state) const {
    const grasp::GraspAttachment& attachment = context_->attachment;
    context_->model.getSystem().realize(state, attachment.getReactionStage());
    return attachment.findReactionOnObject(state);
}

double EngagedGraspTracker::calcQuality(const SimTK::State& state) const {
    if (tracked_.empty()) return 0;
    const SimTK::SpatialVec W = findConstraintWrench(state);
    const SimTK::Transform& X_GH = context_->palm.getBodyTransform(state);
    const SimTK::Transform& X_GO = context_->object.getBodyTransform(state);
    std::vector<grasp::GraspContact> contacts;
    std::vector<Eigen::Vector3d> reference;
    for (const TrackedContact& t : tracked_) {
        grasp::GraspContact c;
        // The normal as the contact had it, turned with the object: the face it pressed. Taken
        // again from the shape at the palm-fixed point, a pad near an edge of a box that had
        // pivoted in the hand got the neighbouring face's normal, its captured force pointed out
        // of the object, and Q fell to 0 on the first check (the engage/release chatter of a
        // loaded pinch, docs/capacity.md).
        c.p_GC = system::toEigenVector(X_GH * t.p_HC);
        c.n_G = system::toEigenVector(X_GO.R() * t.n_O).normalized();
        contacts.push_back(c);
        reference.push_back(system::toEigenVector(X_GO.R() * t.f_O));
    }
    Eigen::Matrix<double, 6, 1> wrench;
    wrench << system::toEigenVector(W[0]), system::toEigenVector(W[1]);
    const grasp::QualityOptions options = makeQualityOptions(context_->contactParameters);
    const grasp::ObjectFrame frame = toObjectFrame(X_GO);
    const grasp::WrenchDistribution d = grasp::distributeWrench(contacts, frame, wrench, reference, options.mu);
    for (std::size_t i = 0; i < contacts.size(); ++i) contacts[i].normalForce = d.normalForces[i];
    return grasp::calcGraspQuality(contacts, frame, options);
}

double EngagedGraspTracker::measurePenetration(const SimTK::State& state) {
    // Only the pairs the approximation has switched off: those in ordinary contact (with multi,
    // the palm and digits without a goal) compress under load as they would in full contact.
    const contact::CompliantContactForce& pairs = context_->contacts;
    std::vector<int> replaced;
    for (int k = 0; k < pairs.getNumPairs(); ++k) {
        if (!pairs.isPairEnabled(state, k)) replaced.push_back(k);
    }
    std::vector<int>& seen = penetration_.replacedPairs;
    if (!std::includes(seen.begin(), seen.end(), replaced.begin(), replaced.end())) {
        std::vector<int> all;
        std::set_union(seen.begin(), seen.end(), replaced.begin(), replaced.end(), std::back_inserter(all));
        seen = std::move(all);
    }
    context_->model.getSystem().realize(state, SimTK::Stage::Position);
    double deepest = 0, growthNow = 0;
    for (const contact::ContactDepth& c : pairs.findContactDepths(state, replaced)) {
        deepest = std::max(deepest, c.depth);
        const auto engaged = depthAtEngage_.find(c.pairIndex);
        growthNow = std::max(growthNow, c.depth - (engaged == depthAtEngage_.end() ? 0.0 : engaged->second));
    }
    penetration_.maxGrowth = std::max(penetration_.maxGrowth, growthNow);
    penetration_.maxWhileEngaged = std::max(penetration_.maxWhileEngaged, deepest);
    return growthNow;
}

}  // namespace graspsim::simulation
