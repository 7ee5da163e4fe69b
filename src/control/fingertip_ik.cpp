#include "graspsim/control/fingertip_ik.h"

#include "graspsim/error.h"

#include <algorithm>
#include <memory>
#include <cmath>

namespace graspsim::control {

FingertipIk::FingertipIk(const system::MultibodyModel& model, const std::vector<std::string>& endEffectors,
                         const std::vector<std::string>& movingJoints)
    : model_(model), movingJoints_(movingJoints), assembler_(std::make_unique<SimTK::Assembler>(model.getSystem())) {
    const model::ModelDescription& d = model.getDescription();
    const SimTK::SimbodyMatterSubsystem& matter = model.getMatter();
    for (const std::string& joint : movingJoints) {
        const model::Joint* j = d.findJoint(joint);
        if (!j || j->type == model::Joint::Type::Fixed) throw InputError("IK: no movable joint named '" + joint + "'");
        const SimTK::MobilizedBody& mobod = model.getMobilizedBody(j->child);
        movingBodies_.push_back(mobod.getMobilizedBodyIndex());
        if (j->hasLimits()) assembler_->restrictQ(mobod.getMobilizedBodyIndex(), SimTK::MobilizerQIndex(0), j->lower, j->upper);
    }
    // Lock everything that is not a moving joint: the rest of the arm and any grasped object.
    for (SimTK::MobilizedBodyIndex b(1); b < matter.getNumBodies(); ++b) {
        if (std::find(movingBodies_.begin(), movingBodies_.end(), b) == movingBodies_.end()) assembler_->lockMobilizer(b);
    }
    // Owned here until the assembler adopts it, so that an unknown name below leaks nothing.
    auto markers = std::make_unique<SimTK::Markers>();
    SimTK::Array_<SimTK::Markers::MarkerIx> order;
    for (const std::string& name : endEffectors) {
        const model::EndEffector* e = d.findEndEffector(name);
        if (!e) throw InputError("IK: no end-effector named '" + name + "'");
        const SimTK::Vec3 p_BE(e->p_BE[0], e->p_BE[1], e->p_BE[2]);
        order.push_back(markers->addMarker(name, model.getMobilizedBody(e->body), p_BE));
    }
    markers->defineObservationOrder(order);
    markers_ = markers.get();
    assembler_->adoptAssemblyGoal(markers.release());
    assembler_->setAccuracy(1e-6);
}

FingertipIk::~FingertipIk() = default;

namespace {

// Whether `body` moves with any of the IK's moving joints (it is one of them or outboard of one).
bool movesWith(const SimTK::MobilizedBody& body, const std::vector<SimTK::MobilizedBodyIndex>& moving) {
    for (const SimTK::MobilizedBody* b = &body; !b->isGround(); b = &b->getParentMobilizedBody()) {
        if (std::find(moving.begin(), moving.end(), b->getMobilizedBodyIndex()) != moving.end()) return true;
    }
    return false;
}

bool involvesMovingBodies(const SimTK::Constraint& constraint, const std::vector<SimTK::MobilizedBodyIndex>& moving) {
    for (SimTK::ConstrainedBodyIndex k(0); k < constraint.getNumConstrainedBodies(); ++k) {
        if (movesWith(constraint.getMobilizedBodyFromConstrainedBody(k), moving)) return true;
    }
    for (SimTK::ConstrainedMobilizerIndex k(0); k < constraint.getNumConstrainedMobilizers(); ++k) {
        if (movesWith(constraint.getMobilizedBodyFromConstrainedMobilizer(k), moving)) return true;
    }
    return false;
}

// The Assembler satisfies every enabled constraint of its state, but two kinds are not part of
// the hand's kinematics. Conditional constraints (rigid contacts, enabled while touching): the IK
// places the fingertips at their goals as if nothing were in the way, and contact pushes back in
// the dynamics. Constraints among bodies no moving joint moves (the Ground weld holding an object
// before its release): the IK cannot change them, so they would only fail the assembly when the
// integrator holds them to a looser tolerance than the Assembler's. Returns nullptr when `state`
// has none enabled (no copy needed).
std::unique_ptr<SimTK::State> withoutUnreachableConstraints(const SimTK::SimbodyMatterSubsystem& matter,
                                                            const SimTK::State& state,
                                                            const std::vector<SimTK::MobilizedBodyIndex>& moving) {
    std::unique_ptr<SimTK::State> copy;
    for (SimTK::ConstraintIndex c(0); c < matter.getNumConstraints(); ++c) {
        const SimTK::Constraint& constraint = matter.getConstraint(c);
        if (constraint.isDisabled(state)) continue;
        if (!constraint.isConditional() && involvesMovingBodies(constraint, moving)) continue;
        if (!copy) copy = std::make_unique<SimTK::State>(state);
        constraint.disable(*copy);
    }
    return copy;
}

}  // namespace

SimTK::Vector FingertipIk::solve(const SimTK::State& state, const std::vector<SimTK::Vec3>& goals_G) {
    SimTK::Array_<SimTK::Vec3> observations(goals_G.begin(), goals_G.end());
    markers_->moveAllObservations(observations);
    const std::unique_ptr<SimTK::State> unconstrained = withoutUnreachableConstraints(model_.getMatter(), state, movingBodies_);
    try {
        // The locked joints (arm, object) come from `state`; the Assembler starts the moving
        // joints from there too, which keeps consecutive solutions close (warm start).
        assembler_->initialize(unconstrained ? *unconstrained : state);
        assembler_->assemble();
    } catch (const std::exception& e) {
        throw Error(std::string("fingertip IK failed at t = ") + std::to_string(state.getTime()) + " s: " + e.what());
    }
    const SimTK::State& solved = assembler_->getInternalState();
    double sumSquares = 0;
    lastDistances_.clear();
    for (SimTK::Markers::MarkerIx m(0); m < markers_->getNumMarkers(); ++m) {
        const double squared = markers_->findCurrentMarkerErrorSquared(m);
        sumSquares += squared;
        lastDistances_.push_back(std::sqrt(squared));
    }
    lastError_ = std::sqrt(sumSquares / std::max(1, markers_->getNumMarkers()));
    SimTK::Vector q(static_cast<int>(movingBodies_.size()));
    for (std::size_t k = 0; k < movingBodies_.size(); ++k) {
        q[static_cast<int>(k)] = model_.getMatter().getMobilizedBody(movingBodies_[k]).getOneQ(solved, 0);
    }
    return q;
}

}  // namespace graspsim::control
