#pragma once
/// @file
/// Mass properties of solid geometry at uniform density: how the hand's de Leva mass is
/// shared over the palm boxes and phalanx capsules, and how objects get their inertia.

#include "graspsim/model/model_description.h"

#include <array>
#include <vector>

namespace graspsim::model {

/// Mass, centre of mass and central inertia of a rigid body.
struct MassProperties {
    double mass = 0;      ///< kg
    Vec3 p_BCm{0, 0, 0};  ///< centre of mass in the body frame B (m)
    Inertia inertia;      ///< central inertia, expressed in B (kg m^2)
};

/// Volume of a sphere, box, cylinder, capsule, ellipsoid or loaded mesh (m^3).
/// @throws graspsim::InputError for a mesh known only by file name (`mesh` null).
double calcVolume(const Geometry& geometry);

/// Mass properties of one solid of the given density (kg/m^3), in the body frame via X_BG.
MassProperties calcSolidMassProperties(const Geometry& geometry, double density);

/// Mass properties of the union of non-overlapping solids of one density (kg/m^3).
MassProperties calcSolidMassProperties(const std::vector<Geometry>& geometry, double density);

/// Principal moments of the symmetric matrix [xx xy xz; xy yy yz; xz yz zz], ascending (kg m^2).
std::array<double, 3> calcPrincipalMoments(const Inertia& I);

/// Relative slack (of the trace) allowed in the triangle inequality of principal moments, so that
/// a flat plate's inertia written to six significant digits by another tool still passes this
/// check. Simbody's own, also part of ModelDescription::validate, allows sqrt(eps) max(trace, 1)
/// kg m^2 on the diagonal: tighter than this above a trace of about 0.0075 kg m^2.
constexpr double kInertiaTriangleTolerance = 1e-6;

/// Rotates a central inertia given in G into B: I_B = R_BG I_G R_BG^T.
Inertia reexpressInertia(const Inertia& I_G, const Transform& X_BG);

}  // namespace graspsim::model
