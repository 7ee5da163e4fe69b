// results.md: cases with made-up summaries (the oracle is the hand-written table they must give):
// one column per base scenario (file stem), one row per value of the other axes, full mode's
// held/drift/overlap/plan time first and approx mode's engagement after; a case that failed
// shows its error once, without the case's scenario path.

#include "graspsim/study/study_case.h"
#include "graspsim/study/study_folder.h"
#include "graspsim/study/study_grid_table.h"

#include "scratch_folder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace graspsim::study;
namespace fs = std::filesystem;

TEST(StudyGridTable, OneColumnPerBaseOneRowPerOtherAxisCellsFromTheirCases) {
    const fs::path dir = graspsim::testing::makeScratchFolder("grid");
    const StudySpec spec = parseStudy("name: g\nbase: [types/ball.yaml, types/rod.yaml]\n"
                                      "axes:\n  subject.mass: [60, 80]\n  mode: [full, approx]\nmeasures: [held]\n",
                                      (dir / "s.yaml").string());
    const std::string folder = (dir / "out").string();
    prepareStudyFolder(folder, spec, "base");
    for (const StudyCase& c : expandCases(spec)) {
        // values: base, subject.mass, mode; the rod for 80 kg cannot be planned
        const bool rod = c.values[0] == "types/rod.yaml", heavy = c.values[1] == "80", approx = c.values[2] == "approx";
        const fs::path tmp = fs::path(findCaseFolder(folder, c.index) + ".tmp-1");
        fs::create_directories(tmp);
        if (rod && heavy) {
            commitCase(folder, tmp.string(), {c.index, CaseStatus::Failed, "/x/0007.tmp-9/scenario.yaml: no grasp | rims", c.values});
            continue;
        }
        std::ofstream(tmp / "summary.json") << "{\"held\": " << (rod ? "false" : "true")
                                             << ", \"object_displacement_m\": " << (rod ? 0.25 : 0.00123)
                                             << ", \"initial_penetration_m\": 0.0004, \"plan_time_s\": 1.5, \"engaged\": "
                                             << (approx && !heavy ? "true" : "false") << "}";
        commitCase(folder, tmp.string(), {c.index, CaseStatus::Ok, "", c.values});
    }
    EXPECT_EQ(formatGridTable(spec, folder),
              "| subject.mass | ball | rod |\n"
              "|---|---|---|\n"
              "| 60 | held, drift 1.2 mm, 0.4 mm inside at t = 0; plan 1.50 s; approx engaged | DROPPED, drift 250.0 mm, "
              "0.4 mm inside at t = 0; plan 1.50 s; approx engaged |\n"
              "| 80 | held, drift 1.2 mm, 0.4 mm inside at t = 0; plan 1.50 s; approx NOT engaged | no grasp / rims |\n");
    fs::remove_all(dir);
}

// A capacity study's cells: the slip onset and drop of each mode's measurement (capacity.json),
// in the command's words ("not dropped within the ramp", "no slip up to" the ramp's last load, "not
// measured" without one; a bisection's bracket), and an incomplete case's figures with why it stopped.
TEST(StudyGridTable, CapacityCellsGiveTheSlipOnsetAndDrop) {
    const fs::path dir = graspsim::testing::makeScratchFolder("grid-capacity");
    const StudySpec spec = parseStudy("name: g\ncommand: capacity\nbase: [types/ball.yaml, types/key.yaml]\n"
                                      "axes:\n  subject.mass: [60, 80]\n  mode: [full, approx]\nmeasures: [slip_onset_n]\n",
                                      (dir / "s.yaml").string());
    const std::string folder = (dir / "out").string();
    prepareStudyFolder(folder, spec, "base");
    for (const StudyCase& c : expandCases(spec)) {
        const bool key = c.values[0] == "types/key.yaml", heavy = c.values[1] == "80", approx = c.values[2] == "approx";
        const fs::path tmp = fs::path(findCaseFolder(folder, c.index) + ".tmp-1");
        fs::create_directories(tmp);
        std::string figures = "\"slip_onset_n\": " + std::string(approx ? "2.25" : "2.5") + ", \"drop_n\": " + (heavy ? "null" : "3");
        if (key) figures = "\"slip_onset_n\": null, \"drop_n\": null" + std::string(heavy ? "" : ", \"max_load_n\": 1.57");
        std::string method = "ramp";
        if (!key && heavy && approx) {
            method = "bisection";
            figures = "\"slip_onset_n\": 2.25, \"drop_n\": null, \"bracket_held_n\": 2.2, \"bracket_slipped_n\": 2.3";
        }
        std::ofstream(tmp / "capacity.json") << "{\"measurements\": [{\"load\": \"force\", \"method\": \"" << method << "\", " << figures << "}]}";
        const bool stopped = key && heavy && approx;
        commitCase(folder, tmp.string(), {c.index, stopped ? CaseStatus::Incomplete : CaseStatus::Ok, stopped ? "the integrator stalled" : "", c.values});
    }
    EXPECT_EQ(formatGridTable(spec, folder),
              "| subject.mass | ball | key |\n"
              "|---|---|---|\n"
              "| 60 | slips at 2.5 N, drops at 3 N; approx: slips at 2.25 N, drops at 3 N | no slip up to 1.57 N; approx: no slip up to 1.57 N |\n"
              "| 80 | slips at 2.5 N, not dropped within the ramp; approx: slips from 2.25 N (held 2.2, slipped 2.3) | not measured; "
              "approx: not measured (the integrator stalled) |\n");
    fs::remove_all(dir);
}
