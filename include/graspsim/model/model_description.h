#pragma once
/// @file
/// The model description: a plain-data, engine-independent tree of rigid bodies and joints.
///
/// It is what the builders produce, what URDF export writes and URDF import reads, and what
/// the Simbody layer turns into a `MultibodySystem`. Everything is SI: metres, kilograms,
/// radians, newton-metres per radian, newton-metre-seconds per radian.
///
/// Frames (monogram notation): each body B has its own frame B. A joint J connects a parent
/// body P to a child body C; its frame is placed in P by `X_PJ` and, at zero joint angle,
/// coincides with the child's frame C (URDF's convention: the joint origin is the child frame).
/// Multi-DOF anatomical joints (shoulder 3, wrist 2, MCP 2, CMC 2) are chains of revolute
/// joints through massless "virtual" bodies, exactly as URDF writes them.

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace graspsim::model {

/// A 3-vector, in the frame named by the field that holds it.
using Vec3 = std::array<double, 3>;

/// A closed triangle mesh (m): vertices, and triangles as vertex indices ordered
/// counter-clockwise seen from outside (so the right-hand normals point out).
struct TriangleMesh {
    std::vector<Vec3> vertices;                 ///< in the geometry frame, scale applied (m)
    std::vector<std::array<int, 3>> triangles;  ///< indices into vertices
};

/// A rigid transform: rotation R (row-major 3x3) and translation p, X_AB maps B coordinates to A.
struct Transform {
    std::array<double, 9> R{1, 0, 0, 0, 1, 0, 0, 0, 1};  ///< rotation R_AB, row-major, orthonormal
    Vec3 p{0, 0, 0};                                       ///< p_AB: origin of B from A's origin, in A (m)

    /// Identity transform.
    static Transform identity() { return Transform{}; }
    /// Pure translation by p (m).
    static Transform translation(const Vec3& p);
    /// Rotation about a unit axis (in A) by angle (rad), with translation p (m).
    static Transform axisAngle(const Vec3& axis, double angle, const Vec3& p = {0, 0, 0});
    /// Composition X_AC = X_AB * X_BC.
    Transform operator*(const Transform& X_BC) const;
    /// Maps a point given in B to A (m).
    Vec3 shiftFrameStationToBase(const Vec3& p_BQ) const;
    /// Re-expresses a vector given in B in A.
    Vec3 xformFrameVecToBase(const Vec3& v_B) const;
};

/// Central inertia of a body, about its centre of mass, expressed in the body frame (kg m^2).
struct Inertia {
    double xx = 0, yy = 0, zz = 0;  ///< moments (kg m^2)
    double xy = 0, xz = 0, yz = 0;  ///< products (kg m^2), URDF sign convention (I = [xx xy xz; xy yy yz; xz yz zz])
};

/// Collision (and display) geometry attached to a body.
struct Geometry {
    enum class Type { Sphere, Box, Capsule, Cylinder, Mesh, Ellipsoid };
    Type type = Type::Sphere;
    std::string name;          ///< unique within the body
    Transform X_BG;            ///< pose of the geometry frame G in the body frame B
    double radius = 0;         ///< sphere, capsule, cylinder radius (m)
    double length = 0;         ///< capsule and cylinder: length of the axis segment along G's z, excluding caps (m)
    Vec3 halfLengths{0, 0, 0}; ///< box half-lengths along G's x, y, z (m)
    Vec3 semiAxes{0, 0, 0};    ///< ellipsoid semi-axes along G's x, y, z (m)
    std::string meshFile;      ///< mesh: file name as given
    Vec3 meshScale{1, 1, 1};   ///< mesh: scale applied to the file's coordinates per axis of G
    /// Mesh: the loaded vertices and triangles (scale applied), when graspsim has read the file;
    /// null for a mesh known only by name (a display mesh of an imported URDF).
    std::shared_ptr<const TriangleMesh> mesh;
};

/// The geometry type's lower-case name as scenario files write it ("sphere", "box", "capsule",
/// "cylinder", "mesh", "ellipsoid").
std::string toString(Geometry::Type type);

/// What a body is to a grasp, as the model builder knows it (so nothing downstream has to guess
/// it from names).
enum class BodyRole {
    Other,  ///< arm segments, objects, anything else
    Palm,   ///< the palm (and the massless bodies of the wrist chain leading to it)
    Digit   ///< a phalanx of a finger or the thumb, or a massless body of a digit's joint chain
};

/// "other", "palm" or "digit", as URDF extension files write it.
std::string toString(BodyRole role);

/// A rigid body.
struct Body {
    std::string name;
    std::string segment;  ///< anatomical segment it belongs to (e.g. "hand", "upper_arm"); empty for objects
    BodyRole role = BodyRole::Other;  ///< palm, digit or other (set by the builder)
    double mass = 0;      ///< kg; 0 only for virtual bodies of multi-DOF joint chains
    Vec3 p_BCm{0, 0, 0};  ///< centre of mass in the body frame (m)
    Inertia inertia;      ///< central inertia in the body frame (kg m^2)
    std::vector<Geometry> geometry;

    /// True for the massless intermediate bodies of multi-DOF joint chains.
    bool isVirtual() const { return mass == 0; }
};

/// A joint between a parent and a child body.
struct Joint {
    enum class Type { Revolute, Continuous, Prismatic, Fixed };
    std::string name;
    Type type = Type::Revolute;
    std::string parent;       ///< parent body name
    std::string child;        ///< child body name
    Transform X_PJ;           ///< joint frame (= child frame at q = 0) in the parent frame
    Vec3 axis{0, 0, 1};       ///< unit axis in the joint frame
    double lower = 0;         ///< lower limit (rad or m); Revolute and Prismatic only
    double upper = 0;         ///< upper limit (rad or m)
    double stiffness = 0;     ///< passive stiffness toward restAngle (N m/rad or N/m)
    double damping = 0;       ///< passive damping (N m s/rad or N s/m)
    double restAngle = 0;     ///< where the passive spring is relaxed (rad or m)

    /// Number of mobilities: 1 for all but Fixed (0).
    int getDofCount() const { return type == Type::Fixed ? 0 : 1; }
    /// True when the joint has limits to enforce (Revolute, Prismatic).
    bool hasLimits() const { return type == Type::Revolute || type == Type::Prismatic; }
};

/// A named point on a body, e.g. a fingertip that the controller tracks.
struct EndEffector {
    std::string name;
    std::string body;
    Vec3 p_BE{0, 0, 0};  ///< position in the body frame (m)
};

/// A whole model. The first body is the root; it is welded to ground at X_GR.
struct ModelDescription {
    std::string name;
    Transform X_GR;  ///< pose of the root body in ground
    std::vector<Body> bodies;
    std::vector<Joint> joints;
    std::vector<EndEffector> endEffectors;

    /// Body by name, or nullptr.
    const Body* findBody(const std::string& name) const;
    Body* updBody(const std::string& name);
    /// Joint by name, or nullptr.
    const Joint* findJoint(const std::string& name) const;
    Joint* updJoint(const std::string& name);
    /// Joint whose child is `body`, or nullptr for the root.
    const Joint* findParentJoint(const std::string& body) const;
    /// End-effector by name, or nullptr.
    const EndEffector* findEndEffector(const std::string& name) const;
    /// The palm: the one body with BodyRole::Palm that has mass (the builder's role, not a name).
    /// @throws graspsim::InputError when there is none or more than one (a grasp needs one hand).
    const Body& findPalm() const;

    /// Total degrees of freedom (sum over joints).
    int getDofCount() const;
    /// Total mass (kg).
    double calcTotalMass() const;
    /// Mass per anatomical segment (kg), in order of first appearance.
    std::vector<std::pair<std::string, double>> calcSegmentMasses() const;

    /// Checks that the description is a well-formed tree and physically valid: unique names,
    /// every joint's parent and child exist, one root, no cycles, every body reachable, masses
    /// finite and non-negative, inertias of massive bodies positive definite and satisfying the
    /// triangle inequality, mass properties Simbody can hold (about the link origin, within its
    /// tighter inertia tolerance), limits ordered, axes unit length, geometry sizes positive, and
    /// every movable joint carrying mass (a link with mass at or beyond its child).
    /// @param source names the origin (file name or builder) for the error message.
    /// @throws graspsim::InputError naming source, field, value and what is accepted.
    void validate(const std::string& source) const;
};

}  // namespace graspsim::model
