#include "graspsim/model/thesis_preset.h"

#include "graspsim/error.h"

#include <set>

namespace graspsim::model {

namespace {

void scaleMass(Body& body, double newMass) {
    const double ratio = newMass / body.mass;
    body.mass = newMass;
    Inertia& I = body.inertia;
    for (double* c : {&I.xx, &I.yy, &I.zz, &I.xy, &I.xz, &I.yz}) *c *= ratio;
}

// The side prefix of a body ("", "r_" or "l_"): what precedes its anatomical part name.
std::string prefixOf(const Body& body, const std::string& part) {
    return body.name.substr(0, body.name.size() - part.size());
}

}  // namespace

void applyThesisPreset(ModelDescription& model) {
    std::set<std::string> sides;  // side prefixes ("", "r_", "l_") of every hand in the model
    for (Body& body : model.bodies) {
        if (body.segment != "hand" || body.isVirtual()) continue;
        const bool palm = body.role == BodyRole::Palm;
        scaleMass(body, palm ? kThesisPalmMass : kThesisFingerSegmentMass);
        if (palm) sides.insert(prefixOf(body, "palm"));
    }
    for (const std::string& prefix : sides) {
        Body* upperArm = model.updBody(prefix + "upper_arm");
        Body* forearm = model.updBody(prefix + "forearm");
        if (!upperArm || !forearm) throw Error("thesis preset: arm '" + prefix + "' has no upper_arm/forearm");
        const double handMass = kThesisPalmMass + 15 * kThesisFingerSegmentMass;
        const double scale = (kThesisArmMass - handMass) / (upperArm->mass + forearm->mass);
        scaleMass(*upperArm, upperArm->mass * scale);
        scaleMass(*forearm, forearm->mass * scale);
    }
}

}  // namespace graspsim::model
