#include "graspsim/model/joint_chain.h"

#include "graspsim/error.h"

namespace graspsim::model {

void addRevoluteChain(ModelDescription& model, const std::string& parent, const Transform& X_PJ,
                      const std::vector<RevoluteSpec>& dofs, Body child) {
    if (dofs.empty()) throw Error("addRevoluteChain: joint chain for '" + child.name + "' has no DOF");
    std::string inboard = parent;
    Transform X_inboard = X_PJ;
    for (std::size_t k = 0; k < dofs.size(); ++k) {
        const RevoluteSpec& dof = dofs[k];
        const bool last = k + 1 == dofs.size();
        std::string outboard = child.name;
        if (!last) {
            Body virtualBody;
            virtualBody.name = child.name + "__" + dof.name;
            virtualBody.segment = child.segment;
            virtualBody.role = child.role;
            model.bodies.push_back(virtualBody);
            outboard = virtualBody.name;
        }
        Joint joint;
        joint.name = dof.name;
        joint.type = Joint::Type::Revolute;
        joint.parent = inboard;
        joint.child = outboard;
        joint.X_PJ = X_inboard;
        joint.axis = dof.axis;
        joint.lower = dof.lower;
        joint.upper = dof.upper;
        joint.stiffness = dof.stiffness;
        joint.damping = dof.damping;
        model.joints.push_back(joint);
        // Later joints of the chain sit at the same point: their frames coincide at q = 0.
        inboard = outboard;
        X_inboard = Transform::identity();
    }
    model.bodies.push_back(std::move(child));
}

void addFixedBody(ModelDescription& model, const std::string& parent, const Transform& X_PJ, Body child) {
    Joint joint;
    joint.name = child.name + "_fixed";
    joint.type = Joint::Type::Fixed;
    joint.parent = parent;
    joint.child = child.name;
    joint.X_PJ = X_PJ;
    model.joints.push_back(joint);
    model.bodies.push_back(std::move(child));
}

}  // namespace graspsim::model
