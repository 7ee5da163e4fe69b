#pragma once
/// @file
/// One grasp experiment as plain data: world, subject, object, grasp pose, goal points,
/// perturbations, contact, controller and simulation settings.
///
/// A scenario is what a user edits to run another object or another grasp without touching
/// C++; scenario_file.h reads it from a commented YAML file. Everything here is SI (m, kg, s,
/// rad, N); the file's angles are degrees and are converted once, when the file is read.
///
/// Frames: Ground G is the world frame of the arm model: y up, x anterior, z to the subject's
/// right, origin at the right shoulder joint centre. The object frame O sits at the object's
/// centre of mass with its axes along the object's symmetry axes (model/object_model.h).

#include "graspsim/contact/contact_parameters.h"
#include "graspsim/contact/friction_settings.h"
#include "graspsim/model/build_options.h"
#include "graspsim/model/model_description.h"

#include <array>
#include <map>
#include <string>
#include <vector>

namespace graspsim::scenario {

using model::Vec3;

/// The world the experiment runs in.
struct WorldSpec {
    Vec3 gravity{0, -9.81, 0};  ///< gravitational acceleration in G (m/s^2); default (0, -9.81, 0)
};

/// Shape of the grasped object (docs/shapes.md).
enum class ObjectShape {
    Sphere,     ///< solid sphere of `radius` (the thesis's ball)
    Box,        ///< solid box of `size` (the thesis's phone)
    Cylinder,   ///< solid cylinder of `radius` and `length` (full height) along O's z
    Capsule,    ///< solid capsule of `radius` and `length` (its straight part) along O's z
    Ellipsoid,  ///< solid ellipsoid of `semiAxes` along O's x, y, z
    Mesh        ///< solid closed convex mesh read from `mesh` (STL or OBJ), scaled by `meshScale`
};

/// "sphere", "box", "cylinder", "capsule", "ellipsoid" or "mesh", the spelling a scenario file uses.
std::string toString(ObjectShape shape);

/// The grasped object: a free rigid body of uniform density. No defaults for its shape, mass,
/// size or position: a scenario file must give them.
struct ObjectSpec {
    ObjectShape shape = ObjectShape::Sphere;
    double mass = 0;           ///< kg, > 0
    double radius = 0;         ///< sphere, cylinder, capsule radius (m), > 0
    Vec3 size{0, 0, 0};        ///< box edge lengths along O's x, y, z (m), each > 0; box only
    double length = 0;         ///< cylinder height, capsule straight part, along O's z (m), > 0
    Vec3 semiAxes{0, 0, 0};    ///< ellipsoid semi-axes along O's x, y, z (m), each > 0
    std::string mesh;          ///< mesh file as the scenario gives it (relative to the scenario file)
    std::string meshPath;      ///< mesh: the file read, absolute; what a written scenario gives as `mesh`
    Vec3 meshScale{1, 1, 1};   ///< mesh: scale of the file's coordinates per axis, each > 0; default 1
    /// Mesh: the loaded triangles in the file's frame M, scale applied; null for the other shapes.
    std::shared_ptr<const model::TriangleMesh> meshData;
    /// Mesh: p_MO, the centroid of the solid in the file's frame M (m). The object frame O sits
    /// there (at the centre of mass) with M's axes, so p_M = p_O + meshCentroid.
    Vec3 meshCentroid{0, 0, 0};
    Vec3 position{0, 0, 0};    ///< p_GO: centre of mass in G at t = 0 (m)
    Vec3 orientation{0, 0, 0}; ///< body-fixed X-Y-Z Euler angles of O in G at t = 0 (rad); default 0

    /// X_GO, the object's initial pose in ground: translation `position`, rotation
    /// R_GO = Rx(orientation[0]) * Ry(orientation[1]) * Rz(orientation[2]).
    model::Transform findPose() const;

