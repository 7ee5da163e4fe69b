// Runs the real `graspsim grasp plan`: a plan is written as a scenario, byte for byte the same
// each time; no grasp and bad input are one line on stderr, exit code 2, no file.

#include "cli_process.h"

#include <gtest/gtest.h>

namespace fs = std::filesystem;
using graspsim::testing::RunResult;
using GraspCommand = graspsim::testing::CliProcess;

TEST_F(GraspCommand, ThePlanIsAScenarioWrittenTheSameEachTime) {
    const std::string request = "grasp plan --sex female --mass 50 --stature 1.52 "
                                "--object sphere:radius=0.045,mass=0.2 --type power-sphere -o ";
    const RunResult first = run(request + (dir_ / "a.yaml").string());
    ASSERT_EQ(first.exitCode, 0) << first.err;
    const RunResult second = run(request + (dir_ / "b.yaml").string());
    ASSERT_EQ(second.exitCode, 0) << second.err;
    const std::string text = graspsim::testing::slurp(dir_ / "a.yaml");
    EXPECT_EQ(text, graspsim::testing::slurp(dir_ / "b.yaml"));
    for (const char* part : {"grasp_pose:", "goals:", "thumb_tip:", "little_tip:", "sex: female", "Feix et al. 2016"}) {
        EXPECT_NE(text.find(part), std::string::npos) << part;
    }
}

// A cylinder from the command line: the plan is a scenario whose object is that cylinder.
TEST_F(GraspCommand, PowerCylinderOnACylinderObject) {
    const RunResult r = run("grasp plan --object cylinder:radius=0.02,length=0.12,mass=0.2 --type power-cylinder -o " +
                            (dir_ / "c.yaml").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string text = graspsim::testing::slurp(dir_ / "c.yaml");
    for (const char* part : {"shape: cylinder", "length: 0.12", "grasp_pose:", "goals:"}) EXPECT_NE(text.find(part), std::string::npos) << part << text;
}

TEST_F(GraspCommand, NoGraspIsOneLineWithTheNumbers) {
    expectBadInput("grasp plan --object sphere:radius=0.075,mass=0.2 --type pinch -o " + output(),
                   {"no pinch grasp", "object width 150 mm", "thumb-index span"});
    expectBadInput("grasp plan --object box:size=0.4x0.4x0.4,mass=1 --type power-sphere -o " + output(),
                   {"no power-sphere grasp", "object width 400 mm exceeds the hand's thumb-little span"});
}

TEST_F(GraspCommand, BadInputNamesTheOptionAndValue) {
    expectBadInput("grasp plan --object cone:radius=0.02,mass=0.2 -o " + output(), {"--object", "'cone'"});
    expectBadInput("grasp plan --object cylinder:radius=0.02,mass=0.2 -o " + output(), {"--object", "lacks a size"});
    expectBadInput("grasp plan --object ellipsoid:semi_axes=0.02x0.03,mass=0.2 -o " + output(), {"--object", "semi_axes"});
    expectBadInput("grasp plan --object sphere:radius=-0.02,mass=0.2 -o " + output(), {"--object radius", "'-0.02'"});
    expectBadInput("grasp plan --object sphere:radius=0.02 -o " + output(), {"--object", "mass"});
    expectBadInput("grasp plan --object sphere:radius=0.02,mass=0.2,radius=0.03 -o " + output(),
                   {"--object: field 'radius' is given twice in 'sphere:radius=0.02,mass=0.2,radius=0.03'"});
    expectBadInput("grasp plan --object sphere:radius=0.02,mass=0.2 --type fist -o " + output(), {"--type", "'fist'"});
    // Refused before the planning's seconds of work, naming the option.
    expectBadInput("grasp plan --object sphere:radius=0.02,mass=0.2 -o " + dir_.string(), {"--output: value '", "' is a folder"});
    expectBadInput("grasp plan --object sphere:radius=0.02,mass=0.2 --mass 300 -o " + output(), {"--mass"});
}
