#include "graspsim/capacity/capacity_files.h"

#include "graspsim/capacity/overload.h"

#include "graspsim/io/atomic_file.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <sstream>

namespace graspsim::capacity {

namespace {

using Json = nlohmann::ordered_json;

Json valueOrNull(bool valid, double value) { return valid ? Json(value) : Json(nullptr); }

Json numberOrNull(double value) { return valueOrNull(std::isfinite(value), value); }

// Grip force at the load's start and at the slip onset (null where the approximation was engaged).
void addGripForces(const CapacityFigures& f, Json& j) {
    j["grip_force_start_n"] = numberOrNull(f.gripForceAtStart);
    j["grip_force_onset_n"] = numberOrNull(f.gripForceAtOnset);  // NaN without slip
}

// The ramp's figures: loads and times (on the scene's clock) of slip onset, drop and release.
void addRampFigures(const GraspCapacity& c, const std::string& unit, Json& j) {
    const CapacityFigures& f = c.trace.figures;
    j["slip_onset_" + unit] = valueOrNull(f.slipped, f.slipOnsetLoad);
    j["drop_" + unit] = valueOrNull(f.dropped, f.dropLoad);
    j["slip_onset_time_s"] = valueOrNull(f.slipped, f.slipOnsetTime);
    j["drop_time_s"] = valueOrNull(f.dropped, f.dropTime);
    // The last sample's: what a ramp without slip held up to.
    j["max_load_" + unit] = valueOrNull(!c.trace.samples.empty(), c.trace.samples.empty() ? 0 : c.trace.samples.back().load);
    addGripForces(f, j);
    if (c.mode != simulation::SimulationMode::Approx) return;
    j["release_" + unit] = valueOrNull(f.released, f.releaseLoad);
    j["release_time_s"] = valueOrNull(f.released, f.releaseTime);
    j["release_reason"] = c.trace.releaseReason.empty() ? Json(nullptr) : Json(c.trace.releaseReason);
}

// A constant load's: the load and hold, and the times of slip onset, drop and release after the
// load's start.
void addConstantFigures(const GraspCapacity& c, const std::string& unit, Json& j) {
    const OverloadFigures f = findOverloadFigures(c.trace.figures, c.start);
    j["load_" + unit] = c.load;
    j["hold_s"] = c.hold;
    j["slip_onset_time_s"] = valueOrNull(f.slipped, f.slipOnsetTime);
    j["drop_time_s"] = valueOrNull(f.dropped, f.dropTime);
    addGripForces(c.trace.figures, j);
    if (c.mode != simulation::SimulationMode::Approx) return;
    j["release_time_s"] = valueOrNull(f.released, f.releaseTime);
    j["release_reason"] = c.trace.releaseReason.empty() ? Json(nullptr) : Json(c.trace.releaseReason);
}

void addBisectionFigures(const GraspCapacity& c, const std::string& unit, Json& j) {
    j["slip_onset_" + unit] = c.bisection.findEstimate();
    j["drop_" + unit] = nullptr;
    j["slip_onset_time_s"] = nullptr;
    j["drop_time_s"] = nullptr;
    if (c.mode == simulation::SimulationMode::Approx) {
        j["release_" + unit] = nullptr;
        j["release_time_s"] = nullptr;
        j["release_reason"] = nullptr;
    }
    j["bracket_held_" + unit] = c.bisection.held;
    j["bracket_slipped_" + unit] = c.bisection.slipped;
    j["runs"] = c.bisection.runs;
}

Json formatMeasurement(const GraspCapacity& c) {
    const std::string unit = c.torque ? "nm" : "n";
    Json j;
    j["direction"] = c.directionName;
    j["direction_vector"] = {c.direction[0] + 0.0, c.direction[1] + 0.0, c.direction[2] + 0.0};  // no -0
    j["load"] = c.torque ? "torque" : "force";
    j["method"] = c.method;
    j["contact"] = simulation::toString(c.contact);
    if (c.friction) j["friction"] = contact::toString(*c.friction);  // the default law's files stay as they were
    if (c.capsuleContact) j["capsule_contact"] = contact::toString(*c.capsuleContact);  // so do the default rule's
    j["mode"] = simulation::toString(c.mode);
    j["realization"] = c.realization.empty() ? Json(nullptr) : Json(c.realization);
    j["load_start_s"] = c.start;
    j["rate"] = valueOrNull(c.method == "ramp", c.rate);
    j["slip_threshold_m"] = c.criteria.slip;
    j["drop_threshold_m"] = c.criteria.drop;
    if (c.method == "ramp") addRampFigures(c, unit, j);
    if (c.method == "constant") addConstantFigures(c, unit, j);
    if (c.method == "bisection") addBisectionFigures(c, unit, j);
    if (!c.trace.failure.empty()) j["failure"] = c.trace.failure;
    j["wall_time_s"] = c.wallTime;
    return j;
}

std::string formatNumber(double value, const char* format) {
    char text[64];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

// "slips after 0.12 s, drops after 0.4 s of 2.5 N held 1 s" and the release, the failure.
std::string describeConstant(const GraspCapacity& c) {
    const OverloadFigures f = findOverloadFigures(c.trace.figures, c.start);
    const std::string load = formatNumber(c.load, "%.4g") + (c.torque ? " N m" : " N");
    std::string text = f.slipped ? "slips after " + formatNumber(f.slipOnsetTime, "%.4g") + " s" : "no slip";
    if (f.slipped) text += f.dropped ? ", drops after " + formatNumber(f.dropTime, "%.4g") + " s" : ", not dropped";
    text += " of " + load + " held " + formatNumber(c.hold, "%.4g") + " s";
    if (!c.trace.failure.empty()) text += " [run stopped early: " + c.trace.failure + "]";
    if (f.released) {
        text += " (approximation released after " + formatNumber(f.releaseTime, "%.4g") + " s" +
                (c.trace.releaseReason.empty() ? "" : ": " + c.trace.releaseReason) + ")";
    }
    return text;
}

}  // namespace

std::string formatCapacityJson(const std::string& scenario, const std::vector<GraspCapacity>& measurements) {
    Json j;
    j["scenario"] = scenario;
    j["measurements"] = Json::array();
    for (const GraspCapacity& c : measurements) j["measurements"].push_back(formatMeasurement(c));
    return j.dump(2) + "\n";
}

std::string formatCapacityCsv(const std::vector<GraspCapacity>& measurements) {
    std::ostringstream out;
    out << "direction,load,time_s,load_value,slip_m,rotation_rad,held,engaged,grip_force_n\n";
    for (const GraspCapacity& c : measurements) {
        for (const CapacitySample& s : c.trace.samples) {
            out << c.directionName << ',' << (c.torque ? "torque" : "force") << ',' << formatNumber(s.time, "%.4f") << ','
                << formatNumber(s.load, "%.6g") << ',' << formatNumber(s.slip, "%.6g") << ','
                << formatNumber(s.rotation, "%.6g") << ',' << (s.held ? 1 : 0) << ',' << s.engaged << ','
                << (std::isfinite(s.gripForce) ? formatNumber(s.gripForce, "%.6g") : "") << '\n';
        }
    }
    return out.str();
}

std::string describeCapacity(const GraspCapacity& c) {
    const char* unit = c.torque ? " N m" : " N";
    std::string text = c.directionName + (c.torque ? " torque" : " force") + " (" + c.method + "): ";
    if (c.method == "bisection") {
        return text + "slips from " + formatNumber(c.bisection.findEstimate(), "%.4g") + unit + " (held " +
               formatNumber(c.bisection.held, "%.4g") + ", slipped " + formatNumber(c.bisection.slipped, "%.4g") + ")";
    }
    if (c.method == "constant") return text + describeConstant(c);
    const CapacityFigures& f = c.trace.figures;
    if (c.trace.samples.empty()) {
        text += "not measured";
    } else {
        text += f.slipped ? "slips at " + formatNumber(f.slipOnsetLoad, "%.4g") + unit
                          : "no slip up to " + formatNumber(c.trace.samples.back().load, "%.4g") + unit;
    }
    if (f.slipped) text += f.dropped ? ", drops at " + formatNumber(f.dropLoad, "%.4g") + unit : ", not dropped within the ramp";
    if (!c.trace.failure.empty()) text += " [run stopped early: " + c.trace.failure + "]";
    if (f.released) text += " (approximation released at " + formatNumber(f.releaseLoad, "%.4g") + unit + (c.trace.releaseReason.empty() ? "" : ": " + c.trace.releaseReason) + ")";
    return text;
}

void writeCapacityFiles(const std::string& folder, const std::string& scenario, const std::vector<GraspCapacity>& measurements) {
    io::writeFileAtomically(folder + "/capacity.json", formatCapacityJson(scenario, measurements));
    io::writeFileAtomically(folder + "/capacity.csv", formatCapacityCsv(measurements));
}

}  // namespace graspsim::capacity
