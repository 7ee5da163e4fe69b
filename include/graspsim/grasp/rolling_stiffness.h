#pragma once
/// @file
/// The geometric ("rolling") stiffness of a preloaded grasp: how the contact forces already on the
/// object change their wrench about its centre of mass when the object moves a little, at fixed
/// force magnitudes (Cutkosky and Kao 1989, the term a grasp's stiffness adds to the springs').
///
/// Model. Contact i (point C_i, inward normal n_i, force f_i on the object, in G) is two convex
/// surfaces touching: the finger's, curvature k_f (1/m; its centre c_f = C - n / k_f, fixed with
/// the finger) and the object's, curvature k_o (centre c_o = C + n / k_o, a material point of the
/// object). Under a small object displacement delta = [dp ; theta] (force rows first, dp of the
/// centre of mass O, theta a rotation vector; m and rad, in G), with u = dp + theta x (C - O):
///
///     the normal turns with the line of centres:  dn = k_f k_o / (k_f + k_o) (I - n n^T) u
///                                                       + k_f / (k_f + k_o) theta x n
///     the force turns with it (fixed magnitude):  df = (n x dn) x f
///     the contact point moves along that line:    dC = k_o / (k_f + k_o) u + 1 / (k_f + k_o) theta x n
///     the wrench about the moving O changes by:   dF = df,  dM = (dC - dp) x f + (C - O) x df
///
/// G = sum_i d[dF ; dM] / d delta (6 x 6, force first, N/m, N, N m/rad); a spring grasp's
/// stiffness is then sum_i D_i K_i D_i^T - G. A plate of thickness 2a pinched by two spherical
/// pads of radius rho with force N gains 2 N (rho + a) about an axis across the pinch, and nothing
/// about the pinch axis. A contact whose curvatures are both 0 (the default: geometry unknown, or
/// two flat faces) adds nothing. The fingers' own give under the force is left out of the
/// geometry (it enters the springs only).

#include "graspsim/grasp/compliant_grasp_capacity.h"

#include <Eigen/Core>

#include <vector>

namespace graspsim::grasp {

/// One contact's part of G (file comment) with the force `force_G` on the object (N, in G) in place
/// of the contact's force_G, about the centre of mass p_GO (m, in G): 6 x 6, rows and columns force
/// first ([force ; moment] by [dp ; theta]). Zero when both curvatures are 0.
/// @throws graspsim::InputError for a negative or non-finite curvature.
Eigen::Matrix<double, 6, 6> calcRollingStiffness(const CompliantContact& contact, const Eigen::Vector3d& force_G,
                                                 const Eigen::Vector3d& p_GO);

/// G of the file comment: the sum of the contacts' parts at their forces force_G.
Eigen::Matrix<double, 6, 6> calcRollingStiffness(const std::vector<CompliantContact>& contacts, const Eigen::Vector3d& p_GO);

}  // namespace graspsim::grasp
