#pragma once
/// @file
/// Forward kinematics of a model description without a Simbody system: the pose in Ground of
/// every body for given joint angles, and every body's contact shapes posed with it. Fast enough
/// to be evaluated tens of thousands of times while a grasp is planned.

#include "graspsim/simbody.h"

#include "graspsim/contact/contact_shape.h"
#include "graspsim/model/model_description.h"

#include <string>
#include <vector>

namespace graspsim::planning {

/// A model geometry as a contact shape on its body.
struct SegmentShape {
    std::string name;            ///< the geometry's name, e.g. "index_distal_capsule"
    int body = 0;                ///< index into ModelDescription::bodies
    contact::ContactShape shape;
    SimTK::Transform X_BS;       ///< shape frame in the body frame
};

/// The model's joint tree with the joint angles as a vector in ModelDescription::joints order.
class ArmKinematics {
public:
    explicit ArmKinematics(const model::ModelDescription& model);

    const model::ModelDescription& getModel() const { return m_model; }
    /// Index of joint `name` in ModelDescription::joints.
    /// @throws graspsim::InputError when the model has no such joint.
    int findJointIndex(const std::string& name) const;
    /// Index of body `name` in ModelDescription::bodies, or -1.
    int findBodyIndex(const std::string& name) const;

    /// X_GB of every body (ModelDescription::bodies order) for joint angles q (rad or m, one per
    /// joint, fixed joints ignored).
    void calcBodyPoses(const std::vector<double>& q, std::vector<SimTK::Transform>& X_GB) const;

    /// Every sphere, capsule and box geometry of every body, as contact shapes (other geometry
    /// types are display-only on the arm and skipped).
    const std::vector<SegmentShape>& getSegmentShapes() const { return m_shapes; }
    /// The axis of joint `joint` in Ground for body poses X_GB (calcBodyPoses): a point on it
    /// (m) and its unit direction; a revolute joint turns its child about it.
    void findJointAxis(int joint, const std::vector<SimTK::Transform>& X_GB, SimTK::Vec3& p_GJ, SimTK::Vec3& a_G) const;

private:
    model::ModelDescription m_model;
    std::vector<int> m_order;          // joint indices, parents before children
    std::vector<int> m_parentBody;     // per joint
    std::vector<int> m_childBody;      // per joint
    SimTK::Transform m_X_GR;          // root body in Ground
    std::vector<SimTK::Transform> m_X_PJ;
    std::vector<SimTK::UnitVec3> m_axis;
    std::vector<SegmentShape> m_shapes;
};

}  // namespace graspsim::planning
