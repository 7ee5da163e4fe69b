#include "graspsim/validation/capacity_comparison.h"

#include "number_text.h"
#include "graspsim/capacity/capacity_files.h"
#include "graspsim/capacity/capacity_plot.h"
#include "graspsim/capacity/load_direction.h"
#include "graspsim/scenario/scenario_file.h"
#include "graspsim/validation/validation_plan.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <sstream>

namespace graspsim::validation {

namespace {

struct Load {
    std::string name;
    capacity::LoadDirection direction;
    bool torque = false;
};

std::vector<Load> listLoads(bool quick) {
    std::vector<Load> loads;
    for (const capacity::LoadDirection& d : capacity::findAxisDirections()) {
        if (quick && d.name != "-y") continue;
        loads.push_back({d.name, d, false});
    }
    if (quick) return loads;
    for (const char* axis : {"x", "y", "z"}) {
        loads.push_back({std::string("torque ") + axis, capacity::parseLoadDirection(axis, "capacity comparison"), true});
    }
    return loads;
}

std::vector<std::string> listVariants(const CapacityPlan& plan) {
    std::vector<std::string> variants{"full"};
    for (const std::string& v : plan.variants.empty() ? getAvailableVariants() : plan.variants) {
        if (v.rfind("approx", 0) == 0) variants.push_back(v);
        // Quick: the default realization only, unless variants were named.
        if (plan.quick && plan.variants.empty() && variants.size() == 2) break;
    }
    // The other friction-limit models on the default realization, so that the report compares
    // them with the thesis's box (issue 17 item 3).
    if (!plan.quick && plan.variants.empty()) {
        for (const char* v : {"approx-bushing-merged-contact", "approx-bushing-merged-compliance"}) variants.push_back(v);
    }
    return variants;
}

std::string describeSlip(const CapacityRow& row) {
    const capacity::CapacityFigures& f = row.measured.trace.figures;
    const std::string unit = row.measured.torque ? " N m" : " N";
    if (!row.measured.trace.failure.empty() && !f.slipped) return "failed (integrator)";
    if (!f.slipped) return "no slip";
    std::string text = formatBriefNumber(f.slipOnsetLoad) + unit;
    if (row.hasReference) text += " (" + std::string(row.relativeDifference >= 0 ? "+" : "") + formatBriefNumber(100 * row.relativeDifference) + " %)";
    if (f.released && f.releaseLoad <= f.slipOnsetLoad) text += ", released first";
    return text;
}

}  // namespace

std::vector<CapacityRow> runCapacityComparison(const CapacityPlan& plan, const CapacityProgress& progress) {
    const std::vector<std::string> experiments = plan.experiments.empty() ? getThesisExperiments() : plan.experiments;
    const std::vector<std::string> variants = listVariants(plan);
    const std::vector<Load> loads = listLoads(plan.quick);
    const std::size_t count = experiments.size() * loads.size() * variants.size();
    std::vector<CapacityRow> rows;
    for (const std::string& experiment : experiments) {
        const scenario::Scenario scenario = scenario::findBuiltinScenario(experiment);
        for (const Load& load : loads) {
            const std::size_t full = rows.size();  // this load's full-contact row, run first
            for (const std::string& variant : variants) {
                if (progress) progress(rows.size(), count, experiment + " " + load.name + " " + variant);
                capacity::GraspCapacityRequest request;
                request.direction = load.direction.direction;
                request.directionName = load.name;
                request.torque = load.torque;
                CapacityRow row{experiment, load.name, variant, {}, false, 0};
                simulation::SimulationOptions options = makeVariantOptions(variant, "none", 0);
                options.accuracy = plan.accuracy;
                options.integrator = plan.integrator;
                row.measured = capacity::measureGraspCapacityRamp(scenario, options, request);
                const capacity::CapacityFigures& f = row.measured.trace.figures;
                if (variant != "full" && rows[full].measured.trace.figures.slipped && f.slipped) {
                    row.hasReference = true;
                    const double reference = rows[full].measured.trace.figures.slipOnsetLoad;
                    row.relativeDifference = (f.slipOnsetLoad - reference) / reference;
                }
                rows.push_back(std::move(row));
            }
        }
    }
    return rows;
}

std::string formatCapacityCsv(const std::vector<CapacityRow>& rows) {
    std::ostringstream csv;
    csv << "experiment,load,variant,unit,rate,slipped,slip_onset,slip_onset_time_s,dropped,drop,released,release_load,"
           "relative_difference_to_full,release_reason,failure,wall_time_s\n";
    for (const CapacityRow& r : rows) {
        const capacity::CapacityFigures& f = r.measured.trace.figures;
        csv << r.experiment << "," << r.load << "," << r.variant << "," << (r.measured.torque ? "N m" : "N") << ","
            << formatExactNumber(r.measured.rate) << "," << (f.slipped ? 1 : 0) << "," << (f.slipped ? formatExactNumber(f.slipOnsetLoad) : "") << ","
            << (f.slipped ? formatExactNumber(f.slipOnsetTime) : "") << "," << (f.dropped ? 1 : 0) << "," << (f.dropped ? formatExactNumber(f.dropLoad) : "")
            << "," << (f.released ? 1 : 0) << "," << (f.released ? formatExactNumber(f.releaseLoad) : "") << ","
            << (r.hasReference ? formatExactNumber(r.relativeDifference) : "") << ",\"" << r.measured.trace.releaseReason << "\",\""
            << r.measured.trace.failure << "\"," << formatExactNumber(r.measured.wallTime) << "\n";
    }
    return csv.str();
}

std::string formatCapacityMarkdown(const std::vector<CapacityRow>& rows) {
    if (rows.empty()) return "";
    std::ostringstream md;
    md << "\n## Holding capacity: full contact against the approximation\n\n"
       << "Slip onset of a load ramped from the settled grasp (graspsim capacity; the difference to full contact's in "
          "parentheses; \"released first\": the approximation let go at or before that load, and the slip was then full "
          "contact's). Every ramp's figures are in capacity.csv.\n";
    std::string experiment;
    std::vector<std::string> variants;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (rows[i].experiment != experiment) {
            experiment = rows[i].experiment;
            variants.clear();
            for (std::size_t j = i; j < rows.size() && rows[j].experiment == experiment && rows[j].load == rows[i].load; ++j) {
                variants.push_back(rows[j].variant);
            }
            md << "\n### " << experiment << "\n\n| load |";
            for (const std::string& v : variants) md << " " << v << " |";
            md << "\n|---|";
            for (std::size_t v = 0; v < variants.size(); ++v) md << "---|";
            md << "\n";
        }
        if (rows[i].variant == variants.front()) md << "| " << rows[i].load << " |";
        md << " " << describeSlip(rows[i]) << " |";
        if (rows[i].variant == variants.back()) md << "\n";
    }
    return md.str();
}

