#pragma once
/// @file
/// The inputs of grasp quality: where each finger touches the object, which way it pushes, and the
/// object's frame. Plain Eigen, no Simbody, so the quality code is independent of the engine.
///
/// Frames (monogram notation): G is Ground (the world), O is the object frame, C a contact point.
/// `p_GC` is the position of C from G's origin expressed in G; `R_GO` the orientation of O in G
/// (it maps a vector expressed in O to the same vector expressed in G: v_G = R_GO v_O).

#include <Eigen/Core>

namespace graspsim::grasp {

/// One point contact between a finger and the grasped object.
struct GraspContact {
    /// Contact point C, measured from G's origin, expressed in G (m).
    Eigen::Vector3d p_GC = Eigen::Vector3d::Zero();
    /// Unit contact normal at C, expressed in G, pointing INTO the object: the direction in which
    /// the finger pushes the object (dimensionless, |n_G| = 1 to 1e-6).
    Eigen::Vector3d n_G = Eigen::Vector3d::UnitZ();
    /// Normal force magnitude (N, >= 0). It scales the contact's friction-cone basis forces (the
    /// thesis takes the basis from the contact solution). Use 1 for a unit-force, geometry-only
    /// quality (the classic definition of both metrics).
    double normalForce = 1;
    /// Optional first tangent direction t1 of the friction basis, expressed in G (unit and
    /// perpendicular to n_G, both to 1e-6); t2 = n x t1. Zero (the default) lets
    /// findTangent() choose t1 from the normal expressed in O, so the basis is attached to the
    /// object and the quality does not depend on the world frame. Pass a contact solver's own
    /// tangent here to use its basis.
    Eigen::Vector3d t_G = Eigen::Vector3d::Zero();
};

/// The object frame O in which wrenches are expressed and about whose origin torques are taken.
/// The thesis puts O at the object's centre of mass; the quality depends on that choice.
struct ObjectFrame {
    /// Orientation of O in G: v_G = R_GO v_O (a proper rotation to 1e-6).
    Eigen::Matrix3d R_GO = Eigen::Matrix3d::Identity();
    /// Position of O's origin from G's origin, expressed in G (m).
    Eigen::Vector3d p_GO = Eigen::Vector3d::Zero();
};

}  // namespace graspsim::grasp
