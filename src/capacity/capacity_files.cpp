#include "graspsim/capacity/capacity_files.h"

#include "graspsim/io/atomic_file.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <sstream>

namespace graspsim::capacity {

namespace {

using Json = nlohmann::ordered_json;

Json valueOrNull(bool valid, double value) { return valid ? Json(value) : Json(nullptr); }

Json formatMeasurement(const GraspCapacity& c) {
    const std::string unit = c.torque ? "nm" : "n";
    Json j;
    j["direction"] = c.directionName;
    j["direction_vector"] = {c.direction[0] + 0.0, c.direction[1] + 0.0, c.direction[2] + 0.0};  // no -0
    j["load"] = c.torque ? "torque" : "force";
    j["method"] = c.method;
    j["contact"] = simulation::toString(c.contact);
    j["mode"] = simulation::toString(c.mode);
    j["realization"] = c.realization.empty() ? Json(nullptr) : Json(c.realization);
    j["load_start_s"] = c.start;
    const bool ramp = c.method == "ramp";
    const CapacityFigures& f = c.trace.figures;
    j["rate"] = valueOrNull(ramp, c.rate);
    j["slip_threshold_m"] = c.criteria.slip;
    j["drop_threshold_m"] = c.criteria.drop;
    j["slip_onset_" + unit] = ramp ? valueOrNull(f.slipped, f.slipOnsetLoad) : Json(c.bisection.findEstimate());
    j["drop_" + unit] = valueOrNull(ramp && f.dropped, f.dropLoad);
    j["slip_onset_time_s"] = valueOrNull(ramp && f.slipped, f.slipOnsetTime);
    j["drop_time_s"] = valueOrNull(ramp && f.dropped, f.dropTime);
    if (c.mode == simulation::SimulationMode::Approx) {
        j["release_" + unit] = valueOrNull(ramp && f.released, f.releaseLoad);
        j["release_time_s"] = valueOrNull(ramp && f.released, f.releaseTime);
        j["release_reason"] = c.trace.releaseReason.empty() ? Json(nullptr) : Json(c.trace.releaseReason);
    }
    if (!ramp) {
        j["bracket_held_" + unit] = c.bisection.held;
        j["bracket_slipped_" + unit] = c.bisection.slipped;
        j["runs"] = c.bisection.runs;
    }
    if (!c.trace.failure.empty()) j["failure"] = c.trace.failure;
    j["wall_time_s"] = c.wallTime;
    return j;
}

std::string formatNumber(double value, const char* format) {
    char text[64];
    std::snprintf(text, sizeof text, format, value);
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
    out << "direction,load,time_s,load_value,slip_m,rotation_rad,held,engaged\n";
    for (const GraspCapacity& c : measurements) {
        for (const CapacitySample& s : c.trace.samples) {
            out << c.directionName << ',' << (c.torque ? "torque" : "force") << ',' << formatNumber(s.time, "%.4f") << ','
                << formatNumber(s.load, "%.6g") << ',' << formatNumber(s.slip, "%.6g") << ','
                << formatNumber(s.rotation, "%.6g") << ',' << (s.held ? 1 : 0) << ',' << s.engaged << '\n';
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
    const CapacityFigures& f = c.trace.figures;
    text += f.slipped ? "slips at " + formatNumber(f.slipOnsetLoad, "%.4g") + unit : "no slip up to " +
                        formatNumber(c.trace.samples.empty() ? 0 : c.trace.samples.back().load, "%.4g") + unit;
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
