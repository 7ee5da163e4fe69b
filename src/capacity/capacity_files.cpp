#include "graspsim/capacity/capacity_files.h"

#include "graspsim/capacity/overload.h"

#include "graspsim/io/atomic_file.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <optional>
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

template <class J>
std::optional<double> findNumber(const J& m, const std::string& key) {
    const auto it = m.find(key);
    if (it == m.end() || !it->is_number()) return std::nullopt;
    return it->template get<double>();
}

// One entry of capacity.json in words; one template for the ordered JSON this file writes and the
// plain JSON a reader of the file has.
template <class J>
std::string describeFigures(const J& m) {
    const bool torque = m.value("load", std::string("force")) == "torque";
    const std::string unit = torque ? "nm" : "n";
    const auto load = [torque](double value) { return formatNumber(value, "%.4g") + (torque ? " N m" : " N"); };
    const auto seconds = [](double value) { return formatNumber(value, "%.4g") + " s"; };
    const std::optional<double> slip = findNumber(m, "slip_onset_" + unit), drop = findNumber(m, "drop_" + unit);
    const std::string method = m.value("method", std::string("ramp"));
    if (method == "bisection") {
        return "slips from " + (slip ? load(*slip) : "?") + " (held " + formatNumber(findNumber(m, "bracket_held_" + unit).value_or(NAN), "%.4g") +
               ", slipped " + formatNumber(findNumber(m, "bracket_slipped_" + unit).value_or(NAN), "%.4g") + ")";
    }
    if (method == "constant") {
        const std::optional<double> slipTime = findNumber(m, "slip_onset_time_s"), dropTime = findNumber(m, "drop_time_s");
        std::string text = slipTime ? "slips after " + seconds(*slipTime) : "no slip";
        if (slipTime) text += dropTime ? ", drops after " + seconds(*dropTime) : ", not dropped";
        return text + " of " + load(findNumber(m, "load_" + unit).value_or(NAN)) + " held " + seconds(findNumber(m, "hold_s").value_or(NAN));
    }
    const std::optional<double> reached = findNumber(m, "max_load_" + unit);
    std::string text = slip ? "slips at " + load(*slip) : reached ? "no slip up to " + load(*reached) : "not measured";
    if (slip) text += drop ? ", drops at " + load(*drop) : ", not dropped within the ramp";
    return text;
}

}  // namespace

std::string describeMeasuredFigures(const nlohmann::json& measurement) { return describeFigures(measurement); }

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
    std::string text = c.directionName + (c.torque ? " torque" : " force") + " (" + c.method + "): " + describeFigures(formatMeasurement(c));
    if (c.method == "bisection") return text;
    if (!c.trace.failure.empty()) text += " [run stopped early: " + c.trace.failure + "]";
    const CapacityFigures& f = c.trace.figures;
    if (!f.released) return text;
    const std::string reason = c.trace.releaseReason.empty() ? "" : ": " + c.trace.releaseReason;
    if (c.method == "constant") {
        return text + " (approximation released after " + formatNumber(findOverloadFigures(f, c.start).releaseTime, "%.4g") + " s" + reason + ")";
    }
    return text + " (approximation released at " + formatNumber(f.releaseLoad, "%.4g") + (c.torque ? " N m" : " N") + reason + ")";
}

void writeCapacityFiles(const std::string& folder, const std::string& scenario, const std::vector<GraspCapacity>& measurements) {
    io::writeFileAtomically(folder + "/capacity.json", formatCapacityJson(scenario, measurements));
    io::writeFileAtomically(folder + "/capacity.csv", formatCapacityCsv(measurements));
}

}  // namespace graspsim::capacity
