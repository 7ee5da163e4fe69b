#pragma once
/// @file
/// The Ferrari–Canny epsilon metric in the L1 wrench space (Ferrari & Canny 1992).
///
/// With unit normal forces, the wrenches a grasp can apply with total normal force at most 1 are
/// the convex hull W of the columns of G (and the origin). epsilon is the radius of the largest
/// ball centred at the origin that fits inside W: the magnitude of the smallest disturbance
/// wrench, in the worst direction, that the grasp can resist with unit total normal force.
/// It is positive exactly when the origin is strictly inside W, i.e. the grasp is force-closure.
/// Equivalently epsilon = min over unit directions d of max_j d . w_j (the support function of W),
/// attained at the facet normals: epsilon is the distance from the origin to the nearest facet.

#include <Eigen/Core>

namespace graspsim::grasp {

/// Ferrari–Canny epsilon of the 6 x n grasp matrix G (same units as G's entries).
/// Computes the convex hull of G's columns in 6-D with qhull and returns the smallest distance
/// from the origin to a facet hyperplane. Returns 0 when the origin is not strictly inside the
/// hull (not force-closure), and when the hull is lower-dimensional (fewer than 7 columns, or the
/// columns lie in a 5-D affine subspace to relative precision 1e-10): no 6-D ball fits inside.
/// @throws graspsim::InputError if G does not have 6 rows or has a non-finite entry.
/// @throws graspsim::NumericalError if qhull fails on a full-dimensional input (precision or
/// topology error), with qhull's message.
double calcFerrariCanny(const Eigen::MatrixXd& G);

}  // namespace graspsim::grasp
