#pragma once
/// @file
/// The grasp matrix G: every friction-cone basis force of every contact, mapped to the wrench it
/// applies to the object, expressed in the object frame O (thesis eqs. 2.14-2.18).
///
/// For contact i with point C_i and basis forces f_ij (calcFrictionConeBasis scaled by the
/// normal force), column j of contact i is the wrench, about O's origin and expressed in O,
///
///     w_ij = D_i f_ij_O = [ f_ij_O ; (p_OC_i x f_ij_O) / L ],   f_ij_O = R_OG f_ij_G,
///     p_OC_i = R_OG (p_GC_i - p_GO),   D_i = [ I ; p_OC_i^ / L ],
///
/// where ^ is the cross-product matrix and L the torque scale. Rows 0-2 are the force (N),
/// rows 3-5 the moment about O's origin divided by L (N m / m).
///
/// Sign and order versus the thesis. Eq. 2.14 writes w = [c x f ; f] (torque first), and eq. 2.17
/// writes D_i = [R^T  -c^ R^T]^T. Read as the transpose of a block row, with R mapping world to
/// object vectors, that D_i f is [R f ; R (c x f)] = [f_O ; c_O x f_O], exactly our w_ij. Read as
/// stacked blocks (R the object's orientation, so R^T maps world to object), it is
/// [f_O ; -c_O x f_O], the negative of the moment. We use the physical moment c_O x f_O, force
/// first. None of this matters for the quality: reordering rows or negating the torque rows is an
/// orthogonal map P of wrench space, and P G has the same singular values as G and maps the
/// columns' convex hull to a congruent one (same inscribed-ball radius).

#include "graspsim/grasp/grasp_contact.h"
#include "graspsim/grasp/quality_options.h"

#include <Eigen/Core>

#include <vector>

namespace graspsim::grasp {

/// The 6 x 3 map D = [I ; p_OC^ / L] from a force at point C, expressed in O, to the wrench
/// [force ; moment about O's origin / L] it applies, expressed in O. `p_OC` in m, `torqueScale`
/// L in m.
Eigen::Matrix<double, 6, 3> calcContactWrenchMap(const Eigen::Vector3d& p_OC, double torqueScale);

/// The 6 x (k N) grasp matrix G = [w_1 ... w_N], N contacts with k basis forces each
/// (getNumConeEdges); contact i's k columns start at column k i, in calcFrictionConeBasis's
/// order. Each contact's friction basis uses its t_G if given, else findTangent() of the normal
/// expressed in O. A contact with zero normal force contributes zero columns.
/// @throws graspsim::InputError naming the contact (by index) or the field that is invalid:
/// non-finite values, a normal or tangent that is not unit to 1e-6, a tangent not perpendicular
/// to the normal, a negative normal force, an R_GO that is not a proper rotation, or any invalid
/// option (see validate(const QualityOptions&)).
Eigen::MatrixXd calcGraspMatrix(const std::vector<GraspContact>& contacts, const ObjectFrame& frame,
                                const QualityOptions& options);

}  // namespace graspsim::grasp