std::vector<std::string> drawCapacityComparisonPlots(const std::string& folder, const std::vector<CapacityRow>& rows) {
    // Experiment -> variant -> its ramps, in the rows' order.
    std::map<std::string, std::vector<std::pair<std::string, std::vector<capacity::GraspCapacity>>>> runs;
    for (const CapacityRow& r : rows) {
        auto& variants = runs[r.experiment];
        auto v = std::find_if(variants.begin(), variants.end(), [&](const auto& entry) { return entry.first == r.variant; });
        if (v == variants.end()) v = variants.insert(variants.end(), {r.variant, {}});
        v->second.push_back(r.measured);
    }
    std::vector<std::string> plots;
    for (const auto& [experiment, variants] : runs) {
        std::vector<std::string> folders;
        for (const auto& [variant, measurements] : variants) {
            const std::string runFolder = folder + "/capacity/" + experiment + "/" + variant;
            std::filesystem::create_directories(runFolder);
            capacity::writeCapacityFiles(runFolder, experiment, measurements);
            folders.push_back(runFolder);
        }
        const std::string png = "capacity_" + experiment + ".png";
        if (capacity::drawCapacityPlot(folder + "/" + png, folders).skipped.empty()) plots.push_back(png);
    }
    return plots;
}

}  // namespace graspsim::validation
