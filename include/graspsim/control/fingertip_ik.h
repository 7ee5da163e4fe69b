#pragma once
/// @file
/// Inverse kinematics that brings fingertip end-effectors to goal points, with Simbody's Assembler.
///
/// Only the given joints move; every other mobilizer of the system (the rest of the arm, the
/// grasped object) is locked. Joint ranges of motion bound the solution. The Assembler minimizes
/// the weighted sum of squared distances between each end-effector and its goal (a least-squares
/// fit, so unreachable goals give the closest pose rather than a failure).

#include "graspsim/system/multibody_model.h"

#include "graspsim/simbody.h"

#include <memory>
#include <string>
#include <vector>

namespace graspsim::control {

/// Fingertip inverse kinematics on a model's system.
class FingertipIk {
public:
    /// @param endEffectors names of the end-effectors to place (e.g. "index_tip").
    /// @param movingJoints joints the solution may change; all other mobilities are locked.
    /// @throws graspsim::InputError naming an unknown end-effector or joint.
    FingertipIk(const system::MultibodyModel& model, const std::vector<std::string>& endEffectors,
                const std::vector<std::string>& movingJoints);
    ~FingertipIk();
    FingertipIk(const FingertipIk&) = delete;
    FingertipIk& operator=(const FingertipIk&) = delete;

    /// Solves from the joint angles in `state` for end-effector goals p_GE* (m, ground, in the
    /// order of `endEffectors`). Returns the moving joints' angles (rad), in their given order.
    SimTK::Vector solve(const SimTK::State& state, const std::vector<SimTK::Vec3>& goals_G);

    /// Root-mean-square distance between end-effectors and goals after the last solve (m).
    double getLastError() const { return lastError_; }

    /// Distance between each end-effector and its goal after the last solve (m), in the order of
    /// `endEffectors`: how far the least-squares fit left each one short.
    const std::vector<double>& getLastDistances() const { return lastDistances_; }

private:
    const system::MultibodyModel& model_;
    std::vector<std::string> movingJoints_;
    std::vector<SimTK::MobilizedBodyIndex> movingBodies_;
    std::unique_ptr<SimTK::Assembler> assembler_;
    SimTK::Markers* markers_ = nullptr;  // owned by assembler_
    double lastError_ = 0;
    std::vector<double> lastDistances_;
};

}  // namespace graspsim::control
