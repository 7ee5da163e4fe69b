#pragma once
/// @file
/// The force Jacobians (force_jacobian.h) of the joints' linear impedance: passive springs and
/// dampers, PD gains and limit stops, as listed for the rigid model's implicit correction
/// (system/implicit_joint_impedance.h), so the linearly implicit stepper treats them implicitly.

#include "graspsim/integration/force_jacobian.h"
#include "graspsim/system/implicit_joint_impedance.h"

#include <vector>

namespace graspsim::integration {

/// Diagonal D and K of the listed joints: D_ii -= C_j, K_ii -= K_j on joint j's mobility i, plus
/// a violated stop's linearization (stop force -k x (1 + d u) for a violation x > 0: stiffness k,
/// damping k d x). Gravity compensation and the other q-dependent forces are left explicit.
class JointImpedanceJacobian : public ForceJacobianContributor {
public:
    /// `joints` on mobilizers of one mobility each (Pin or Slider); `forces` holds their stops.
    JointImpedanceJacobian(const SimTK::SimbodyMatterSubsystem& matter, const SimTK::GeneralForceSubsystem& forces,
                           std::vector<system::JointImpedance> joints);
    /// @throws graspsim::InputError for a joint whose mobilizer has other than one mobility.
    void addForceJacobians(const SimTK::State& state, SimTK::Matrix& D, SimTK::Matrix& K) const override;
    /// The mobilized body index of every joint whose limit stop is engaged (violated).
    void appendActiveSet(const SimTK::State& state, std::vector<int>& active) const override;
    /// The stop's violation of the joint on mobilized body `id` (rad or m; NaN for a joint without
    /// an enabled stop).
    double findTermMargin(const SimTK::State& state, int id) const override;

private:
    const SimTK::SimbodyMatterSubsystem& matter_;
    const SimTK::GeneralForceSubsystem& forces_;
    std::vector<system::JointImpedance> joints_;
};

}  // namespace graspsim::integration
