#pragma once
/// @file
/// The friction limits of the approximation's 6-DOF palm-object constraint: how much force along,
/// and torque about, each axis of the constraint frame M the replaced contacts could carry.
///
/// Two models here (a third, Compliance, is compliance_limits.h: two-sided limits from the
/// compliance model of the grasp, which needs the fingers' compliance from the simulation layer):
///  - Thesis (section 4.2, eq. 4.1-4.3): one box, mu F_perp on every translation axis and
///    mu r F_perp on every rotation axis, with F_perp the summed normal forces and r the mean
///    distance of the contacts from their centroid. It ignores which way each contact faces, so a
///    two-finger pinch gets the same torque limit about the pinch axis (where point contacts give
///    none) as about the axes across it (where the finger separation gives a lever).
///  - ContactGeometry: per axis, the largest load the contacts' friction can carry along that axis
///    alone, with each contact's normal force fixed at its value at engagement:
///      along the unit axis e:   mu sum_i N_i |P_i e|
///      about the unit axis a:   mu sum_i N_i |P_i (a x r_i)|
///    where P_i = 1 - n_i n_i^T projects onto contact i's tangent plane and r_i is the contact
///    point from M's origin. Each term is the most a friction force of magnitude mu N_i in the
///    tangent plane can contribute (Cauchy-Schwarz, reached with the force along the projected
///    direction). Point contacts carry no torsion, as in graspsim's full compliant contact, so
///    contacts on the pinch axis give no torque about it. A load that is not along one axis may
///    still exceed what the contacts carry together: like the thesis's, the limits are a box.

#include "graspsim/grasp/grasp_contact.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace graspsim::grasp {

/// How the approximation's constraint limits are derived from the contacts at engagement.
enum class FrictionLimitModel {
    Thesis,          ///< thesis eq. 4.1-4.3: mu F_perp and mu r F_perp on every axis (the default)
    ContactGeometry,  ///< per axis, from each contact's normal and position (file comment)
    /// two-sided per axis, the compliance model's slip onset along and about each axis
    /// (compliance_limits.h); needs the bushing
    Compliance
};

/// "thesis", "contact" or "compliance", the spelling of the command line.
std::string toString(FrictionLimitModel model);

/// Parses "thesis", "contact" or "compliance".
/// @throws graspsim::InputError naming `what`, the value and the accepted spellings.
FrictionLimitModel parseFrictionLimitModel(const std::string& text, const std::string& what);

/// Per-axis limits of the ContactGeometry model, rotation first: torques about M's x, y, z
/// (N m), then forces along M's x, y, z (N).
/// @param contacts contact points and normals in G (m), with their normal forces N_i (N).
/// @param mu friction coefficient (>= 0).
/// @param R_GM orientation of the constraint frame M in G; p_GM its origin in G (m).
/// @throws graspsim::InputError for a negative or non-finite mu.
Eigen::Matrix<double, 6, 1> calcContactGeometryLimits(const std::vector<GraspContact>& contacts, double mu,
                                                      const Eigen::Matrix3d& R_GM, const Eigen::Vector3d& p_GM);

}  // namespace graspsim::grasp
