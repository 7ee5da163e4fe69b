#pragma once
/// @file
/// How a scene holds the object at its initial pose until the scenario's approach time
/// (grasp_scene.h): by locking its Free mobilizer from Ground, or, when the object hangs from the
/// palm (the merged weld), by a SimTK::Constraint::Weld to Ground. A plain value: the grasp
/// switch asks it whether the object is still held without referring to the scene.

#include "graspsim/simbody.h"

namespace graspsim::simulation {

/// The object's hold until its release (see the file comment). Copies refer to the same elements.
class ObjectHold {
public:
    ObjectHold() = default;
    /// @param object the object's mobilized body (its frame O).
    /// @param groundWeld the Weld from Ground to O that holds it, or an empty handle when the
    ///        object's mobilizer is Free from Ground and the hold is its lock.
    ObjectHold(const SimTK::MobilizedBody& object, const SimTK::Constraint::Weld& groundWeld)
        : object_(object), groundWeld_(groundWeld) {}

    /// Whether the hold is the Weld to Ground (else the mobilizer's lock).
    bool isByGroundWeld() const { return !groundWeld_.isEmptyHandle(); }
    /// Whether the object is still held at its initial pose (not yet released). Any stage.
    bool isHeld(const SimTK::State& state) const;
    /// Lets the object go (unlocks its mobilizer or disables the Weld): an Instance-stage change.
    void release(SimTK::State& state) const;

private:
    SimTK::MobilizedBody object_;
    SimTK::Constraint::Weld groundWeld_;
};

}  // namespace graspsim::simulation
