#include "graspsim/model/hand_model.h"

#include "graspsim/anthropometry/finger_table.h"
#include "graspsim/anthropometry/proportion_table.h"
#include "graspsim/anthropometry/joint_ranges.h"
#include "graspsim/anthropometry/segment_table.h"
#include "graspsim/model/geometry_inertia.h"
#include "graspsim/model/joint_chain.h"

#include <cmath>
#include <vector>

namespace graspsim::model {

namespace {

using anthropometry::Digit;

// Everything the hand's shape needs, in metres, for one subject.
struct HandSizes {
    double length = 0;     // HL
    double breadth = 0;    // metacarpal breadth
    double thickness = 0;  // palm thickness
    double carpus = 0;     // wrist joint centre to the base of the metacarpals along the hand axis
};

struct Builder {
    Builder(ModelDescription& m, const HandSpec& s) : model(m), spec(s) {}

    ModelDescription& model;
    const HandSpec& spec;
    const anthropometry::ProportionTable proportions = anthropometry::ProportionTable::loadHand();
    const anthropometry::FingerTable fingers = anthropometry::FingerTable::loadBuchholz();
    const anthropometry::JointRanges ranges = anthropometry::JointRanges::loadDefault();
    HandSizes sizes;
    std::vector<std::string> handBodies;  // every massive body of this hand, to share the mass

    std::string named(const std::string& base) const { return spec.prefix + base; }

    RevoluteSpec fingerDof(const std::string& name, const std::string& rangeKey, const Vec3& axis) const {
        const anthropometry::JointRange& r = ranges.get(rangeKey);
        return {named(name), axis, r.lower, r.upper, spec.fingerStiffness, spec.fingerDamping};
    }

    Body makePhalanx(const std::string& name, double length, double radius) {
        Body body;
        body.name = named(name);
        body.segment = "hand";
        body.role = BodyRole::Digit;
        Geometry capsule;
        capsule.type = Geometry::Type::Capsule;
        capsule.name = body.name + "_capsule";
        capsule.radius = radius;
        // The capsule spans the bone from joint to joint, caps included, so neighbours never overlap.
        capsule.length = length - 2 * radius;
        capsule.X_BG = Transform::axisAngle({1, 0, 0}, -M_PI / 2, {0, -length / 2, 0});
        body.geometry.push_back(capsule);
        handBodies.push_back(body.name);
        return body;
    }

