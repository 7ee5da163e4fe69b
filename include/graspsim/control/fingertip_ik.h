#pragma once
/// @file
/// Inverse kinematics that brings end-effectors to goal points.
///
/// An end-effector is any named point of the model description (model::EndEffector): the
/// fingertip pads the hand builder makes, or a point fixed on any other segment that the build
/// options add (model::SegmentPoint, e.g. the radial side of the index's middle phalanx, on
/// which a lateral pinch presses). Each is placed by the moving joints on its path from the base.
///
/// Only the given joints move; every other mobilizer of the system (the rest of the arm, the
/// grasped object) is locked. Joint ranges of motion bound the solution. The solution minimizes
/// the sum of squared distances between each end-effector and its goal (a least-squares fit, so
/// unreachable goals give the closest pose rather than a failure), starting from the state's
/// joint angles (a warm start: consecutive solutions stay close).
///
/// Two methods find it. The default, damped least squares (Levenberg-Marquardt with the joint
/// ranges as bounds), computes the end-effectors' positions and Jacobian along their chains of
/// mobilizers without touching the system and costs tens of microseconds. Simbody's Assembler,
/// the other, re-initializes a general optimizer on every solve (about a millisecond); it also
/// honours the system's constraints among the moving joints, so the default falls back to it
/// when such a constraint is enabled. docs/performance.md compares the two.

#include "graspsim/system/multibody_model.h"

#include "graspsim/simbody.h"

#include <memory>
#include <string>
#include <vector>

namespace graspsim::control {

class FingerChains;

/// How FingertipIk finds its least-squares pose.
enum class IkMethod {
    DampedLeastSquares,  ///< bounded Levenberg-Marquardt along the fingers' chains (fast, default)
    Assembler            ///< Simbody's Assembler (the reference the default is tested against)
};

/// Fingertip inverse kinematics on a model's system.
class FingertipIk {
public:
    /// @param endEffectors names of the end-effectors to place (e.g. "index_tip", "index_middle_radial").
    /// @param movingJoints joints the solution may change; all other mobilities are locked.
    /// @param method which solver to use.
    /// @throws graspsim::InputError naming an unknown end-effector or joint.
    FingertipIk(const system::MultibodyModel& model, const std::vector<std::string>& endEffectors,
                const std::vector<std::string>& movingJoints, IkMethod method = IkMethod::DampedLeastSquares);
    ~FingertipIk();
    FingertipIk(const FingertipIk&) = delete;
    FingertipIk& operator=(const FingertipIk&) = delete;

    /// Solves from the joint angles in `state` for end-effector goals p_GE* (m, ground, in the
    /// order of `endEffectors`). Returns the moving joints' angles (rad), in their given order.
    SimTK::Vector solve(const SimTK::State& state, const std::vector<SimTK::Vec3>& goals_G);

    /// Root-mean-square distance between end-effectors and goals after the last solve (m).
    double getLastError() const { return lastError_; }
    /// Iterations of the last damped-least-squares solve (0 after an Assembler solve).
    int getLastIterations() const { return lastIterations_; }

    /// Distance between each end-effector and its goal after the last solve (m), in the order of
    /// `endEffectors`: how far the least-squares fit left each one short.
    const std::vector<double>& getLastDistances() const { return lastDistances_; }

private:
    SimTK::Vector solveWithAssembler(const SimTK::State& state, const std::vector<SimTK::Vec3>& goals_G);
    SimTK::Vector solveWithDampedLeastSquares(const SimTK::State& state, const std::vector<SimTK::Vec3>& goals_G);
    bool hasConstraintOnMovingJoints(const SimTK::State& state) const;

    const system::MultibodyModel& model_;
    std::vector<std::string> movingJoints_;
    std::vector<SimTK::MobilizedBodyIndex> movingBodies_;
    std::unique_ptr<SimTK::Assembler> assembler_;
    SimTK::Markers* markers_ = nullptr;  // owned by assembler_
    std::unique_ptr<FingerChains> chains_;
    IkMethod method_;
    double lastError_ = 0;
    std::vector<double> lastDistances_;
    int lastIterations_ = 0;
};

}  // namespace graspsim::control
