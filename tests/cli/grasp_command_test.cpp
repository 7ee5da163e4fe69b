// Runs the real `graspsim grasp plan`: a plan is written as a scenario, byte for byte the same
// each time; no grasp and bad input are one line on stderr, exit code 2, no file.

#include "cli_process.h"

#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <set>

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

// A tripod of an 80 mm, 300 g ball for a 90 kg, 1.85 m man passes the planner's static checks, but
// its three pads cannot carry the ball: the plan is refused (one line, exit 2, no file) because the
// full-contact run of it loses the ball while settling. The second method: the same plan written
// with --no-hold-check and simulated by `graspsim simulate` is not held either, while a planned
// tripod of the 30 g ball holds and says so.
TEST_F(GraspCommand, APlanThatCannotHoldItsObjectIsRefused) {
    const std::string heavy = "grasp plan --sex male --mass 90 --stature 1.85 --object sphere:radius=0.04,mass=0.3 --type tripod -o ";
    expectBadInput(heavy + output(), {"no tripod grasp found that holds the object", "by t = 1.5 s", "--no-hold-check"});
    const std::string written = (dir_ / "heavy.yaml").string();
    const RunResult unchecked = run(heavy + written + " --no-hold-check");
    ASSERT_EQ(unchecked.exitCode, 0) << unchecked.err;
    EXPECT_NE(unchecked.out.find("hold not checked"), std::string::npos) << unchecked.out;
    const RunResult simulated = run("simulate " + written + " --duration 1.5 -q --out " + (dir_ / "sim").string());
    ASSERT_EQ(simulated.exitCode, 0) << simulated.err;
    EXPECT_NE(simulated.out.find("held no"), std::string::npos) << simulated.out;
    const RunResult light = run("grasp plan --object sphere:radius=0.015,mass=0.03 --type tripod -o " + (dir_ / "light.yaml").string());
    ASSERT_EQ(light.exitCode, 0) << light.err;
    EXPECT_NE(light.out.find("holds its object 0.5 s after settling (drift "), std::string::npos) << light.out;
    EXPECT_NE(light.out.find(", Q 0."), std::string::npos) << light.out;  // three contacts: their grasp quality
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

namespace {

// The forms "shape:fields" a text lists, e.g. "sphere:radius=R,mass=M".
std::vector<std::string> findObjectForms(const std::string& text) {
    static const std::regex form(R"([a-z_]+:[a-z_]+=[A-Za-z]+(,[a-z_]+=[A-Za-z]+)*)");
    std::vector<std::string> forms;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), form); it != std::sregex_iterator(); ++it) forms.push_back(it->str());
    return forms;
}

// A form with numbers for its placeholders: "sphere:radius=0.02,mass=0.2".
std::string fillForm(std::string form) {
    const std::vector<std::pair<std::string, std::string>> values{
        {"=XxYxZ", "=0.05x0.02x0.01"}, {"=AxBxC", "=0.03x0.02x0.01"}, {"=R", "=0.02"}, {"=L", "=0.1"}, {"=M", "=0.2"}};
    for (const auto& [placeholder, value] : values) {
        for (size_t at = form.find(placeholder); at != std::string::npos; at = form.find(placeholder)) form.replace(at, placeholder.size(), value);
    }
    return form;
}

}  // namespace

// The help's --object text names every shape the planner takes, with its fields. Oracles: the
// five shapes a scenario's object may have besides a mesh (docs/shapes.md), the list the parser
// gives when it refuses a shape, and the parser itself: each listed form, filled with numbers,
// passes --object (the command then stops at the next option checked, the bad --type).
TEST_F(GraspCommand, HelpListsEveryObjectShapeTheParserAccepts) {
    const RunResult help = run("grasp plan --help");
    ASSERT_EQ(help.exitCode, 0) << help.err;
    const size_t option = help.out.find("--object");
    ASSERT_NE(option, std::string::npos) << help.out;
    const std::string line = help.out.substr(option, help.out.find("\n  -", option) - option);
    const std::vector<std::string> listed = findObjectForms(line);
    std::set<std::string> shapes;
    for (const std::string& form : listed) shapes.insert(form.substr(0, form.find(':')));
    EXPECT_EQ(shapes, (std::set<std::string>{"sphere", "box", "cylinder", "capsule", "ellipsoid"})) << line;

    const RunResult refused = run("grasp plan --object cone:radius=0.02,mass=0.2 -o " + output());
    EXPECT_EQ(findObjectForms(refused.err), listed) << refused.err;
    for (const std::string& form : listed) {
        expectBadInput("grasp plan --object " + fillForm(form) + " --type fist -o " + output(), {"--type", "'fist'"});
    }
}

// A pinch has two contacts, whose grasp quality Q is round-off: the line says what the planner
// checked, the antipodal test, with its figure. Oracle: the angle between the line through the
// two written goals and the phone's face normals (+-z in its frame), in closed form, within what
// the goals' rounding to 0.1 mm allows (0.14 mm across an 8 mm thickness: 1 deg); the friction
// cone of mu 0.7, atan(0.7) = 35.0 deg.
TEST_F(GraspCommand, APinchReportsTheAntipodalTestNotQ) {
    const std::string file = (dir_ / "pinch.yaml").string();
    const RunResult r = run("grasp plan --type pinch --object box:size=0.07x0.14x0.008,mass=0.1 --no-hold-check -o " + file);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out.find(" Q "), std::string::npos) << r.out;
    std::smatch figure;
    const std::string out = r.out;
    ASSERT_TRUE(std::regex_search(out, figure, std::regex(R"(, antipodal \(contact line ([0-9.]+) deg off the normals, friction cone 35\.0 deg\), hold not checked)")))
        << r.out;
    const std::string text = graspsim::testing::slurp(file);
    EXPECT_NE(text.find("# Force closure: antipodal (contact line " + figure[1].str() + " deg off the normals"), std::string::npos) << text;
    std::smatch thumb, index;
    const std::regex goal(R"(: \[(-?[0-9.e+-]+), (-?[0-9.e+-]+), (-?[0-9.e+-]+)\])");
    const size_t goals = text.find("\ngoals:");
    ASSERT_NE(goals, std::string::npos);
    const std::string thumbLine = text.substr(text.find("thumb_tip:", goals)), indexLine = text.substr(text.find("index_tip:", goals));
    ASSERT_TRUE(std::regex_search(thumbLine, thumb, goal));
    ASSERT_TRUE(std::regex_search(indexLine, index, goal));
    double d[3];
    for (int i = 0; i < 3; ++i) d[i] = std::stod(index[i + 1].str()) - std::stod(thumb[i + 1].str());
    EXPECT_NEAR(std::abs(d[2]), 0.008, 1e-12);  // across the thickness
    const double expected = std::atan2(std::hypot(d[0], d[1]), std::abs(d[2])) * 180 / M_PI;
    EXPECT_NEAR(std::stod(figure[1].str()), expected, 1.1) << "goals' line " << expected << " deg off the normals";
}
