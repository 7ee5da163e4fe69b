#pragma once
/// @file
/// The thesis's grasped objects as one-body models of uniform density.
///
/// Object frame O: at the centre of mass, axes along the object's symmetry axes. A scenario
/// decides how the object is mounted (free, in practice); the description holds only the body.

#include "graspsim/model/model_description.h"

#include <string>

namespace graspsim::model {

/// Mass (kg) and radius (m) of the thesis's ball. The thesis gives 200 g; the radius is ours:
/// 45 mm fits a five-finger clutch of an adult male hand (documented model assumption).
constexpr double kBallMass = 0.200;
constexpr double kBallRadius = 0.045;
/// Mass (kg) and size (m) of the thesis's phone: 100 g, about 0.07 x 0.14 x 0.008 m (x width,
/// y length, z thickness).
constexpr double kPhoneMass = 0.100;
constexpr Vec3 kPhoneSize{0.070, 0.140, 0.008};

/// A solid sphere of uniform density: body "ball" with sphere geometry "ball_sphere".
ModelDescription buildBallModel(double mass = kBallMass, double radius = kBallRadius);

/// A solid box of uniform density: body "phone" with box geometry "phone_box".
ModelDescription buildPhoneModel(double mass = kPhoneMass, const Vec3& size = kPhoneSize);

/// A solid cylinder of uniform density, axis along O's z: body "cylinder", geometry
/// "cylinder_shape". `length` is the full height (m).
ModelDescription buildCylinderModel(double mass, double radius, double length);

/// A solid capsule of uniform density, axis along O's z: body "capsule", geometry
/// "capsule_shape". `length` is its straight part, between the centres of its hemispherical caps (m).
ModelDescription buildCapsuleModel(double mass, double radius, double length);

/// A solid ellipsoid of uniform density with semi-axes (m) along O's x, y, z: body "ellipsoid",
/// geometry "ellipsoid_shape".
ModelDescription buildEllipsoidModel(double mass, const Vec3& semiAxes);

/// A solid closed mesh of uniform density: body "mesh", geometry "mesh_shape". Mass properties
/// come from the divergence theorem over signed tetrahedra (model/triangle_mesh.h). The object
/// frame O must sit at the centre of mass, so the geometry frame G (the file's frame, vertices
/// unchanged) is placed at X_OG = translation(-centroid); O's axes are the file's axes, not
/// rotated to principal axes, so the inertia keeps its products.
/// @param mesh vertices (scale applied) and outward triangles, as model::readMeshFile returns them.
/// @param meshFile, scale the file name and scale, kept for export.
ModelDescription buildMeshModel(double mass, const TriangleMesh& mesh, const std::string& meshFile,
                                const Vec3& scale);

/// The named object ("ball" or "phone") at its thesis mass.
/// @throws graspsim::InputError naming `source`, the value and the accepted names.
ModelDescription buildObjectModel(const std::string& name, const std::string& source);

}  // namespace graspsim::model
