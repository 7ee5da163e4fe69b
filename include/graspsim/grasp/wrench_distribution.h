#pragma once
/// @file
/// Contact forces that reproduce a given wrench on the object: how the grasp approximation
/// estimates the forces at the fingertips while one constraint, not the contacts, holds the
/// object (the thesis keeps monitoring the grasp quality while engaged, chapter 4: the quality
/// is built from the constraint's reaction wrench distributed over the tracked contacts). Plain
/// Eigen, no Simbody.
///
/// Problem. N contacts at points C_i (G), inward unit normals n_i (G), and a wrench W on the
/// object (force F (N) and moment M (N m) about O's origin, both expressed in G) are given.
/// Find forces f_i (G) with sum f_i = F and sum (p_OC_i x f_i) = M that stay as close as
/// possible to given reference forces f0_i:
///
///     minimize  sum |f_i - f0_i|^2   subject to   A f = W,
///     f = f0 + A^+ (W - A f0)        (A: the 6 x 3N map of calcContactWrenchMap, torqueScale 1),
///
/// with A^+ the Moore-Penrose pseudo-inverse, so a wrench the contacts cannot produce at all
/// (e.g. torsion about the line through two point contacts) is met in the least-squares sense.
/// Each f_i is then projected onto its friction cone (normal part clipped at 0, tangential part
/// scaled down to at most mu times the normal part), and the part of W the projected forces
/// miss is reported.
///
/// Why a reference f0 rather than the least-norm solution (f0 = 0): a wrench fixes the forces only
/// up to the internal (squeezing) forces in the null space of A, and the least-norm answer has no
/// squeeze at all, so its normal forces, and a grasp quality built from them, say nothing about
/// how hard the fingers press. With f0 the contact forces at the moment the constraint took over,
/// the squeeze the locked fingers keep applying is carried over, and only the change of the load
/// is distributed (least-norm). Pass zeros for the least-norm forces.

#include "graspsim/grasp/grasp_contact.h"

#include <Eigen/Core>

#include <vector>

namespace graspsim::grasp {

/// The contact forces of distributeWrench().
struct WrenchDistribution {
    /// f_i on the object, expressed in G (N), inside each contact's friction cone; in contact order.
    std::vector<Eigen::Vector3d> forces_G;
    /// Normal part n_i . f_i of each force (N, >= 0).
    std::vector<double> normalForces;
    /// |W - A f| after the cone projection, force and moment rows together (N and N m): the part of
    /// W the contacts, within friction, do not reproduce (0 when they can carry it).
    double residual = 0;
};

/// Distributes `wrench_G` = [moment about O's origin (N m); force (N)] (Simbody's SpatialVec
/// order: rotation first), expressed in G, over `contacts` (their p_GC and n_G are used; their
/// normalForce and t_G are ignored), staying closest to `referenceForces_G` (one per contact, N,
/// in G). `mu` is the friction coefficient of the cones (>= 0).
/// @throws graspsim::InputError if the sizes differ, mu is negative or not finite, a normal is
///         not a unit vector (to 1e-6), or any input is not finite.
WrenchDistribution distributeWrench(const std::vector<GraspContact>& contacts, const ObjectFrame& frame,
                                    const Eigen::Matrix<double, 6, 1>& wrench_G,
                                    const std::vector<Eigen::Vector3d>& referenceForces_G, double mu);

}  // namespace graspsim::grasp
