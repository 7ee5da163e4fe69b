#pragma once
/// @file
/// The per-axis elasto-plastic law and the rotation-vector chart of grasp::LimitedBushing, as
/// plain functions so they can be tested against closed forms without a multibody system.
///
/// One axis (rotation: rad, N m, rad/s; translation: m, N, m/s) has stiffness K > 0, damping
/// D >= 0 and limit L >= 0 (+Infinity for a locked axis); its state is the displacement e from
/// the anchor, and r is the rate of the relative coordinate (e's rate if the anchor stood still).

#include "graspsim/simbody.h"

#include <array>

namespace graspsim::grasp {

/// Fraction s of the relative rate r that the anchor takes over (zdot = s r).
/// s = 0 unless the axis is loading (e r > 0); then s = g(u), u = K |e| / L, with g = 0 below
/// 1 - w, the C1 smoothstep 3 t^2 - 2 t^3, t = (u - 1 + w) / w, up to u = 1 (g = 1), and
/// g = 1 + ((u - 1) / w)^2 above: beyond the limit the anchor outruns the motion slightly,
/// which returns |K e| to L (corrects integrator overshoot and drift of e while sliding).
/// L = +Infinity gives 0; L = 0 gives 1 for any loading e != 0.
/// @param onsetWidth w in (0, 1]: the band of |K e| / L below 1 in which slip begins.
double calcSlipFraction(double stiffness, double limit, double onsetWidth, double e, double r);

/// Force (N or N m) on the axis: clamp(-K e - D edot, -L, +L), edot the elastic rate
/// (1 - s) r.
double calcAxisForce(double stiffness, double damping, double limit, double e, double edot);

/// Two-sided limits (an axis whose force may lie in [-L-, +L+]): the limit of the side the elastic
/// force -K e points to, L+ for e < 0 and L- otherwise (N m or N). Sliding is decided by that
/// side's limit: a load that presses the axis toward +L+ slips at L+, one toward -L- at L-.
double findLoadedSideLimit(double lower, double upper, double e);

/// calcSlipFraction with the limit of the loaded side (findLoadedSideLimit): identical to it for
/// lower == upper.
double calcTwoSidedSlipFraction(double stiffness, double lower, double upper, double onsetWidth, double e, double r);

/// Force (N or N m) on a two-sided axis: clamp(-K e - D edot, -L-, +L+); calcAxisForce for
/// lower == upper.
double calcTwoSidedAxisForce(double stiffness, double damping, double lower, double upper, double e, double edot);

/// The limits with the locked axes' set to +Infinity.
SimTK::Vec6 applyAxisLocks(const SimTK::Vec6& limits, const std::array<bool, 6>& locked);

/// Per axis the larger of two one-sided limits (N m, N): what a two-sided axis must be stiff enough for.
SimTK::Vec6 findLargerSide(const SimTK::Vec6& lower, const SimTK::Vec6& upper);

/// Stiffness per axis for which loads up to `loads` (N m on rotations 0-2, N on translations 3-5)
/// move a point at `leverArm` (m) from the frame origin by at most `bound` (m): each of the two
/// parts, |e_p| <= sqrt(3) L_t / K_t and leverArm |e_r| <= sqrt(3) leverArm L_r / K_r, gets half
/// of it, so K_t >= 2 sqrt(3) L_t / bound and K_r >= 2 sqrt(3) leverArm L_r / bound; never below
/// `minimum` (N m/rad, N/m).
SimTK::Vec6 calcStiffnessForBound(const SimTK::Vec6& minimum, const SimTK::Vec6& loads, double leverArm, double bound);

/// Critical damping per axis of stiffness K on a rigid body of mass m (kg) and central principal
/// moments I (kg m^2): D_k = 2 sqrt(K_k I_k) on the rotations 0-2 (N m s/rad) and
/// D_k = 2 sqrt(K_k m) on the translations 3-5 (N s/m).
SimTK::Vec6 calcCriticalDamping(const SimTK::Vec6& stiffness, const SimTK::Vec3& centralMoments, double mass);

/// Whether the symmetric matrix K is positive definite (its Cholesky factorization succeeds).
bool isPositiveDefinite(const SimTK::Mat66& K);

/// Checks a coupled stiffness matrix (N m/rad, N/rad, N/m; rotation first): finite, symmetric to
/// 1e-9 relative, positive definite.
/// @throws graspsim::InputError naming the entry, or saying it is not positive definite.
void checkStiffnessMatrix(const SimTK::Mat66& K);

/// Rotation vector theta = angle * axis of R (angle in [0, pi]), rad.
SimTK::Vec3 calcRotationVector(const SimTK::Rotation& R);

/// The rotation exp([theta]x): angle |theta| about theta / |theta| (identity for theta = 0).
SimTK::Rotation calcRotationFromVector(const SimTK::Vec3& theta);

/// Time derivative of the rotation vector theta of R_PB (rad/s) for B's angular velocity in P
/// expressed in B, w_PB_B (rad/s): thetadot = w + theta x w / 2
/// + (1 - (phi / 2) cot(phi / 2)) / phi^2 theta x (theta x w), phi = |theta| (the inverse of
/// the right Jacobian of SO(3)). Singular at phi = 2 pi; accurate for phi well below it.
SimTK::Vec3 calcRotationVectorRate(const SimTK::Vec3& theta, const SimTK::Vec3& w_PB_B);

}  // namespace graspsim::grasp
