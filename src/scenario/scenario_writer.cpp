#include "graspsim/scenario/scenario_writer.h"

#include "graspsim/anthropometry/units.h"

#include <charconv>
#include <sstream>

namespace graspsim::scenario {

namespace {

// The shortest text that reads back to the same double (0.005, not 0.0050000000000000001): exact
// and readable. Zero without a sign: "-0" is noise in a file a user reads.
std::string formatNumber(double value) {
    char buffer[32];
    const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof buffer, value == 0 ? 0.0 : value);
    return std::string(buffer, r.ptr);
}

// An angle in degrees: the shortest text that the reader (anthropometry::fromDegrees of the
// number) turns back into the same radians. The shortest text of radians / (pi / 180) alone is
// not enough: dividing 16.4 deg's radians by it gives 16.400000000000002, and that text reads
// back a bit away. An angle no decimal reads back to exactly keeps that closest text.
std::string formatDegrees(double radians) {
    const double degrees = radians / anthropometry::fromDegrees(1.0);
    for (int digits = 1; digits <= 17; ++digits) {
        char buffer[32];
        const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof buffer, degrees, std::chars_format::general, digits);
        double read = 0;
        std::from_chars(buffer, r.ptr, read);
        if (anthropometry::fromDegrees(read) == radians) return formatNumber(read);
    }
    return formatNumber(degrees);
}

std::string formatVec3(const Vec3& v) {
    return "[" + formatNumber(v[0]) + ", " + formatNumber(v[1]) + ", " + formatNumber(v[2]) + "]";
}

std::string formatDegreesVec3(const Vec3& radians) {
    return "[" + formatDegrees(radians[0]) + ", " + formatDegrees(radians[1]) + ", " + formatDegrees(radians[2]) + "]";
}

// YAML double-quoted scalar: names and descriptions may hold ':' or '#'.
std::string quote(const std::string& text) {
    std::string quoted = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') quoted += '\\';
        quoted += c;
    }
    return quoted + "\"";
}

void writeObjectDimensions(std::ostringstream& out, const ObjectSpec& o) {
    switch (o.shape) {
        case ObjectShape::Sphere: out << "  radius: " << formatNumber(o.radius) << "\n"; break;
        case ObjectShape::Box: out << "  size: " << formatVec3(o.size) << "\n"; break;
        case ObjectShape::Cylinder:
        case ObjectShape::Capsule:
            out << "  radius: " << formatNumber(o.radius) << "\n  length: " << formatNumber(o.length) << "\n";
            break;
        case ObjectShape::Ellipsoid: out << "  semi_axes: " << formatVec3(o.semiAxes) << "\n"; break;
        case ObjectShape::Mesh: {
            // Absolute: a written scenario (a result folder's copy, a planned scenario) lies
            // elsewhere than the one read, and must still find the same file.
            out << "  mesh: " << quote(o.meshPath.empty() ? o.mesh : o.meshPath) << "\n";
            const Vec3& s = o.meshScale;
            if (s[0] == s[1] && s[1] == s[2]) out << "  scale: " << formatNumber(s[0]) << "\n";
            else out << "  scale: " << formatVec3(s) << "\n";
            break;
        }
    }
}

void writeSubjectAndObject(std::ostringstream& out, const Scenario& s) {
    const anthropometry::Subject& subject = s.bodyOptions.subject;
    out << "subject:\n  sex: " << anthropometry::toString(subject.sex) << "\n  mass: " << formatNumber(subject.mass)
        << "\n  stature: " << formatNumber(subject.stature) << "\n  preset: " << model::toString(s.bodyOptions.preset) << "\n\n";
    const ObjectSpec& o = s.object;
    out << "object:\n  shape: " << toString(o.shape) << "\n  mass: " << formatNumber(o.mass) << "\n";
    writeObjectDimensions(out, o);
    out << "  position: " << formatVec3(o.position) << "\n  orientation: " << formatDegreesVec3(o.orientation) << "  # deg\n\n";
}

