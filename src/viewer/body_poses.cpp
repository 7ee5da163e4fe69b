#include "graspsim/viewer/body_poses.h"

#include "graspsim/error.h"

#include <unordered_map>

namespace graspsim::viewer {

namespace {

model::Transform findJointMotion(const model::Joint& joint, double q) {
    switch (joint.type) {
    case model::Joint::Type::Revolute:
    case model::Joint::Type::Continuous:
        return model::Transform::axisAngle(joint.axis, q);
    case model::Joint::Type::Prismatic:
        return model::Transform::translation({joint.axis[0] * q, joint.axis[1] * q, joint.axis[2] * q});
    case model::Joint::Type::Fixed:
        break;
    }
    return model::Transform::identity();
}

}  // namespace

std::vector<model::Transform> calcBodyPoses(const model::ModelDescription& model,
                                            const std::map<std::string, double>& jointAngles) {
    std::unordered_map<std::string, std::size_t> index;
    for (std::size_t b = 0; b < model.bodies.size(); ++b) index[model.bodies[b].name] = b;
    std::vector<model::Transform> X_GB(model.bodies.size(), model.X_GR);
    std::vector<bool> done(model.bodies.size(), false);
    if (!model.bodies.empty()) done[0] = true;
    // Joints may come in any order: sweep until every child is placed (a tree of N bodies needs at
    // most N sweeps; the builders' order needs one).
    for (std::size_t sweep = 0; sweep < model.bodies.size(); ++sweep) {
        bool progress = false;
        for (const model::Joint& joint : model.joints) {
            const std::size_t parent = index.at(joint.parent), child = index.at(joint.child);
            if (done[child] || !done[parent]) continue;
            const auto q = jointAngles.find(joint.name);
            X_GB[child] = X_GB[parent] * joint.X_PJ * findJointMotion(joint, q == jointAngles.end() ? 0.0 : q->second);
            done[child] = progress = true;
        }
        if (!progress) break;
    }
    for (std::size_t b = 0; b < done.size(); ++b) {
        if (!done[b]) throw Error("model '" + model.name + "': body '" + model.bodies[b].name + "' is not reachable from the root");
    }
    return X_GB;
}

}  // namespace graspsim::viewer
