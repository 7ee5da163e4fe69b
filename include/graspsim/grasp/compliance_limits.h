#pragma once
/// @file
/// Two-sided per-axis limits of the approximation's palm-object constraint from the compliance
/// model of the grasp (compliant_grasp_capacity.h): FrictionLimitModel::Compliance.
///
/// For each axis k of the constraint frame M (rotation about M's x, y, z first, then translation
/// along them) and each sign, the model follows a load along (or a torque about) that axis through
/// M's origin from the grasp at engagement and reports its slip onset c(+-e_k): the load at which
/// the largest displacement of a contact's material point reaches `slipDistance`, or at which the
/// grasp can carry no more, whichever comes first (CompliantCapacity::onset; the same figure the
/// capacity ramp measures at the grasp goals). The contacts carry the wrench W0 (about M's
/// origin, in M) at engagement, which the constraint takes over (the object's weight); a load s
/// along +e_k leaves the constraint W0 - s e_k to carry, so its force on the object along the
/// axis must stay in
///
///     [-L-_k, +L+_k],   L-_k = c(+e_k) - W0_k,   L+_k = W0_k + c(-e_k)   (each at least 0).
///
/// A side the model never lets go of up to `maxLoads` (a load that presses the object into the
/// fingers) gets maxLoads_k, which keeps the stiffened bushing's stiffness finite.
///
/// For a stiff two-finger pinch carrying a weight W by friction, along the weight's line the onsets
/// are 2 mu N + W (lifting) and 2 mu N - W, so both sides are 2 mu N: the limit bounds the total
/// friction force, as the thesis's box does; along the pinch axis the sides differ (the finger a
/// load pulls away from lets go first): tests/grasp/compliance_limits_test.cpp.

#include "graspsim/grasp/compliant_grasp_capacity.h"

#include <Eigen/Core>

#include <limits>
#include <vector>

namespace graspsim::grasp {

/// Options of calcComplianceLimits.
struct ComplianceLimitOptions {
    double mu = 0.7;             ///< friction coefficient of every contact's cone (>= 0): where it breaks loose
    /// Kinetic friction coefficient of a contact once it slides, in [0, mu]; NaN (default): mu
    /// (CompliantCapacityOptions::kineticMu).
    double kineticMu = std::numeric_limits<double>::quiet_NaN();
    double slipDistance = 2e-3;  ///< m (> 0): the displacement that counts as slip onset
    /// Where the slip is measured (m, in G; CompliantCapacityOptions::slipPoints_G): the grasp
    /// goals; empty: the contact points.
    std::vector<Eigen::Vector3d> slipPoints_G;
    /// Per axis (N m for 0-2, N for 3-5; each > 0): the most a side's limit can be.
    Eigen::Matrix<double, 6, 1> maxLoads = Eigen::Matrix<double, 6, 1>::Constant(1e3);
};

/// Two-sided per-axis limits, rotation first (N m for 0-2, N for 3-5), each >= 0: the force on the
/// object along axis k stays in [-lower_k, +upper_k].
struct TwoSidedLimits {
    Eigen::Matrix<double, 6, 1> lower = Eigen::Matrix<double, 6, 1>::Zero();
    Eigen::Matrix<double, 6, 1> upper = Eigen::Matrix<double, 6, 1>::Zero();
};

/// The contacts' total wrench on the object about p_GM (m, in G), expressed in M (orientation
/// R_GM): moment (N m) first, then force (N).
Eigen::Matrix<double, 6, 1> calcContactWrenchInM(const std::vector<CompliantContact>& contacts, const Eigen::Matrix3d& R_GM,
                                                 const Eigen::Vector3d& p_GM);

/// The limits of the file comment for the grasp `contacts` (at engagement) and the constraint
/// frame M (orientation R_GM in G, origin p_GM in G, m).
/// @throws graspsim::InputError for invalid contacts or options (non-positive maxLoads).
TwoSidedLimits calcComplianceLimits(const std::vector<CompliantContact>& contacts, const Eigen::Matrix3d& R_GM,
                                    const Eigen::Vector3d& p_GM, const ComplianceLimitOptions& options);

}  // namespace graspsim::grasp
