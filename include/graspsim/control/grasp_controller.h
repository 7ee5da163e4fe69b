#pragma once
/// @file
/// The thesis's grasp controller (section 4.1): fingertips tracked to goal points on the object by
/// inverse kinematics, joints driven toward the IK solution by PD torques.
///
/// Every `ikInterval` seconds (a Simbody periodic event) the goals, fixed in a goal frame F, are
/// carried to ground with that frame's current pose, IK solves for the finger joints, and the PD
/// targets move to the new solution along a smoothstep over the next interval (a first-order hold
/// that keeps the torques continuous, so the integrator goes on without restarting); the arm
/// joints keep their grasp-pose targets. Goals sit inside the
/// object's surface, so the fingers press and contact force builds up.
///
/// Which frame: the goals are points on the object as it sits when the grasp is formed, held
/// fixed to the hand (F = the palm). Fixing them to the object instead would make the fingers
/// chase a slipping object: every slip would move the goals with it, an equilibrium with no
/// restoring force, and the grasp would drift without any load.

#include "graspsim/control/fingertip_ik.h"
#include "graspsim/control/joint_pd_controller.h"

#include "graspsim/simbody.h"

#include <chrono>
#include <string>
#include <vector>

namespace graspsim::control {

/// A goal for one end-effector (a fingertip pad or a point on another segment, fingertip_ik.h):
/// a point fixed in the goal frame F.
struct FingertipGoal {
    std::string endEffector;  ///< e.g. "index_tip" or "index_middle_radial"
    SimTK::Vec3 p_FG;         ///< goal point in F (m)
};

/// Time spent in inverse kinematics, for the per-step cost split the thesis reports.
struct IkTiming {
    long solves = 0;          ///< IK solutions computed
    double totalSeconds = 0;  ///< wall-clock time in IK (s)
    double lastError = 0;     ///< RMS fingertip-goal distance of the last solution (m)
};

/// Periodic event handler that updates the PD targets from fingertip IK.
class GraspController : public SimTK::PeriodicEventHandler {
public:
    /// @param pd controller whose targets are updated; its joints must include `ikJoints`.
    /// @param ik solver over `ikJoints` for the goals' end-effectors, in the goals' order.
    /// @param goalFrame the body whose frame F carries the goals (the palm).
    GraspController(const JointPdController& pd, FingertipIk& ik, std::vector<std::string> ikJoints,
                    const SimTK::MobilizedBody& goalFrame, double ikInterval, IkTiming& timing);

    /// Sets the goals, in the goal-end-effector order the IK was built with.
    void setGoals(std::vector<FingertipGoal> goals) { goals_ = std::move(goals); }

    void handleEvent(SimTK::State& state, SimTK::Real accuracy, bool& shouldTerminate) const override;

    /// Runs one IK update on `state` now (the simulation calls it once at t = 0).
    void updateTargets(SimTK::State& state) const;

    /// The IK solver (its last solution's fingertip-goal distances, for the set-up check).
    const FingertipIk& getIk() const { return ik_; }

private:
    const JointPdController& pd_;
    FingertipIk& ik_;
    std::vector<int> targetSlots_;  // position of each IK joint in the PD target vector
    const SimTK::MobilizedBody& goalFrame_;
    std::vector<FingertipGoal> goals_;
    IkTiming& timing_;
};

}  // namespace graspsim::control
