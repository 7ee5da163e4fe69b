#pragma once
/// @file
/// The shapes the contact layer collides: spheres, capsules and boxes (what the hand is made of),
/// the object shapes (those and cylinders, ellipsoids and convex meshes) and half-spaces
/// (floors, tables).
///
/// A shape is described in its own frame S; where S is (on a body, or in Ground) is given
/// separately, as a pose X_BS or X_GS. Conventions in S (m):
///  - Sphere: centred on S's origin, `radius`.
///  - Capsule: the points within `radius` of the segment from (0, 0, -length/2) to
///    (0, 0, +length/2); `length` excludes the caps, exactly as model::Geometry's capsule.
///  - Box: the points with |x| <= halfLengths[0], |y| <= halfLengths[1], |z| <= halfLengths[2].
///  - Cylinder: the points with x^2 + y^2 <= radius^2 and |z| <= length/2 (flat caps).
///  - Ellipsoid: the points with sum (x_i / semiAxes[i])^2 <= 1.
///  - ConvexMesh: the convex polytope `polytope` (vertices and faces in S, see
///    convex_polytope.h), shared between copies.
///  - HalfSpace: the points with z <= 0. Its surface is S's xy plane and its outward normal is
///    +z_S. A floor in graspsim's y-up Ground is X_GS = SimTK::Rotation(-SimTK::Pi/2,
///    SimTK::XAxis), which turns z_S into +y_G. (Simbody's ContactGeometry::HalfSpace occupies
///    x > 0 instead; ours follows the z-axis convention of our capsules.)

#include "graspsim/simbody.h"

#include <memory>
#include <string>

#include "graspsim/contact/convex_polytope.h"
#include "graspsim/model/model_description.h"

namespace graspsim::contact {

/// Radius of curvature (m) given to a box's corners and edges when one of them is the
/// penetrating feature (box vertex into a box or a half-space, box edge into a box).
///
/// A mathematically sharp corner has no Hertz radius (the Hertz force law needs R > 0), so we
/// treat corners as rounded. 5 mm is an assumption: the order of the corner rounding of
/// handheld objects such as a phone, and of the soft palm that our palm boxes approximate.
constexpr double kDefaultBoxCornerRadius = 0.005;

/// A convex contact shape in its own frame S (see the file comment for the conventions).
struct ContactShape {
    enum class Type { Sphere, Capsule, Box, HalfSpace, Cylinder, Ellipsoid, ConvexMesh };
    Type type = Type::Sphere;
    double radius = 0;  ///< Sphere, Capsule, Cylinder: radius (m)
    double length = 0;  ///< Capsule (caps excluded), Cylinder: length along z_S (m)
    SimTK::Vec3 halfLengths{0, 0, 0};  ///< Box: half-lengths along x_S, y_S, z_S (m)
    SimTK::Vec3 semiAxes{0, 0, 0};     ///< Ellipsoid: semi-axes along x_S, y_S, z_S (m)
    std::shared_ptr<const ConvexPolytope> polytope;  ///< ConvexMesh: its polytope, in S
    /// Box, ConvexMesh: Hertz radius of corners and edges; Cylinder: of its rims (m).
    double cornerRadius = kDefaultBoxCornerRadius;

    /// A sphere of the given radius (m).
    static ContactShape sphere(double radius);
    /// A capsule: radius (m) and axis length along z_S without the caps (m).
    static ContactShape capsule(double radius, double length);
    /// A box with half-lengths along x_S, y_S, z_S (m).
    static ContactShape box(const SimTK::Vec3& halfLengths,
                            double cornerRadius = kDefaultBoxCornerRadius);
    /// The half-space z_S <= 0.
    static ContactShape halfSpace();
    /// A cylinder: radius (m) and length along z_S (m), flat caps.
    static ContactShape cylinder(double radius, double length,
                                 double cornerRadius = kDefaultBoxCornerRadius);
    /// An ellipsoid with semi-axes along x_S, y_S, z_S (m).
    static ContactShape ellipsoid(const SimTK::Vec3& semiAxes);
    /// A convex mesh (see ConvexPolytope::build()).
    static ContactShape convexMesh(std::shared_ptr<const ConvexPolytope> polytope,
                                   double cornerRadius = kDefaultBoxCornerRadius);

    /// The shape of a model geometry (its pose X_BG is not part of the shape; see
    /// findGeometryPose()).
    /// A Mesh becomes a ConvexMesh built from geometry.mesh (ConvexPolytope::build(), which
    /// checks and indexes the whole mesh: build the shape once and copy it, copies share the
    /// polytope, rather than calling this in a loop).
    /// @throws graspsim::InputError naming the geometry for a non-positive or non-finite size,
    ///         a Mesh whose triangles are not loaded (geometry.mesh null), or a mesh that is
    ///         not closed, not convex or inside out.
    static ContactShape fromGeometry(const model::Geometry& geometry);

    /// Checks sizes: radius > 0 for spheres, capsules and cylinders, length >= 0 for capsules
    /// and > 0 for cylinders, every half-length or semi-axis > 0, cornerRadius > 0 for boxes,
    /// cylinders and meshes, a polytope for meshes, all finite.
    /// @param what names the shape for the message ("geometry 'index_distal_capsule'").
    /// @throws graspsim::InputError naming `what`, the field, its value and what is accepted.
    void validate(const std::string& what) const;

    /// Radius (m) of the smallest sphere about S's origin that holds the shape: the bounding
    /// sphere used to skip far-apart pairs. Infinite for a half-space.
    /// @pre validate() passes (a ConvexMesh has its polytope).
    double calcBoundingRadius() const;
};

/// The pose X_BS of a model geometry's frame in its body frame, as a SimTK::Transform (m).
/// @throws graspsim::InputError naming the geometry if X_BG's rotation is not a proper
///         rotation (see system::toSimTKTransform).
SimTK::Transform findGeometryPose(const model::Geometry& geometry);

}  // namespace graspsim::contact
