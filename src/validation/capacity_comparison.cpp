#include "graspsim/validation/capacity_comparison.h"

#include "number_text.h"
#include "graspsim/capacity/capacity_files.h"
#include "graspsim/capacity/capacity_plot.h"
#include "graspsim/capacity/load_direction.h"
#include "graspsim/capacity/overload.h"
#include "graspsim/capacity/settled_grasps.h"
#include "graspsim/io/parallel_runs.h"
#include "graspsim/scenario/scenario_file.h"
#include "graspsim/validation/validation_plan.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>

namespace graspsim::validation {

namespace {

// The default approximation: the realization and attachment a user gets without options.
const std::string kDefaultVariant = "approx-bushing-merged";

struct Load {
    std::string name;
    capacity::LoadDirection direction;
    bool torque = false;
};

std::vector<Load> listLoads(bool quick) {
    std::vector<Load> loads;
    for (const capacity::GraspCapacityRequest& r : capacity::makeAllDirectionRequests()) {
        if (quick && (r.torque || r.directionName != "-y")) continue;
        loads.push_back({(r.torque ? "torque " : "") + r.directionName, capacity::LoadDirection{r.directionName, r.direction}, r.torque});
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
    // The default realization on the thesis's switch (its box alone, no compliance release), the
    // other friction-limit models, and the default's release on the static model alone (no creep
    // watch), so that the report compares them with the default (issue 17 items 2 and 3).
    if (!plan.quick && plan.variants.empty()) {
        for (const char* v : {"approx-bushing-merged-thesis", "approx-bushing-merged-contact", "approx-bushing-merged-compliance",
                              "approx-bushing-merged-static"}) {
            variants.push_back(v);
        }
    }
    return variants;
}

capacity::GraspCapacityRequest makeRequest(const Load& load) {
    capacity::GraspCapacityRequest request;
    request.direction = load.direction.direction;
    request.directionName = load.name;
    request.torque = load.torque;
    return request;
}

simulation::SimulationOptions makeOptions(const std::string& variant, const CapacityPlan& plan) {
    simulation::SimulationOptions options = makeVariantOptions(variant, "none", 0);
    options.accuracy = plan.accuracy;
    options.integrator = plan.integrator;
    return options;
}

capacity::OverloadFigures findOverloadTimes(const capacity::GraspCapacity& c) {
    return capacity::findOverloadFigures(c.trace.figures, c.start);
}

// `row`'s constant load: kOverloadFactor x full contact's ramp onset (`full`'s; none if that ramp
// did not slip), on `row`'s variant.
void runOverload(capacity::SettledGrasps& grasps, const Load& load, const CapacityRow& full, CapacityRow& row) {
    const capacity::CapacityFigures& ramp = full.measured.trace.figures;
    if (!ramp.slipped) return;
    row.overload = capacity::measureGraspCapacityConstant(grasps, makeRequest(load), kOverloadFactor * ramp.slipOnsetLoad, kOverloadHold);
}

// `row`'s constant load's slip-onset time set against full contact's (`full`'s), both run.
void compareOverload(const CapacityRow& full, CapacityRow& row) {
    if (&row == &full || row.overload.method.empty() || full.overload.method.empty()) return;
    const capacity::OverloadFigures f = findOverloadTimes(row.overload), reference = findOverloadTimes(full.overload);
    if (!f.slipped || !reference.slipped) return;
    row.hasOverloadReference = true;
    row.overloadTimeDifference = (f.slipOnsetTime - reference.slipOnsetTime) / reference.slipOnsetTime;
}

// Why a run stopped before its object slipped: the object not held or the approximation not
// engaged when the load began (capacity::makeGraspRuns refuses to load either), or the
// integrator's failure.
std::string describeFailure(const std::string& failure) {
    if (failure.find("does not hold the object") != std::string::npos) return "not held at the load's start";
    return failure.find("not engaged") != std::string::npos ? "not engaged at the load's start" : "failed (integrator)";
}

// A relative difference as a signed percentage, "+4.1 %".
std::string formatSignedPercent(double fraction) {
    return std::string(fraction >= 0 ? "+" : "") + formatBriefNumber(100 * fraction) + " %";
}

std::string describeSlip(const CapacityRow& row) {
    const capacity::CapacityFigures& f = row.measured.trace.figures;
    const std::string unit = row.measured.torque ? " N m" : " N";
    if (!row.measured.trace.failure.empty() && !f.slipped) return describeFailure(row.measured.trace.failure);
    if (!f.slipped) return "no slip";
    std::string text = formatBriefNumber(f.slipOnsetLoad) + unit;
    if (row.hasReference) text += " (" + formatSignedPercent(row.relativeDifference) + ")";
    if (f.released && f.releaseLoad <= f.slipOnsetLoad) text += ", released first";
    // The onset was measured; the drop, which the run did not reach, was not.
    if (!row.measured.trace.failure.empty()) text += ", then " + describeFailure(row.measured.trace.failure);
    return text;
}

// A constant load's slip-onset time (ms after the load's start) and its difference to full contact's.
std::string describeOverload(const CapacityRow& row) {
    if (row.overload.method.empty()) return "-";
    const capacity::OverloadFigures f = findOverloadTimes(row.overload);
    if (!row.overload.trace.failure.empty() && !f.slipped) return describeFailure(row.overload.trace.failure);
    if (!f.slipped) return "no slip";
    std::string text = formatBriefNumber(1000 * f.slipOnsetTime) + " ms";
    if (row.hasOverloadReference) text += " (" + formatSignedPercent(row.overloadTimeDifference) + ")";
    if (f.released) text += ", released at " + formatBriefNumber(1000 * f.releaseTime) + " ms";
    if (!row.overload.trace.failure.empty()) text += ", then " + describeFailure(row.overload.trace.failure);
    return text;
}

// The constant load of a row's experiment and load (full contact's row carries it too).
std::string describeOverloadLoad(const CapacityRow& row) {
    if (row.overload.method.empty()) return "-";
    return formatBriefNumber(row.overload.load) + (row.overload.torque ? " N m" : " N");
}

using Describe = std::function<std::string(const CapacityRow&)>;

// One table per experiment under `heading` ("###"): loads down, variants across, `describe` in each
// cell; a non-empty `leadName` adds a column after the load's, `lead` of the load's first row.
std::string formatTables(const std::vector<CapacityRow>& rows, const std::string& heading, const Describe& describe,
                         const std::string& leadName = "", const Describe& lead = {}) {
    std::ostringstream md;
    std::string experiment;
    std::vector<std::string> variants;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (rows[i].experiment != experiment) {
            experiment = rows[i].experiment;
            variants.clear();
            for (std::size_t j = i; j < rows.size() && rows[j].experiment == experiment && rows[j].load == rows[i].load; ++j) {
                variants.push_back(rows[j].variant);
            }
            md << "\n" << heading << " " << experiment << "\n\n| load |" << (leadName.empty() ? "" : " " + leadName + " |");
            for (const std::string& v : variants) md << " " << v << " |";
            md << "\n|---|" << (leadName.empty() ? "" : "---|");
            for (std::size_t v = 0; v < variants.size(); ++v) md << "---|";
            md << "\n";
        }
        if (rows[i].variant == variants.front()) md << "| " << rows[i].load << " |" << (leadName.empty() ? "" : " " + lead(rows[i]) + " |");
        md << " " << describe(rows[i]) << " |";
        if (rows[i].variant == variants.back()) md << "\n";
    }
    return md.str();
}

using Announce = std::function<void(const std::string& label)>;

// Every load of `experiment` on every variant (full contact first, each load's reference): the
// ramps, then each variant's constant load above full contact's capacity; plan.jobs runs at once.
void runExperiment(const std::string& experiment, const std::vector<std::string>& variants, const std::vector<Load>& loads,
                   const CapacityPlan& plan, const Announce& announce, std::vector<CapacityRow>& rows) {
    const scenario::Scenario scenario = scenario::findBuiltinScenario(experiment);
    const std::size_t first = rows.size(), perLoad = variants.size();
    for (const Load& load : loads) {
        for (const std::string& variant : variants) rows.push_back(CapacityRow{experiment, load.name, variant, {}, false, 0, {}, false, 0});
    }
    const std::size_t count = rows.size() - first;
    // Each variant's loads, ramps and constant, start from its settled grasp (settled_grasps.h).
    std::vector<std::unique_ptr<capacity::SettledGrasps>> settled;
    for (const std::string& variant : variants) settled.push_back(std::make_unique<capacity::SettledGrasps>(scenario, makeOptions(variant, plan)));
    const auto fullOf = [&](std::size_t k) -> const CapacityRow& { return rows[first + k / perLoad * perLoad]; };
    io::runInParallel(count, plan.jobs, [&](std::size_t k) {
        CapacityRow& row = rows[first + k];
        announce(experiment + " " + row.load + " " + row.variant);
        row.measured = capacity::measureGraspCapacityRamp(*settled[k % perLoad], makeRequest(loads[k / perLoad]));
    });
    for (std::size_t k = 0; k < count; ++k) {
        CapacityRow& row = rows[first + k];
        const capacity::CapacityFigures& f = row.measured.trace.figures;
        const capacity::CapacityFigures& reference = fullOf(k).measured.trace.figures;
        if (row.variant == "full" || !reference.slipped || !f.slipped) continue;
        row.hasReference = true;
        row.relativeDifference = (f.slipOnsetLoad - reference.slipOnsetLoad) / reference.slipOnsetLoad;
    }
    io::runInParallel(count, plan.jobs, [&](std::size_t k) {
        announce(experiment + " " + rows[first + k].load + " " + rows[first + k].variant + " constant");
        runOverload(*settled[k % perLoad], loads[k / perLoad], fullOf(k), rows[first + k]);
    });
    for (std::size_t k = 0; k < count; ++k) compareOverload(fullOf(k), rows[first + k]);
}

}  // namespace

std::vector<CapacityRow> runCapacityComparison(const CapacityPlan& plan, const CapacityProgress& progress) {
    const std::vector<std::string> experiments = plan.experiments.empty() ? getThesisExperiments() : plan.experiments;
    const std::vector<std::string> variants = listVariants(plan);
    const std::vector<std::string> defaultOnly{"full", kDefaultVariant};
    const std::vector<Load> loads = listLoads(plan.quick);
    // A ramp and a constant load each.
    const std::size_t count = 2 * loads.size() * (experiments.size() * variants.size() + plan.defaultOnlyExperiments.size() * defaultOnly.size());
    std::size_t index = 0;
    std::mutex announcing;  // runs announce themselves from plan.jobs threads
    const Announce announce = [&](const std::string& label) {
        const std::lock_guard<std::mutex> lock(announcing);
        if (progress) progress(index, count, label);
        ++index;
    };
    std::vector<CapacityRow> rows;
    for (const std::string& experiment : experiments) runExperiment(experiment, variants, loads, plan, announce, rows);
    for (const std::string& experiment : plan.defaultOnlyExperiments) runExperiment(experiment, defaultOnly, loads, plan, announce, rows);
    return rows;
}

namespace {

// Counts the experiment's loads full contact slips in (by `slips`) and, of those, the ones whose
// row of `variant` agrees with full contact's (by `agrees`).
template <class Slips, class Agrees>
CapacityAgreement countAgreement(const std::vector<CapacityRow>& rows, const std::string& experiment, const std::string& variant,
                                 Slips slips, Agrees agrees) {
    CapacityAgreement agreement;
    for (const CapacityRow& r : rows) {
        if (r.experiment != experiment || r.variant != "full" || !slips(r)) continue;
        ++agreement.compared;
        const auto same = std::find_if(rows.begin(), rows.end(), [&](const CapacityRow& v) {
            return v.experiment == experiment && v.load == r.load && v.variant == variant;
        });
        if (same != rows.end() && agrees(r, *same)) ++agreement.within;
    }
    return agreement;
}

// The ramp's slip onset at another slip threshold, from its samples (none if it did not slip).
std::optional<double> findOnsetAt(const CapacityRow& row, double threshold) {
    capacity::SlipCriteria criteria = row.measured.criteria;
    criteria.slip = threshold;
    const capacity::CapacityFigures f = capacity::findCapacityFigures(row.measured.trace.samples, criteria);
    return f.slipped ? std::optional<double>(f.slipOnsetLoad) : std::nullopt;
}

}  // namespace

CapacityAgreement countCapacityAgreement(const std::vector<CapacityRow>& rows, const std::string& experiment,
                                         const std::string& variant, double bound) {
    return countAgreement(
        rows, experiment, variant, [](const CapacityRow& full) { return full.measured.trace.figures.slipped; },
        [bound](const CapacityRow&, const CapacityRow& v) { return v.hasReference && std::abs(v.relativeDifference) <= bound; });
}

CapacityAgreement countCapacityAgreementAt(const std::vector<CapacityRow>& rows, const std::string& experiment,
                                           const std::string& variant, double bound, double threshold) {
    return countAgreement(
        rows, experiment, variant, [threshold](const CapacityRow& full) { return findOnsetAt(full, threshold).has_value(); },
        [bound, threshold](const CapacityRow& full, const CapacityRow& v) {
            const std::optional<double> reference = findOnsetAt(full, threshold), onset = findOnsetAt(v, threshold);
            return onset && std::abs(*onset - *reference) <= bound * std::abs(*reference);
        });
}

namespace {

// The constant load's columns, each after a comma; empty where it was not run or did not happen.
std::string formatOverloadCsv(const CapacityRow& r) {
    std::ostringstream csv;
    if (r.overload.method.empty()) return ",,,,,,,,";
    const capacity::OverloadFigures f = findOverloadTimes(r.overload);
    const auto time = [](bool valid, double t) { return valid ? formatExactNumber(t) : std::string(); };
    csv << "," << formatExactNumber(r.overload.load) << "," << (f.slipped ? 1 : 0) << "," << time(f.slipped, f.slipOnsetTime) << ","
        << time(f.dropped, f.dropTime) << "," << time(f.released, f.releaseTime) << ","
        << (r.hasOverloadReference ? formatExactNumber(r.overloadTimeDifference) : "") << ",\"" << r.overload.trace.failure << "\","
        << formatExactNumber(r.overload.wallTime);
    return csv.str();
}

// A figure, or nothing where it was not measured (NaN).
std::string formatMeasured(double value) { return std::isfinite(value) ? formatExactNumber(value) : std::string(); }

}  // namespace

std::string formatCapacityCsv(const std::vector<CapacityRow>& rows) {
    std::ostringstream csv;
    csv << "experiment,load,variant,unit,rate,slipped,slip_onset,slip_onset_time_s,dropped,drop,released,release_load,"
           "relative_difference_to_full,release_reason,failure,wall_time_s,overload_load,overload_slipped,"
           "overload_slip_onset_time_s,overload_drop_time_s,overload_release_time_s,overload_time_difference_to_full,"
           "overload_failure,overload_wall_time_s,grip_force_start_n,grip_force_onset_n\n";
    for (const CapacityRow& r : rows) {
        const capacity::CapacityFigures& f = r.measured.trace.figures;
        csv << r.experiment << "," << r.load << "," << r.variant << "," << (r.measured.torque ? "N m" : "N") << ","
            << formatExactNumber(r.measured.rate) << "," << (f.slipped ? 1 : 0) << "," << (f.slipped ? formatExactNumber(f.slipOnsetLoad) : "") << ","
            << (f.slipped ? formatExactNumber(f.slipOnsetTime) : "") << "," << (f.dropped ? 1 : 0) << "," << (f.dropped ? formatExactNumber(f.dropLoad) : "")
            << "," << (f.released ? 1 : 0) << "," << (f.released ? formatExactNumber(f.releaseLoad) : "") << ","
            << (r.hasReference ? formatExactNumber(r.relativeDifference) : "") << ",\"" << r.measured.trace.releaseReason << "\",\""
            << r.measured.trace.failure << "\"," << formatExactNumber(r.measured.wallTime) << formatOverloadCsv(r) << ","
            << formatMeasured(f.gripForceAtStart) << "," << formatMeasured(f.gripForceAtOnset) << "\n";
    }
    return csv.str();
}

namespace {

// Per experiment and approximation variant, in the rows' order: how many of full contact's slip
// onsets the variant's ramp came within 10 % of (issue 17's bound for the default).
std::string formatAgreement(const std::vector<CapacityRow>& rows) {
    std::vector<std::pair<std::string, std::string>> pairs;
    for (const CapacityRow& r : rows) {
        if (r.variant == "full" || std::find(pairs.begin(), pairs.end(), std::pair{r.experiment, r.variant}) != pairs.end()) continue;
        pairs.emplace_back(r.experiment, r.variant);
    }
    std::ostringstream md;
    const double padRadius = simulation::ApproxOptions{}.releaseSlideDistance;
    md << "\n### Ramps within 10 % of full contact's slip onset\n\n"
       << "At the protocol's slip onset, and read again from the same ramps at a pad's radius (" << padRadius * 1e3
       << " mm of slip, where full contact's give has mostly ended and the pads slide; docs/capacity.md, \"The slip threshold\").\n\n"
       << "| experiment | variant | loads within 10 % | at " << padRadius * 1e3 << " mm |\n|---|---|---|---|\n";
    for (const auto& [experiment, variant] : pairs) {
        const CapacityAgreement a = countCapacityAgreement(rows, experiment, variant, 0.1);
        const CapacityAgreement b = countCapacityAgreementAt(rows, experiment, variant, 0.1, padRadius);
        md << "| " << experiment << " | " << variant << (variant == kDefaultVariant ? " (default)" : "") << " | " << a.within << " of "
           << a.compared << " | " << b.within << " of " << b.compared << " |\n";
    }
    return md.str();
}

// Full contact's grip force at the load's start and at the slip onset, per experiment and load.
std::string formatGripForces(const std::vector<CapacityRow>& rows) {
    std::ostringstream md;
    md << "\n### Full contact's grip force under load\n\n"
       << "The summed normal forces of the finger-object contacts (N) at the load's start and at the slip onset: how far "
          "the grasp's grip moves from the one the approximation's limits are computed from (docs/capacity.md, \"Grip "
          "force under load\").\n\n"
       << "| experiment | load | at the start | at the slip onset | change |\n|---|---|---|---|---|\n";
    for (const CapacityRow& r : rows) {
        const capacity::CapacityFigures& f = r.measured.trace.figures;
        if (r.variant != "full" || !std::isfinite(f.gripForceAtStart)) continue;
        const bool atOnset = std::isfinite(f.gripForceAtOnset);  // NaN without slip
        md << "| " << r.experiment << " | " << r.load << " | " << formatBriefNumber(f.gripForceAtStart) << " | "
           << (atOnset ? formatBriefNumber(f.gripForceAtOnset) : "-") << " | "
           << (atOnset ? formatSignedPercent(f.gripForceAtOnset / f.gripForceAtStart - 1) : "-") << " |\n";
    }
    return md.str();
}

}  // namespace

std::string formatCapacityMarkdown(const std::vector<CapacityRow>& rows) {
    if (rows.empty()) return "";
    std::ostringstream md;
    md << "\n## Holding capacity: full contact against the approximation\n\n"
       << "Slip onset of a load ramped from the settled grasp (graspsim capacity; the difference to full contact's in "
          "parentheses; \"released first\": the approximation let go at or before that load, and the slip was then full "
          "contact's; \"then failed\": the run stopped after the onset, before any drop). approx-bushing-merged, the default, also releases at the compliance model's limits and once that "
          "model, followed in time with full contact's creep under the load, has given 2 mm (the creep watch); -static "
          "is the default without the creep watch. The other variants are on the thesis's switch: -thesis is the "
          "default's box limits alone, -contact and -compliance those limit models alone. The scenes `graspsim grasp plan` set up (not the thesis's) are compared on "
          "the default only. Every ramp's figures are in capacity.csv.\n";
    md << formatTables(rows, "###", describeSlip);
    md << formatAgreement(rows);
    md << formatGripForces(rows);
    md << "\n### Slip-onset times under a constant load above capacity\n\n"
       << "A constant load of " << formatBriefNumber(kOverloadFactor) << " x full contact's ramp slip onset (column \"constant load\"), "
       << "applied at once at the load's start and held " << formatBriefNumber(kOverloadHold)
       << " s on every variant (graspsim capacity --method constant): ms from the load's start to slip onset (2 mm), the "
          "difference to full contact's in parentheses; \"released at\": when the approximation handed the object back to "
          "full contact. A table, not checks: where they differ is a finding (docs/capacity.md). Figures in capacity.csv "
          "(overload_*).\n";
    md << formatTables(rows, "####", describeOverload, "constant load", describeOverloadLoad);
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
