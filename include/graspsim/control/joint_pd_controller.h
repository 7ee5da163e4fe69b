#pragma once
/// @file
/// Joint-space PD control toward target angles, with gravity compensation, as a Simbody force.
///
/// For each controlled joint j: tau_j = kp_j (q*_j - q_j) - kd_j u_j + g_j(q) (N m), where q*_j
/// is the target (rad) held in a discrete state variable, and g_j(q) is the torque that holds the
/// arm's own weight at the current pose (the negative of gravity's generalized force on the
/// controlled bodies), so that the gains only have to move the arm, not hold it up.
///
/// Targets change in one of two ways. setTargets() makes them jump: the torques jump with them,
/// a Stage::Dynamics change after which an integrator must restart. rampTargets() plans a move
/// from their value at a later start t0 to new ones along a smoothstep in time,
/// q*(t) = a + (b - a) s(tau), s = 3 tau^2 - 2 tau^3, tau = (t - t0)/T clamped to [0, 1]. The
/// torques stay continuous in time (continuously differentiable when ramps follow each other),
/// and nothing changes before t0: an integrator that has already stepped past the present
/// instant, by less than the delay t0 - t, computed those steps with the same targets. So the
/// change is only a Stage::Report one, which the integrator goes on through without restarting.

#include "graspsim/system/multibody_model.h"

#include "graspsim/simbody.h"

#include <string>
#include <vector>

namespace graspsim::control {

/// Proportional and derivative gains of one joint.
struct PdGains {
    double kp = 0;  ///< N m/rad
    double kd = 0;  ///< N m s/rad
};

/// One controlled joint: its name in the model and its gains.
struct ControlledJoint {
    std::string name;
    PdGains gains;
};

/// PD joint torques toward targets, added to the model's force subsystem.
class JointPdController {
public:
    /// Adds the controller to `model`'s forces. `gravityBodies` are the bodies whose weight is
    /// compensated (the arm's; not the grasped object's). Call model.realizeTopology() after.
    /// @throws graspsim::InputError naming an unknown joint or body.
    JointPdController(system::MultibodyModel& model, const std::vector<ControlledJoint>& joints,
                      const std::vector<std::string>& gravityBodies);

    /// Names of the controlled joints, in the order of the target vector.
    const std::vector<std::string>& getJointNames() const { return jointNames_; }
    /// The gains, ordered as getJointNames().
    const std::vector<PdGains>& getGains() const { return gains_; }

    /// Sets the targets q* (rad), ordered as getJointNames(), from now on. Invalidates Stage::Dynamics.
    void setTargets(SimTK::State& state, const SimTK::Vector& targets) const;
    /// Moves the targets to `targets` (rad) over `duration` (s, > 0) along a smoothstep that starts
    /// `delay` (s, >= 0) after the state's time, or when the ramps already planned end if later.
    /// Invalidates only Stage::Report (see the file comment).
    void rampTargets(SimTK::State& state, const SimTK::Vector& targets, double duration, double delay) const;
    /// The targets q* (rad) in effect at the state's time.
    SimTK::Vector getTargets(const SimTK::State& state) const;
    /// The joints' current angles (rad), ordered as getJointNames().
    SimTK::Vector findJointAngles(const SimTK::State& state) const;

private:
    class Implementation;
    std::vector<std::string> jointNames_;
    std::vector<PdGains> gains_;
    const Implementation* impl_ = nullptr;  // owned by the Force::Custom handle in the subsystem
};

}  // namespace graspsim::control
