#pragma once
/// @file
/// The fingertip goals of a grasp scene: each goal end-effector with its point T on the object's
/// surface (in the object frame O, not pressed in), and how far the fingertips are from them, the
/// measure of "held" (scenario simulation.held_tolerance) shared by the summary, the grasp switch
/// and the capacity runs.

#include "graspsim/system/multibody_model.h"

#include "graspsim/simbody.h"

#include <cstddef>
#include <string>
#include <vector>

namespace graspsim::simulation {

/// See the file comment. Refers to the model and the object's body, which must outlive it.
class FingertipGoals {
public:
    FingertipGoals() = default;
    FingertipGoals(const system::MultibodyModel& model, const SimTK::MobilizedBody& object)
        : model_(&model), object_(&object) {}

    /// Adds the goal of `endEffector` at p_OT, on the object's surface in O (m).
    void add(const std::string& endEffector, const SimTK::Vec3& p_OT);
    /// Names of the end-effectors that have goals, in goal order.
    const std::vector<std::string>& getEndEffectors() const { return endEffectors_; }
    /// The goals' points on the object's surface, in O (m), in goal order.
    const std::vector<SimTK::Vec3>& getSurfacePoints() const { return surfacePoints_; }
    /// Distance from goal k's end-effector to its surface point (m). Needs Stage::Position.
    double findDistance(const SimTK::State& state, std::size_t k) const;
    /// The largest of those distances (m): how far the object has left the hand. Realizes `state`
    /// to Stage::Position.
    double findMaxDistance(const SimTK::State& state) const;

private:
    const system::MultibodyModel* model_ = nullptr;
    const SimTK::MobilizedBody* object_ = nullptr;
    std::vector<std::string> endEffectors_;
    std::vector<SimTK::Vec3> surfacePoints_;
};

}  // namespace graspsim::simulation