    void addPalm(const std::string& parent, const Transform& X_PW);
    void addFinger(Digit digit, const std::string& digitName, double radialFraction, const Vec3& abductionAxis);
    void addThumb();
    void shareHandMass();
};

Geometry makeBox(const std::string& name, const Vec3& lo, const Vec3& hi) {
    Geometry box;
    box.type = Geometry::Type::Box;
    box.name = name;
    box.halfLengths = {(hi[0] - lo[0]) / 2, (hi[1] - lo[1]) / 2, (hi[2] - lo[2]) / 2};
    box.X_BG = Transform::translation({(hi[0] + lo[0]) / 2, (hi[1] + lo[1]) / 2, (hi[2] + lo[2]) / 2});
    return box;
}

double mcpDepth(const anthropometry::DigitLengths& digit, const HandSizes& s) {
    return s.carpus + digit.metacarpal * s.length;
}

void Builder::addPalm(const std::string& parent, const Transform& X_PW) {
    const double T = sizes.thickness, B = sizes.breadth;
    const double littleDepth = mcpDepth(fingers.getDigit(Digit::Little), sizes);
    const double ringDepth = mcpDepth(fingers.getDigit(Digit::Ring), sizes);
    const double ringRadial = proportions.get("ring_mcp_lateral_per_hand_breadth");
    const double littleRadial = proportions.get("little_mcp_lateral_per_hand_breadth");
    // Ulnar edge of the distal box: halfway between the ring and little MCP joints.
    const double zUlnar = B * (0.5 - (ringRadial + littleRadial) / 2);
    Body palm;
    palm.name = named("palm");
    palm.segment = "hand";
    palm.role = BodyRole::Palm;
    palm.geometry.push_back(makeBox(palm.name + "_proximal_box", {-T / 2, -littleDepth, -B / 2}, {T / 2, 0, B / 2}));
    palm.geometry.push_back(makeBox(palm.name + "_distal_box", {-T / 2, -ringDepth, zUlnar}, {T / 2, -littleDepth, B / 2}));
    handBodies.push_back(palm.name);
    const auto& flex = ranges.get("wrist_flexion");
    const auto& dev = ranges.get("wrist_deviation");
    addRevoluteChain(model, parent, X_PW,
                     {{named("wrist_flexion"), {0, 0, 1}, flex.lower, flex.upper, spec.wristStiffness, spec.wristDamping},
                      {named("wrist_deviation"), {-1, 0, 0}, dev.lower, dev.upper, spec.wristStiffness, spec.wristDamping}},
                     std::move(palm));
}

void Builder::addFinger(Digit digit, const std::string& d, double radialFraction, const Vec3& abductionAxis) {
    const anthropometry::DigitLengths& len = fingers.getDigit(digit);
    const double HL = sizes.length;
    const Vec3 p_mcp{0, -mcpDepth(len, sizes), sizes.breadth * (0.5 - radialFraction)};
    const double rP = proportions.get("finger_proximal_radius_per_hand_length") * HL;
    const double rM = proportions.get("finger_middle_radius_per_hand_length") * HL;
    const double rD = proportions.get("finger_distal_radius_per_hand_length") * HL;
    const Vec3 flexion{0, 0, 1};
    addRevoluteChain(model, named("palm"), Transform::translation(p_mcp),
                     {fingerDof(d + "_mcp_abduction", "mcp_abduction", abductionAxis),
                      fingerDof(d + "_mcp_flexion", "mcp_flexion", flexion)},
                     makePhalanx(d + "_proximal", len.proximal * HL, rP));
    addRevoluteChain(model, named(d + "_proximal"), Transform::translation({0, -len.proximal * HL, 0}),
                     {fingerDof(d + "_pip_flexion", "pip_flexion", flexion)}, makePhalanx(d + "_middle", len.middle * HL, rM));
    addRevoluteChain(model, named(d + "_middle"), Transform::translation({0, -len.middle * HL, 0}),
                     {fingerDof(d + "_dip_flexion", "dip_flexion", flexion)}, makePhalanx(d + "_distal", len.distal * HL, rD));
    // The pad: palmar side of the distal cap's centre.
    model.endEffectors.push_back({named(d + "_tip"), named(d + "_distal"), {rD, -(len.distal * HL - rD), 0}});
}

void Builder::addThumb() {
    const anthropometry::DigitLengths& len = fingers.getDigit(Digit::Thumb);
    const double HL = sizes.length;
    const double rMc = proportions.get("thumb_metacarpal_radius_per_hand_length") * HL;
    const double rP = proportions.get("thumb_proximal_radius_per_hand_length") * HL;
    const double rD = proportions.get("thumb_distal_radius_per_hand_length") * HL;
    // At q = 0 the thumb lies alongside the index finger (AAOS zero); its metacarpal capsule,
    // which stands for the thenar eminence too, overlaps the palm box a little.
    const Vec3 p_cmc{proportions.get("thumb_cmc_palmar_per_hand_length") * HL,
                     -proportions.get("thumb_cmc_distal_per_hand_length") * HL,
                     proportions.get("thumb_cmc_radial_per_hand_length") * HL};
    const Transform X_PC = Transform::translation(p_cmc);
    // Thumb flexion curls toward the ulnar side (-z), palmar abduction lifts it off the palm (+x).
    const Vec3 flexion{1, 0, 0};
    addRevoluteChain(model, named("palm"), X_PC,
                     {fingerDof("thumb_cmc_abduction", "thumb_cmc_abduction", {0, 0, 1}),
                      fingerDof("thumb_cmc_flexion", "thumb_cmc_flexion", flexion)},
                     makePhalanx("thumb_metacarpal", len.metacarpal * HL, rMc));
    addRevoluteChain(model, named("thumb_metacarpal"), Transform::translation({0, -len.metacarpal * HL, 0}),
                     {fingerDof("thumb_mcp_flexion", "thumb_mcp_flexion", flexion)},
                     makePhalanx("thumb_proximal", len.proximal * HL, rP));
    addRevoluteChain(model, named("thumb_proximal"), Transform::translation({0, -len.proximal * HL, 0}),
                     {fingerDof("thumb_ip_flexion", "thumb_ip_flexion", flexion)},
                     makePhalanx("thumb_distal", len.distal * HL, rD));
    model.endEffectors.push_back({named("thumb_tip"), named("thumb_distal"), {0, -(len.distal * HL - rD), -rD}});
}

// One density for the whole hand: each part's mass is the de Leva hand mass times its volume share.
void Builder::shareHandMass() {
    const anthropometry::SegmentTable table = anthropometry::SegmentTable::loadDeLeva(spec.subject.sex);
    const double handMass = table.getSegment("hand").massFraction * spec.subject.mass;
    double volume = 0;
    for (const std::string& name : handBodies) {
        for (const Geometry& g : model.findBody(name)->geometry) volume += calcVolume(g);
    }
    const double density = handMass / volume;
    for (const std::string& name : handBodies) {
        Body& body = *model.updBody(name);
        const MassProperties mp = calcSolidMassProperties(body.geometry, density);
        body.mass = mp.mass;
        body.p_BCm = mp.p_BCm;
        body.inertia = mp.inertia;
    }
}

}  // namespace

double calcHandLength(const anthropometry::Subject& subject) {
    return anthropometry::ProportionTable::loadHand().get("hand_length_per_stature") * subject.stature;
}

void addHand(ModelDescription& model, const std::string& parent, const Transform& X_PW, const HandSpec& spec) {
    Builder b(model, spec);
    b.sizes.length = calcHandLength(spec.subject);
    b.sizes.breadth = b.proportions.get("hand_breadth_per_hand_length") * b.sizes.length;
    b.sizes.thickness = b.proportions.get("palm_thickness_per_hand_length") * b.sizes.length;
    const anthropometry::DigitLengths& middle = b.fingers.getDigit(Digit::Middle);
    b.sizes.carpus = b.sizes.length * (1 - middle.metacarpal - middle.proximal - middle.middle - middle.distal);

    b.addPalm(parent, X_PW);
    b.addFinger(Digit::Index, "index", b.proportions.get("index_mcp_lateral_per_hand_breadth"), {-1, 0, 0});
    b.addFinger(Digit::Middle, "middle", b.proportions.get("middle_mcp_lateral_per_hand_breadth"), {-1, 0, 0});
    b.addFinger(Digit::Ring, "ring", b.proportions.get("ring_mcp_lateral_per_hand_breadth"), {1, 0, 0});
    b.addFinger(Digit::Little, "little", b.proportions.get("little_mcp_lateral_per_hand_breadth"), {1, 0, 0});
    b.addThumb();
    b.shareHandMass();
}

}  // namespace graspsim::model