    /// Signed distance (m) from the point p_OP (object frame, m) to the object's surface:
    /// positive outside, negative inside, zero on the surface. Exact for every shape except the
    /// ellipsoid, where it is the first-order estimate F/|grad F| (F = sum (x_i/a_i)^2 - 1, scaled),
    /// exact on the surface and good to second order near it (enough to check goal points).
    double calcSurfaceDistance(const Vec3& p_OP) const;

    /// Outward unit normal of the surface nearest to point P (given in O), in O: the radial
    /// direction for a sphere, the normal of the face whose plane is nearest for a box or mesh,
    /// the nearer of side and end face for a cylinder, the direction from the axis segment for a
    /// capsule, the gradient direction for an ellipsoid.
    Vec3 findOutwardNormal(const Vec3& p_OP) const;

    /// Half the object's smallest thickness through O (m): a goal pressed deeper would pass the centre.
    double findHalfThickness() const;

    /// Mesh: p_MP, the point given in O expressed in the mesh file's frame M (m).
    Vec3 toMeshFrame(const Vec3& p_OP) const;
};

/// The name of the object's body in every scenario, whatever its shape: what contacts.csv gives
/// as body_b (the object's geometry is named after its shape, toString(ObjectShape)).
constexpr const char* kObjectBodyName = "object";

/// The object as a one-body model: model and body named kObjectBodyName, its one geometry named
/// toString(object.shape) ("box", "mesh", ...), whatever the shape. Built by model::buildBallModel,
/// buildPhoneModel, buildCylinderModel, buildCapsuleModel, buildEllipsoidModel or buildMeshModel
/// with the spec's mass and size, then renamed (those builders keep the thesis's names, "phone",
/// for the models they export). The pose is not part of the description; use ObjectSpec::findPose().
model::ModelDescription buildObjectModel(const ObjectSpec& object);

/// A force pushed on the object's centre of mass for a while. The thesis runs each
/// perturbation in a simulation of its own (reset in between), so perturbations of one
/// scenario usually share one time window.
struct Perturbation {
    std::string name;        ///< its key in the file, e.g. "f1"
    Vec3 force{0, 0, 0};     ///< force in G, applied at the object's centre of mass (N)
    double start = 0;        ///< when it starts (s), >= 0
    double duration = 0;     ///< how long it acts (s), > 0; it stops at start + duration

