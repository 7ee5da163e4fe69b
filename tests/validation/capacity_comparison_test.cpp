#include "graspsim/validation/capacity_comparison.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

namespace graspsim::validation {
namespace {

CapacityRow makeRow(const std::string& experiment, const std::string& load, const std::string& variant, double slip) {
    CapacityRow row;
    row.experiment = experiment;
    row.load = load;
    row.variant = variant;
    row.measured.trace.figures.slipped = slip > 0;
    row.measured.trace.figures.slipOnsetLoad = slip;
    return row;
}

// One table per experiment, one line per load, one column per variant, in run order.
TEST(CapacityComparison, ReportTablesHaveALinePerLoadAndAColumnPerVariant) {
    std::vector<CapacityRow> rows;
    for (const char* experiment : {"ball-clutch", "phone-pinch"}) {
        for (const char* load : {"-y", "x"}) {
            rows.push_back(makeRow(experiment, load, "full", 10));
            rows.push_back(makeRow(experiment, load, "approx-bushing-merged", 11));
            rows.back().hasReference = true;
            rows.back().relativeDifference = 0.1;
        }
    }
    const std::string md = formatCapacityMarkdown(rows);
    EXPECT_NE(md.find("### ball-clutch\n\n| load | full | approx-bushing-merged |\n|---|---|---|\n| -y | 10 N | 11 N (+10 %) |\n"
                      "| x | 10 N | 11 N (+10 %) |\n"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("### phone-pinch"), std::string::npos);
    const std::string csv = formatCapacityCsv(rows);
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 9);
    EXPECT_TRUE(formatCapacityMarkdown({}).empty());
}

// A ramp that slipped and then stopped (a stalled integrator) keeps its onset and says it failed:
// its drop was never measured.
TEST(CapacityComparison, AnOnsetBeforeAFailureIsMarked) {
    std::vector<CapacityRow> rows{makeRow("key-lateral", "-x", "full", 0.427), makeRow("key-lateral", "z", "full", 0)};
    rows[0].measured.trace.failure = "the integrator stalled between t = 3.095 and 3.1 s";
    rows[1].measured.trace.failure = "the integrator stalled between t = 2 and 2.01 s";
    const std::string md = formatCapacityMarkdown(rows);
    EXPECT_NE(md.find("| -x | 0.427 N, then failed (integrator) |\n| z | failed (integrator) |\n"), std::string::npos) << md;
}

// A grasp that lost its object before the load (capacity::makeGraspRuns stops it) is named as such,
// not as an integrator's failure.
TEST(CapacityComparison, AGraspNotHoldingAtTheLoadsStartIsNamed) {
    std::vector<CapacityRow> rows{makeRow("planned-tripod", "-y", "full", 0)};
    rows[0].measured.trace.failure =
        "capacity: the grasp does not hold the object at the load's start, t = 1.1 s: a goal fingertip is 1.36e+03 mm from its goal";
    const std::string md = formatCapacityMarkdown(rows);
    EXPECT_NE(md.find("| -y | not held at the load's start |\n"), std::string::npos) << md;
}

// Full contact's grip at the load's start and at the onset, with its change, in report.md and
// capacity.csv's last two columns; the approximation's rows (engaged: not measured) stay out of the
// table and leave the columns empty.
TEST(CapacityComparison, GripForcesOfFullContactAreTabledWithTheirChange) {
    std::vector<CapacityRow> rows{makeRow("phone-pinch", "-y", "full", 2), makeRow("phone-pinch", "-y", "approx-bushing-merged", 2.1)};
    rows[0].measured.trace.figures.gripForceAtStart = 4;
    rows[0].measured.trace.figures.gripForceAtOnset = 7;
    const std::string md = formatCapacityMarkdown(rows);
    EXPECT_NE(md.find("| experiment | load | at the start | at the slip onset | change |\n|---|---|---|---|---|\n"
                      "| phone-pinch | -y | 4 | 7 | +75 % |\n\n"),
              std::string::npos)
        << md;
    const std::string csv = formatCapacityCsv(rows);
    EXPECT_NE(csv.find(",grip_force_start_n,grip_force_onset_n\n"), std::string::npos) << csv;
    EXPECT_NE(csv.find(",4,7\n"), std::string::npos) << csv;
    EXPECT_NE(csv.find("approx-bushing-merged"), std::string::npos);
    EXPECT_EQ(csv.substr(csv.size() - 3), ",,\n") << csv;
}

// A constant load held from t = 1.1 s whose slip passed 2 mm at `onset` s after it.
capacity::GraspCapacity makeOverload(double load, double onset) {
    capacity::GraspCapacity c;
    c.method = "constant";
    c.start = 1.1;
    c.load = load;
    c.hold = 1;
    c.trace.figures.slipped = onset > 0;
    c.trace.figures.slipOnsetTime = c.start + onset;
    return c;
}

// The constant loads' table: the load in its own column, the onset times in ms after the load's
// start, the difference to full contact's and the release; "-" where full contact's ramp did not
// slip (no load to set); the times in capacity.csv's last columns.
TEST(CapacityComparison, ConstantLoadTableGivesOnsetTimesAfterTheLoadsStart) {
    std::vector<CapacityRow> rows{makeRow("ball-clutch", "-y", "full", 10), makeRow("ball-clutch", "-y", "approx-bushing-merged", 11),
                                  makeRow("ball-clutch", "x", "full", 0), makeRow("ball-clutch", "x", "approx-bushing-merged", 0)};
    rows[0].overload = makeOverload(12.5, 0.05);
    rows[1].overload = makeOverload(12.5, 0.06);
    rows[1].overload.mode = simulation::SimulationMode::Approx;
    rows[1].overload.trace.figures.released = true;
    rows[1].overload.trace.figures.releaseTime = 1.1 + 0.02;
    rows[1].hasOverloadReference = true;
    rows[1].overloadTimeDifference = 0.2;
    const std::string md = formatCapacityMarkdown(rows);
    EXPECT_NE(md.find("#### ball-clutch\n\n| load | constant load | full | approx-bushing-merged |\n|---|---|---|---|\n"
                      "| -y | 12.5 N | 50 ms | 60 ms (+20 %), released at 20 ms |\n| x | - | - | - |\n"),
              std::string::npos)
        << md;
    const std::string csv = formatCapacityCsv(rows);
    EXPECT_NE(csv.find(",12.5,1,0.06"), std::string::npos) << csv;
    const auto countCommas = [](const std::string& line) { return std::count(line.begin(), line.end(), ','); };
    std::istringstream lines(csv);
    std::string header, line;
    std::getline(lines, header);
    while (std::getline(lines, line)) EXPECT_EQ(countCommas(line), countCommas(header)) << line;
}

// The agreement count: a load counts where full contact slipped; a variant's ramp is within the
// bound on either side (exactly 10 % is within), not where it did not slip or was not run.
TEST(CapacityComparison, AgreementCountsLoadsWithinTheBoundOfFullContactsOnset) {
    std::vector<CapacityRow> rows;
    const auto add = [&](const std::string& load, double full, double approx) {
        rows.push_back(makeRow("ball-tripod", load, "full", full));
        rows.push_back(makeRow("ball-tripod", load, "approx-bushing-merged", approx));
        if (full > 0 && approx > 0) {
            rows.back().hasReference = true;
            rows.back().relativeDifference = (approx - full) / full;
        }
    };
    add("x", 10, 11);    // +10 %: within
    add("-x", 10, 8.5);  // -15 %
    add("y", 10, 9.5);   // -5 %: within
    add("-y", 10, 0);    // the approximation did not slip
    add("z", 0, 4);      // full contact did not slip: not compared
    rows.push_back(makeRow("ball-tripod", "-z", "full", 10));  // the variant not run
    const CapacityAgreement a = countCapacityAgreement(rows, "ball-tripod", "approx-bushing-merged", 0.1);
    EXPECT_EQ(a.within, 2u);
    EXPECT_EQ(a.compared, 5u);
    EXPECT_EQ(countCapacityAgreement(rows, "ball-tripod", "approx-bushing-merged", 0.2).within, 3u);
    EXPECT_EQ(countCapacityAgreement(rows, "can-power", "approx-bushing-merged", 0.1).compared, 0u);
    EXPECT_NE(formatCapacityMarkdown(rows).find("| ball-tripod | approx-bushing-merged (default) | 2 of 5 |"), std::string::npos)
        << formatCapacityMarkdown(rows);
}

// Read again at another threshold: the onsets come from the samples (slip against load, linear
// between samples), not from the figures measured at 2 mm. Full contact gives 2 mm at 5 N and
// slides 5 mm at 10 N; the approximation, stiff, first slips 2 mm at 6 N (+20 %) and 5 mm at
// 10.5 N (+5 %).
TEST(CapacityComparison, AgreementAtAnotherThresholdReadsTheSamples) {
    const auto ramp = [](const std::string& variant, std::vector<std::pair<double, double>> loadSlip) {
        CapacityRow row = makeRow("ball-clutch", "-z", variant, 0);
        for (const auto& [load, slip] : loadSlip) row.measured.trace.samples.push_back({load / 10, load, slip, 0, true, -1});
        row.measured.trace.figures = capacity::findCapacityFigures(row.measured.trace.samples, row.measured.criteria);
        return row;
    };
    std::vector<CapacityRow> rows{ramp("full", {{0, 0}, {5, 0.002}, {10, 0.005}, {12, 0.03}}),
                                  ramp("approx-bushing-merged", {{0, 0}, {6, 0.002}, {10.5, 0.005}, {12, 0.03}})};
    rows.back().hasReference = true;
    rows.back().relativeDifference = 0.2;
    EXPECT_EQ(countCapacityAgreement(rows, "ball-clutch", "approx-bushing-merged", 0.1).within, 0u);
    const CapacityAgreement a = countCapacityAgreementAt(rows, "ball-clutch", "approx-bushing-merged", 0.1, 0.005);
    EXPECT_EQ(a.within, 1u);
    EXPECT_EQ(a.compared, 1u);
    EXPECT_EQ(countCapacityAgreementAt(rows, "ball-clutch", "approx-bushing-merged", 0.04, 0.005).within, 0u);  // +5 %
    EXPECT_NE(formatCapacityMarkdown(rows).find("| ball-clutch | approx-bushing-merged (default) | 0 of 1 | 1 of 1 |"), std::string::npos)
        << formatCapacityMarkdown(rows);
}

// validate --jobs: the ramps and constant loads of the comparison run on threads; the rows (every
// figure, reference and difference; wall times aside) are those of one job. Quick phone plan:
// full contact and the default on the -y force, a ramp and a constant load each.
TEST(CapacityComparison, RowsAreTheSameForAnyNumberOfJobs) {
    CapacityPlan plan;
    plan.experiments = {"phone-pinch"};
    plan.quick = true;
    std::string csv[2];
    for (int jobs : {1, 2}) {
        plan.jobs = jobs;
        std::vector<CapacityRow> rows = runCapacityComparison(plan);
        ASSERT_EQ(rows.size(), 2u);
        for (CapacityRow& r : rows) r.measured.wallTime = r.overload.wallTime = 0;
        EXPECT_TRUE(rows[1].hasReference);
        csv[jobs - 1] = formatCapacityCsv(rows);
    }
    EXPECT_EQ(csv[0], csv[1]);
}

}  // namespace
}  // namespace graspsim::validation
