#include "graspsim/planning/arm_kinematics.h"

#include "graspsim/error.h"
#include "graspsim/system/simtk_conversion.h"

namespace graspsim::planning {

ArmKinematics::ArmKinematics(const model::ModelDescription& model)
    : m_model(model), m_X_GR(system::toSimTKTransform(model.X_GR, "model '" + model.name + "' X_GR")) {
    const int n = static_cast<int>(m_model.joints.size());
    for (const model::Joint& joint : m_model.joints) {
        m_parentBody.push_back(findBodyIndex(joint.parent));
        m_childBody.push_back(findBodyIndex(joint.child));
        m_X_PJ.push_back(system::toSimTKTransform(joint.X_PJ, "joint '" + joint.name + "' X_PJ"));
        m_axis.push_back(SimTK::UnitVec3(system::toSimTKVec3(joint.axis)));
    }
    // A joint comes after the joint that places its parent body (a tree: n passes suffice).
    std::vector<bool> placed(m_model.bodies.size(), false);
    if (!placed.empty()) placed[0] = true;
    std::vector<bool> done(n, false);
    for (int pass = 0; pass < n && static_cast<int>(m_order.size()) < n; ++pass) {
        for (int j = 0; j < n; ++j) {
            if (done[j] || m_parentBody[j] < 0 || !placed[m_parentBody[j]]) continue;
            m_order.push_back(j);
            done[j] = true;
            if (m_childBody[j] >= 0) placed[m_childBody[j]] = true;
        }
    }
    for (int b = 0; b < static_cast<int>(m_model.bodies.size()); ++b) {
        for (const model::Geometry& g : m_model.bodies[b].geometry) {
            using T = model::Geometry::Type;
            if (g.type != T::Sphere && g.type != T::Capsule && g.type != T::Box) continue;
            m_shapes.push_back({g.name, b, contact::ContactShape::fromGeometry(g), contact::findGeometryPose(g)});
        }
    }
}

int ArmKinematics::findJointIndex(const std::string& name) const {
    for (int j = 0; j < static_cast<int>(m_model.joints.size()); ++j) {
        if (m_model.joints[j].name == name) return j;
    }
    throw InputError("the arm model has no joint '" + name + "'");
}

int ArmKinematics::findBodyIndex(const std::string& name) const {
    for (int b = 0; b < static_cast<int>(m_model.bodies.size()); ++b) {
        if (m_model.bodies[b].name == name) return b;
    }
    return -1;
}

void ArmKinematics::findJointAxis(int joint, const std::vector<SimTK::Transform>& X_GB, SimTK::Vec3& p_GJ,
                                  SimTK::Vec3& a_G) const {
    const SimTK::Transform X_GJ = X_GB[m_parentBody[joint]] * m_X_PJ[joint];
    p_GJ = X_GJ.p();
    a_G = X_GJ.R() * SimTK::Vec3(m_axis[joint]);
}

void ArmKinematics::calcBodyPoses(const std::vector<double>& q, std::vector<SimTK::Transform>& X_GB) const {
    X_GB.assign(m_model.bodies.size(), m_X_GR);
    for (int j : m_order) {
        const model::Joint& joint = m_model.joints[j];
        const double angle = joint.getDofCount() == 0 ? 0.0 : q[j];
        SimTK::Transform X_JC;  // child frame in the joint frame
        if (joint.type == model::Joint::Type::Prismatic) {
            X_JC.updP() = angle * SimTK::Vec3(m_axis[j]);
        } else if (joint.type != model::Joint::Type::Fixed) {
            X_JC.updR().setRotationFromAngleAboutUnitVector(angle, m_axis[j]);
        }
        X_GB[m_childBody[j]] = X_GB[m_parentBody[j]] * m_X_PJ[j] * X_JC;
    }
}

}  // namespace graspsim::planning
