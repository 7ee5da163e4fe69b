#pragma once
/// @file
/// The Jacobian of a point fixed on a body, built by walking the body's path to Ground: what the
/// force Jacobian contributors (force_jacobian.h) project their 3x3 or 6x6 force derivatives
/// with. Mobility i of mobilizer k on the path moves the point P at H_i[1] + H_i[0] x (P - B_k),
/// H_i the mobilizer's hinge matrix column (MobilizedBody::getHCol, V_PB_G) and B_k its body's
/// origin; it turns the body at H_i[0]. One walk costs the path's length, where Simbody's
/// whole-tree transposed products cost one sweep of every body per row.

#include "graspsim/simbody.h"

#include <vector>

namespace graspsim::integration {

/// J += sign * J_P for the point P (p_G, in Ground, m) moving with `body`. `rows` 3: J is
/// 3 x nu, the point's velocity (m/s per unit speed); `rows` 6: J is 6 x nu, the body's angular
/// velocity (rows 0-2, rad/s) then the point's velocity (rows 3-5), in Ground. Column-major
/// (J[r + rows c]), sized rows * nu. `state` realized through Stage::Position. A relative
/// Jacobian J_b(P) - J_a(P) is two calls; the mobilities both paths share cancel.
void addPointJacobian(const SimTK::SimbodyMatterSubsystem& matter, const SimTK::State& state,
                      SimTK::MobilizedBodyIndex body, const SimTK::Vec3& p_G, double sign, int rows,
                      std::vector<double>& J);

/// The columns of a rows x nu J (column-major) that are not all zero, in order.
void findNonzeroColumns(const std::vector<double>& J, int rows, int nu, std::vector<int>& columns);

}  // namespace graspsim::integration