    /// True when the force acts at time t (s): start <= t < start + duration.
    bool isActiveAt(double t) const { return t >= start && t < start + duration; }
};

/// The grasp controller. At t = 0 the hand is placed in the grasp pose kinematically (the thesis's
/// "forward kinematics once"); inverse kinematics then drives each fingertip toward its goal moved
/// pressDepth inside the surface, and a joint PD controller tracks the resulting angles. The
/// object is held in place until approachTime, then released to the grasp. kp and kd are the gains of the finger and
/// thumb joints, the ones that make the grasp force.
struct ControllerSpec {
    /// Time the object is held in place while the fingers close on it, before it is released (s),
    /// >= 0; default 0.5.
    double approachTime = 0.5;
    /// Depth of each IK goal below the object's surface along the inward normal, so that the
    /// fingers press (m), >= 0 and below half the object's smallest dimension; default 0.002.
    double pressDepth = 0.002;
    /// Proportional gain of the finger and thumb joints' PD controller (N m/rad), > 0; default 5.
    double kp = 5.0;
    /// Whether the file gave kp: a grasp planned on load (`grasp: {type}`) keeps a given gain and
    /// otherwise takes the plan's (the lateral pinch's is 2).
    bool kpGiven = false;
    /// Derivative gain of the finger and thumb joints' PD controller (N m s/rad), >= 0; default 0.05.
    double kd = 0.05;
    /// Time between two IK solutions (s), > 0; default 0.01.
    double ikInterval = 0.01;
};

/// Integration and evaluation settings.
struct SimulationSpec {
    /// Simulated time (s), > 0; default 3.
    double duration = 3.0;
    /// Time between reported states (s), in (0, duration]; default 0.01.
    double outputInterval = 0.01;
    /// Relative accuracy of the integrator, in (0, 1); default 1e-3.
    double accuracy = 1e-3;
    /// Longest step of the linearly implicit integrator (s; its fixed step with implicit-fixed),
    /// > 0; 0 (the default, the key left out) takes the integrator's own: the controller's
    /// ik_interval for error control, 1 ms at fixed steps (simulation::findStepSize).
    double stepSize = 0;
    /// Time from which the grasp counts as settled, and the object's drift is measured (s), in
    /// [ControllerSpec::approachTime, duration]; default 1.
    double settleTime = 1.0;
    /// The object counts as held while each goal point (moved with the object) stays within this
    /// distance of its fingertip (m), > 0; default 0.02.
    double heldTolerance = 0.02;
};

/// The grasp approximation's settings for this experiment (section `approximation:`, optional;
/// used by `--mode approx` only; command-line options override the thresholds).
struct ApproximationSpec {
    /// Names of the constraint axes in ApproximationSpec order: rotation about the object frame's
    /// x, y, z, then translation along them.
    static constexpr const char* kAxisNames[6] = {"rx", "ry", "rz", "x", "y", "z"};
    /// Which axes are relaxed (friction-limited, may slide); the others are locked. The thesis
    /// relaxes the primary and secondary axes where sliding is expected. Default: all six
    /// (`relaxed_axes: [rx, ry, rz, x, y, z]`).
    std::array<bool, 6> relaxedAxes{true, true, true, true, true, true};
    /// Q_Th (N), >= 0; 0 (default) = automatic (simulation/grasp_switch.h).
    double qThreshold = 0;
    /// Q_M (N), >= 0 and below Q_Th when both are given; 0 (default) = half of Q_Th.
    double qMinimum = 0;
};

/// One grasp experiment.
struct Scenario {
    std::string name;         ///< short identifier, e.g. "ball-clutch"
    std::string description;  ///< one sentence for people; may be empty
    std::string source;       ///< the file it was read from (for messages)
    WorldSpec world;
    /// Subject (sex, mass in kg, stature in m) and preset of the arm model. Defaults: de Leva's
    /// male reference subject, thesis preset, right arm. Other BuildOptions keep their defaults.
    model::BuildOptions bodyOptions = makeDefaultBodyOptions();
    ObjectSpec object;
    /// Target angle (rad) of arm and hand joints in the grasp pose, by joint name of
    /// model::buildBodyModel(bodyOptions); joints not listed stay at 0.
    std::map<std::string, double> graspPose;
    /// Goal point of each end-effector (e.g. "index_tip") on the object's surface, in O (m). Besides
    /// the fingertips, a goal may name a point the file fixes on a segment (`end_effectors:`, read
    /// into bodyOptions.segmentPoints).
    std::map<std::string, Vec3> goals;
    /// `grasp: {type: ...}`: the grasp type to plan (planning/planned_scenario.h) when the file
    /// leaves out grasp_pose, goals and the object's position and orientation; empty otherwise.
    std::string graspType;
    std::vector<Perturbation> perturbations;
    ApproximationSpec approximation;  ///< in file order; may be empty
    /// Section `contact:`, the parameters of every hand-object contact pair (the defaults are
    /// ContactParameters's: a finger pad on smooth plastic, sources in
    /// models/scenarios/ball-clutch.yaml).
    graspsim::contact::ContactParameters contact;
    /// Section `contact:` as well: the compliant contact's friction law (friction_model) and the
    /// anchor law's parameters (anchor_stiffness_ratio, anchor_damping_mass,
    /// anchor_relaxation_time).
    graspsim::contact::FrictionSettings friction;
    ControllerSpec controller;
    SimulationSpec simulation;

    /// The perturbation called `perturbationName` (e.g. "f1"), or nullptr.
    const Perturbation* findPerturbation(const std::string& perturbationName) const;

    /// Arm model options of a scenario that says nothing about its subject.
    static model::BuildOptions makeDefaultBodyOptions();
};

}  // namespace graspsim::scenario