void writePoseAndGoals(std::ostringstream& out, const Scenario& s) {
    out << "grasp_pose:  # deg\n";
    for (const auto& [joint, angle] : s.graspPose) out << "  " << joint << ": " << formatDegrees(angle) << "\n";
    const std::vector<model::SegmentPoint>& points = s.bodyOptions.segmentPoints;
    if (!points.empty()) out << "\nend_effectors:  # points fixed on a segment, m in its body frame\n";
    for (const model::SegmentPoint& p : points) {
        out << "  " << p.name << ": {body: " << p.body << ", point: " << formatVec3({p.p_B[0], p.p_B[1], p.p_B[2]}) << "}\n";
    }
    out << "\ngoals:  # m, object frame\n";
    for (const auto& [effector, p_OG] : s.goals) out << "  " << effector << ": " << formatVec3(p_OG) << "\n";
    out << "\nperturbations:" << (s.perturbations.empty() ? "  # none\n" : "\n");
    for (const Perturbation& p : s.perturbations) {
        out << "  " << p.name << ": {force: " << formatVec3(p.force) << ", start: " << formatNumber(p.start)
            << ", duration: " << formatNumber(p.duration) << "}\n";
    }
    out << "\n";
}

void writeSettings(std::ostringstream& out, const Scenario& s) {
    const contact::ContactParameters& c = s.contact;
    out << "contact:\n  stiffness: " << formatNumber(c.effectiveStiffness) << "\n  dissipation: " << formatNumber(c.dissipation)
        << "\n  static_friction: " << formatNumber(c.staticFriction) << "\n  dynamic_friction: " << formatNumber(c.dynamicFriction)
        << "\n  viscous_friction: " << formatNumber(c.viscousFriction)
        << "\n  transition_velocity: " << formatNumber(c.transitionVelocity) << "\n";
    // The default rule leaves the file as it was.
    if (c.capsuleContact != contact::CapsuleContact::Deepest) out << "  capsule_contact: " << contact::toString(c.capsuleContact) << "\n";
    const contact::FrictionSettings& f = s.friction;
    if (f.model != contact::FrictionModel::Regularized) {  // the default law leaves the file as it was
        out << "  friction_model: " << contact::toString(f.model)
            << "\n  anchor_stiffness_ratio: " << formatNumber(f.anchor.stiffnessRatio)
            << "\n  anchor_damping_mass: " << formatNumber(f.anchor.dampingMass)
            << "\n  anchor_relaxation_time: " << formatNumber(f.anchor.relaxationTime) << "\n";
    }
    out << "\n";
    const ControllerSpec& k = s.controller;
    out << "controller:\n  approach_time: " << formatNumber(k.approachTime) << "\n  press_depth: " << formatNumber(k.pressDepth)
        << "\n  kp: " << formatNumber(k.kp) << "\n  kd: " << formatNumber(k.kd) << "\n  ik_interval: " << formatNumber(k.ikInterval)
        << "\n\n";
    const SimulationSpec& m = s.simulation;
    out << "simulation:\n  duration: " << formatNumber(m.duration) << "\n  output_interval: " << formatNumber(m.outputInterval)
        << "\n  accuracy: " << formatNumber(m.accuracy);
    // Left out when unset, so that the file keeps the integrator's own default (findStepSize).
    if (m.stepSize > 0) out << "\n  step_size: " << formatNumber(m.stepSize);
    out << "\n  settle_time: " << formatNumber(m.settleTime) << "\n  held_tolerance: " << formatNumber(m.heldTolerance) << "\n\n";
    const ApproximationSpec& a = s.approximation;
    out << "approximation:\n  relaxed_axes: [";
    bool first = true;
    for (int k2 = 0; k2 < 6; ++k2) {
        if (!a.relaxedAxes[static_cast<std::size_t>(k2)]) continue;
        out << (first ? "" : ", ") << ApproximationSpec::kAxisNames[k2];
        first = false;
    }
    out << "]\n  q_threshold: " << formatNumber(a.qThreshold) << "\n  q_minimum: " << formatNumber(a.qMinimum) << "\n";
}

}  // namespace

std::string formatScenarioYaml(const Scenario& scenario, const std::string& header) {
    std::ostringstream out;
    std::istringstream lines(header);
    for (std::string line; std::getline(lines, line);) out << "# " << line << "\n";
    if (!header.empty()) out << "\n";
    out << "name: " << quote(scenario.name) << "\n";
    out << "description: " << quote(scenario.description) << "\n\n";
    out << "world:\n  gravity: " << formatVec3(scenario.world.gravity) << "\n\n";
    writeSubjectAndObject(out, scenario);
    writePoseAndGoals(out, scenario);
    writeSettings(out, scenario);
    return out.str();
}

}  // namespace graspsim::scenario
