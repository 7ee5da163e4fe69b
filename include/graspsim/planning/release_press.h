#pragma once
/// @file
/// What each goal finger still presses once the object is released: a quasi-static prediction.
///
/// Until its release the object is held in place, and each finger presses it as deep as its
/// controller drives it (its steady press). Released, the object moves until the fingers' forces
/// carry its weight and balance one another: four fingers pressing as hard as one thumb push it
/// toward the thumb, and the fingers on the far side lose press by as much as it moves along their
/// normals. A finger left with none lets go, and a grasp the approximation waits on (every goal
/// finger touching, simulation/grasp_switch.h) never forms. Measured on the 100 kg, 1.90 m man's
/// planned cylinder wrap: at release the contacts pushed the cylinder 1.9 N toward the thumb and
/// carried 0.4 N of its 2 N weight; it moved 5 mm and the little finger let go.
///
/// Each finger is a unilateral linear spring along its inward contact normal n_i (the direction
/// it pushes the object), of stiffness K_i (N/m) and steady press e_i (m). The object moves by a
/// small twist (rotation theta, translation delta) about its centre of mass until
///   sum_i K_i max(0, e_i - w_i . x) w_i + [0; m g] = 0,   w_i = [r_i x n_i; n_i], x = [theta; delta],
/// r_i the contact point from the centre of mass. Friction is left out (it only helps hold), but
/// for the directions no normal constrains (the axis of a cylinder, rotation about a sphere's
/// centre) the twist is held by a small stiffness, a thousandth of the normals' own.

#include "graspsim/simbody.h"

#include <vector>

namespace graspsim::planning {

/// One finger pressing the object, in Ground.
struct FingerPress {
    SimTK::Vec3 p_GC{0, 0, 0};  ///< contact point (m)
    SimTK::Vec3 n_G{0, 0, 0};   ///< unit inward normal at it: the direction the finger pushes the object
    double depth = 0;           ///< how deep the finger's controller drives it in, the object held (m)
    double stiffness = 0;       ///< the finger's stiffness along n_G at the contact (N/m, > 0)
};

/// The press (m) each finger keeps once the object, of mass `mass` (kg) with its centre of mass at
/// p_GCm, is released under `gravity` (m/s^2, in G) and has settled; 0 for a finger that lets go.
/// Same order as `fingers`.
std::vector<double> calcPressAfterRelease(const std::vector<FingerPress>& fingers, const SimTK::Vec3& p_GCm,
                                          double mass, const SimTK::Vec3& gravity);

}  // namespace graspsim::planning
