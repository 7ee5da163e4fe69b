#pragma once
/// @file
/// The force Jacobians (integration/force_jacobian.h) of the friction-limited bushing
/// (limited_bushing.h), so that the linearly implicit stepper treats the engaged approximation's
/// stiff spring-damper implicitly.
///
/// With J the 6 x nu relative Jacobian of M with respect to F, expressed in the anchor frame A
/// (rows 0-2: angular velocity of O relative to H; rows 3-5: velocity of M's origin relative to
/// the point of H at it), the bushing's generalized force is J^T f, and per axis k below its limit
/// df_k = -K_k de_k - D_k dedot_k with de = J dx and dedot = J du, so
///
///     D += -J^T diag(D_k) J,   K += -J^T diag(K_k) J,
///
/// leaving out the rotation-vector chart's and the frames' turning (second order in the small
/// elastic displacement). An axis that slides (LimitedBushing::isSliding: its force at the limit,
/// the anchor following M) contributes nothing: its force no longer changes with the motion.
/// A disabled (released) bushing contributes nothing.

#include "graspsim/grasp/limited_bushing.h"
#include "graspsim/integration/force_jacobian.h"

#include <vector>

namespace graspsim::grasp {

/// The Jacobians of one LimitedBushing between `bodyH` and `bodyO` (the bodies it was built on;
/// handles are kept, the element must outlive this).
class LimitedBushingJacobian : public integration::ForceJacobianContributor {
public:
    LimitedBushingJacobian(const SimTK::SimbodyMatterSubsystem& matter, const LimitedBushing& bushing,
                           const SimTK::MobilizedBody& bodyH, const SimTK::MobilizedBody& bodyO);
    void addForceJacobians(const SimTK::State& state, SimTK::Matrix& D, SimTK::Matrix& K) const override;
    /// 0 when enabled, then 1 + k for every axis k that holds (does not slide: its stiffness is in
    /// K); nothing when disabled.
    void appendActiveSet(const SimTK::State& state, std::vector<int>& active) const override;

private:
    // J (6 x nu, column-major) in A's axes at `state`.
    void fillRelativeJacobian(const SimTK::State& state, std::vector<double>& J) const;

    const SimTK::SimbodyMatterSubsystem& matter_;
    LimitedBushing bushing_;
    SimTK::MobilizedBody bodyH_, bodyO_;
};

}  // namespace graspsim::grasp
