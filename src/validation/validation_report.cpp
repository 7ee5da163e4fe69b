#include "graspsim/validation/validation_report.h"

#include "number_text.h"
#include "graspsim/io/atomic_file.h"

#include <sstream>

namespace graspsim::validation {

namespace {

std::string errorsCsv(const RunRecord& r) {
    if (!r.hasReference) return ",,,,,";
    const PoseErrors& e = r.errors;
    return formatExactNumber(e.maxPosition) + "," + formatExactNumber(e.rmsPosition) + "," + formatExactNumber(e.maxAngle) + "," + formatExactNumber(e.rmsAngle) + "," +
           formatExactNumber(r.windowErrors.maxPosition) + "," + formatExactNumber(r.windowErrors.maxAngle);
}

std::string describeRelation(const ValidationCheck& c) {
    if (c.unit.empty() && c.relation == "==") return c.bound == 1 ? "yes" : "no";
    return c.relation + " " + formatBriefNumber(c.bound) + (c.unit.empty() ? "" : " " + c.unit);
}

std::string describeValue(const ValidationCheck& c) {
    if (c.unit.empty() && c.relation == "==") return c.value == 1 ? "yes" : "no";
    return formatBriefNumber(c.value) + (c.unit.empty() ? "" : " " + c.unit);
}

void appendRunTable(const ValidationResults& results, std::ostringstream& md) {
    md << "\n## Runs\n\n| run | held (full) | displacement after settling (mm) | slip onset (s) | engaged at (s) "
          "| released at (s) | max position error (mm) | RMS position error (mm) | max angle error (deg) | wall time (s) |\n"
          "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const RunRecord& r : results.runs) {
        const simulation::SimulationSummary& s = r.summary;
        md << "| " << r.run.id << " | " << (s.held ? "yes" : "no");
        if (r.hasReference) md << " (" << (r.referenceHeld ? "yes" : "no") << ")";
        md << " | " << formatBriefNumber(s.objectDisplacement * 1e3) << " | " << (r.slipOnset < 0 ? "-" : formatBriefNumber(r.slipOnset)) << " | "
           << (s.engaged ? formatBriefNumber(s.engageTime) : "-") << " | " << (s.releaseTime < 0 ? "-" : formatBriefNumber(s.releaseTime)) << " | ";
        if (r.hasReference) {
            md << formatBriefNumber(r.errors.maxPosition * 1e3) << " | " << formatBriefNumber(r.errors.rmsPosition * 1e3) << " | "
               << formatBriefNumber(r.errors.maxAngle * 180 / 3.14159265358979323846);
        } else {
            md << "- | - | -";
        }
        md << " | " << formatBriefNumber(s.wallTime) << " |\n";
    }
}

}  // namespace

std::string formatResultsCsv(const ValidationResults& results) {
    std::ostringstream csv;
    csv << "id,scenario,perturbation,contact,variant,complete,held,reference_held,object_displacement_m,"
           "reference_displacement_m,slip_onset_s,reference_slip_onset_s,engage_time_s,release_time_s,q_at_engage_n,"
           "max_penetration_m,max_position_error_m,rms_position_error_m,max_angle_error_rad,rms_angle_error_rad,"
           "window_max_position_error_m,window_max_angle_error_rad,wall_time_s,sim_time_s,steps,full_wall_per_sim_s,"
           "approx_wall_per_sim_s\n";
    for (const RunRecord& r : results.runs) {
        const simulation::SimulationSummary& s = r.summary;
        csv << r.run.id << "," << r.run.scenario << "," << s.perturbation << "," << simulation::toString(s.contact) << "," << r.run.variant << ","
            << (s.complete ? 1 : 0) << "," << (s.held ? 1 : 0) << "," << (r.hasReference ? (r.referenceHeld ? "1" : "0") : "")
            << "," << formatExactNumber(s.objectDisplacement) << "," << (r.hasReference ? formatExactNumber(r.referenceDisplacement) : "") << ","
            << formatExactNumber(r.slipOnset) << "," << (r.hasReference ? formatExactNumber(r.referenceSlipOnset) : "") << "," << formatExactNumber(s.engageTime) << ","
            << formatExactNumber(s.releaseTime) << "," << formatExactNumber(s.qAtEngage) << "," << formatExactNumber(s.maxPenetration) << "," << errorsCsv(r) << ","
            << formatExactNumber(s.wallTime) << "," << formatExactNumber(s.simTime) << "," << s.steps << "," << formatExactNumber(s.fullWallPerSimSecond) << ","
            << formatExactNumber(s.approxWallPerSimSecond) << "\n";
    }
    return csv.str();
}

std::string formatChecksCsv(const ValidationResults& results) {
    std::ostringstream csv;
    csv << "run,check,value,relation,bound,unit,pass,source\n";
    for (const ValidationCheck& c : results.checks) {
        csv << c.run << ",\"" << c.name << "\"," << formatExactNumber(c.value) << "," << c.relation << "," << formatExactNumber(c.bound) << "," << c.unit
            << "," << (c.pass ? 1 : 0) << ",\"" << c.source << "\"\n";
    }
    return csv.str();
}

std::string formatReportMarkdown(const ValidationResults& results, const std::vector<std::string>& plots) {
    std::size_t failed = 0;
    for (const ValidationCheck& c : results.checks) failed += c.pass ? 0 : 1;
    std::ostringstream md;
    md << "# graspsim validation report\n\n" << results.runs.size() << " runs, " << results.checks.size() << " checks, "
       << failed << " failed; " << formatBriefNumber(results.wallTime) << " s wall time. Generated by `graspsim validate`; "
       << "full contact is the reference of every approximation run.\n\n## Checks\n\n"
       << "| run | check | measured | bound | result | source |\n|---|---|---|---|---|---|\n";
    for (const ValidationCheck& c : results.checks) {
        md << "| " << c.run << " | " << c.name << " | " << describeValue(c) << " | " << describeRelation(c) << " | "
           << (c.pass ? "pass" : "**FAIL**") << " | " << c.source << " |\n";
    }
    appendRunTable(results, md);
    md << formatCapacityMarkdown(results.capacity);
    if (!plots.empty()) md << "\n## Plots\n\n";
    for (const std::string& p : plots) md << "![" << p << "](" << p << ")\n\n";
    return md.str();
}

void writeValidationReport(const std::string& folder, const ValidationResults& results,
                           const std::vector<std::string>& plots) {
    io::writeFileAtomically(folder + "/results.csv", formatResultsCsv(results));
    io::writeFileAtomically(folder + "/checks.csv", formatChecksCsv(results));
    if (!results.capacity.empty()) io::writeFileAtomically(folder + "/capacity.csv", formatCapacityCsv(results.capacity));
    io::writeFileAtomically(folder + "/report.md", formatReportMarkdown(results, plots));
}

}  // namespace graspsim::validation
