// Reading study files: the shipped example reads, and every malformed study gets one line naming
// the file, the line and the key.

#include "graspsim/error.h"
#include "graspsim/study/study_spec.h"

#include <gtest/gtest.h>

using namespace graspsim::study;

namespace {

std::string errorOf(const std::string& text) {
    try {
        parseStudy(text, "s.yaml");
    } catch (const graspsim::InputError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        return message;
    }
    ADD_FAILURE() << "accepted:\n" << text;
    return "";
}

const std::string kHead = "name: t\nbase: ball-clutch\n";

}  // namespace

TEST(StudySpec, ShippedExampleReads) {
    const StudySpec spec = loadStudyFile(std::string(GRASPSIM_SOURCE_DIR) + "/models/studies/stature-friction.yaml");
    EXPECT_EQ(spec.name, "stature-friction");
    EXPECT_EQ(spec.bases, std::vector<std::string>{"ball-clutch"});
    ASSERT_EQ(spec.axes.size(), 3u);
    EXPECT_EQ(spec.axes[0].name, "subject.stature");
    EXPECT_TRUE(spec.axes[1].isRange);
    EXPECT_EQ(spec.axes[1].range.steps, 3);
    EXPECT_TRUE(spec.axes[2].isRunOption);
    EXPECT_EQ(spec.sampling, Sampling::Grid);
    EXPECT_FALSE(spec.measures.empty());
}

TEST(StudySpec, RelativeBaseFileIsFoundBesideTheStudy) {
    const StudySpec spec = parseStudy(kHead.substr(0, 8) + "base: my.yaml\naxes: {mode: [full]}\nmeasures: [held]\n", "dir/s.yaml");
    EXPECT_EQ(spec.bases, std::vector<std::string>{"dir/my.yaml"});
}

TEST(StudySpec, AListOfBasesIsTheFirstAxis) {
    const StudySpec spec = parseStudy("name: t\nbase: [ball-clutch, my.yaml]\naxes: {mode: [full]}\nmeasures: [held]\n", "dir/s.yaml");
    EXPECT_EQ(spec.bases, (std::vector<std::string>{"ball-clutch", "dir/my.yaml"}));
    ASSERT_EQ(spec.axes.size(), 2u);
    EXPECT_EQ(spec.axes[0].name, "base");
    EXPECT_TRUE(spec.axes[0].isBase);
    EXPECT_EQ(spec.axes[0].values, (std::vector<std::string>{"ball-clutch", "my.yaml"}));
    EXPECT_NE(errorOf("name: t\nbase: []\naxes: {mode: [full]}\nmeasures: [held]\n").find("'base' is an empty list"), std::string::npos);
    EXPECT_NE(errorOf("name: t\nbase: [a.yaml, a.yaml]\naxes: {mode: [full]}\nmeasures: [held]\n").find("listed twice"), std::string::npos);
}

TEST(StudySpec, MalformedStudiesGetOneLineNamingTheKey) {
    EXPECT_NE(errorOf(kHead + "axes:\n  subject.mass: []\nmeasures: [held]\n").find("s.yaml:4: axis 'subject.mass' is empty"), std::string::npos);
    EXPECT_NE(errorOf(kHead + "axes: {}\nmeasures: [held]\n").find("'axes' is missing or empty"), std::string::npos);
    EXPECT_NE(errorOf(kHead + "axes: {mode: [full]}\nmeasures: [drift]\n").find("measure 'drift' is not accepted"), std::string::npos);
    EXPECT_NE(errorOf(kHead + "axes: {mode: [full]}\nmeasures: [held]\ncolour: red\n").find("key 'colour' is not accepted"), std::string::npos);
    EXPECT_NE(errorOf(kHead + "axes: {subject.mass: {from: 80, to: 60, steps: 3}}\nmeasures: [held]\n").find("from must be below to"),
              std::string::npos);
    EXPECT_NE(errorOf(kHead + "axes: {subject.mass: {from: 60, to: 80}}\nmeasures: [held]\n").find("range needs steps"), std::string::npos);
    EXPECT_NE(errorOf(kHead + "axes: {subject.mass: {from: 60, to: 80, steps: 1}}\nmeasures: [held]\n").find("whole number >= 2"),
              std::string::npos);
    EXPECT_NE(errorOf(kHead + "axes: {mode: {from: 1, to: 2, steps: 2}}\nmeasures: [held]\n").find("give a list of values"),
              std::string::npos);
    EXPECT_NE(errorOf(kHead + "axes: {mode: [full]}\nsampling: latin\nmeasures: [held]\n").find("'samples' is missing"), std::string::npos);
    EXPECT_NE(errorOf(kHead + "axes: {mode: [full]}\nsampling: sobol\nmeasures: [held]\n").find("'sampling' value 'sobol'"),
              std::string::npos);
    EXPECT_NE(errorOf(kHead + "set: {mode: full}\naxes: {mode: [full]}\nmeasures: [held]\n").find("both set and an axis"),
              std::string::npos);
    EXPECT_NE(errorOf(kHead + "axes: {subject.mass: {from: 60, to: 80, steps: 2000}, object.mass: {from: 0.1, to: 1, steps: 1000}}\n"
                              "measures: [held]\n").find("the grid has 2000000 cases"),
              std::string::npos);
    EXPECT_NE(errorOf("base: ball-clutch\naxes: {mode: [full]}\nmeasures: [held]\n").find("'name' is missing"), std::string::npos);
    EXPECT_NE(errorOf(kHead + "axes: {'subject..mass': [1]}\nmeasures: [held]\n").find("axis 'subject..mass' is not accepted"),
              std::string::npos);
}

// yaml-cpp keeps both of a key given twice and answers the first: a second value (or a repeated
// case, measure or seed that grid sampling never uses) would be silently dropped.
TEST(StudySpec, RepeatsAndUnusedKeysAreRefusedNamingTheLine) {
    EXPECT_EQ(errorOf("name: t\nname: u\nbase: ball-clutch\naxes: {mode: [full]}\nmeasures: [held]\n"),
              "s.yaml:2: key 'name' is given twice; give each key once");
    EXPECT_EQ(errorOf(kHead + "set:\n  contact.dynamic_friction: 0.4\n  contact.dynamic_friction: 0.5\naxes: {mode: [full]}\nmeasures: [held]\n"),
              "s.yaml:5: set 'contact.dynamic_friction' is given twice; give each field once");
    EXPECT_EQ(errorOf(kHead + "axes: {subject.stature: [1.741, 1.75, 1.741]}\nmeasures: [held]\n"),
              "s.yaml:3: axis 'subject.stature' value '1.741' is listed twice; give each value once");
    EXPECT_EQ(errorOf(kHead + "axes: {mode: [full]}\nmeasures: [held, wall_time_s, held]\n"),
              "s.yaml:4: measure 'held' is listed twice; give each measure once");
    EXPECT_EQ(errorOf(kHead + "axes: {mode: [full]}\nmeasures: [held]\nseed: 5\n"),
              "s.yaml:5: 'seed' is not accepted with grid sampling (it seeds random and latin)");
    EXPECT_EQ(errorOf(kHead + "axes: {mode: [full]}\nmeasures: [held]\n---\nname: u\n"),
              "s.yaml:5: a second YAML document (after '---') is not accepted; a study file is one document");
    // The same keys once each read.
    EXPECT_NO_THROW(parseStudy(kHead + "axes: {subject.stature: [1.741, 1.75]}\nsampling: random\nsamples: 2\nseed: 5\n"
                               "measures: [held, wall_time_s]\n", "s.yaml"));
}

// command: capacity runs `graspsim capacity` per case: its load options are run options, its
// measures are capacity.json's; the other command's options and measures are refused by line.
TEST(StudySpec, ACapacityStudyTakesTheLoadOptionsAndCapacityMeasures) {
    const StudySpec spec = parseStudy(kHead + "command: capacity\nset: {rate: 8, torque: false}\n"
                                              "axes: {direction: [-y, x], max_duration: {from: 0.5, to: 1, steps: 2}}\n"
                                              "measures: [slip_onset_n, drop_n, grip_force_start_n]\n",
                                      "s.yaml");
    EXPECT_EQ(spec.command, StudyCommand::Capacity);
    ASSERT_EQ(spec.axes.size(), 2u);
    EXPECT_TRUE(spec.axes[0].isRunOption);
    EXPECT_TRUE(spec.axes[1].isRange);
    EXPECT_EQ(parseStudy(kHead + "axes: {mode: [full]}\nmeasures: [held]\n", "s.yaml").command, StudyCommand::Simulate);
    EXPECT_NE(errorOf(kHead + "axes: {direction: [-y]}\nmeasures: [held]\n")
                  .find("s.yaml:3: run option 'direction' is not accepted with command: simulate"),
              std::string::npos);
    EXPECT_NE(errorOf(kHead + "command: capacity\naxes: {perturbation: [f1]}\nmeasures: [drop_n]\n")
                  .find("s.yaml:4: run option 'perturbation' is not accepted with command: capacity"),
              std::string::npos);
    EXPECT_NE(errorOf(kHead + "command: capacity\naxes: {direction: [-y]}\nmeasures: [held]\n")
                  .find("measure 'held' is not accepted; measures are capacity.json keys: slip_onset_n"),
              std::string::npos);
    EXPECT_NE(errorOf(kHead + "command: bisect\naxes: {mode: [full]}\nmeasures: [held]\n").find("'command' value 'bisect'"),
              std::string::npos);
    EXPECT_NE(errorOf(kHead + "command: capacity\naxes: {method: {from: 1, to: 2, steps: 2}}\nmeasures: [drop_n]\n")
                  .find("give a list of values"),
              std::string::npos);
}

// A direction written as a YAML list is the text `graspsim capacity --direction` takes; other
// vectors (scenario fields) stay YAML lists; a list of another length, a non-number or a lone
// number is refused naming the line.
TEST(StudySpec, ADirectionListBecomesTheCommandsThreeNumbers) {
    const std::string head = kHead + "command: capacity\n";
    const StudySpec axis = parseStudy(head + "axes: {direction: [[0, -1, 0], [1, 0.5, -2e-1], -y]}\nmeasures: [drop_n]\n", "s.yaml");
    ASSERT_EQ(axis.axes.size(), 1u);
    EXPECT_EQ(axis.axes[0].values, (std::vector<std::string>{"0,-1,0", "1,0.5,-2e-1", "-y"}));
    const StudySpec set = parseStudy(head + "set: {direction: [0, -1, 0], object.size: [0.07, 0.14, 0.008]}\naxes: {rate: [4]}\n"
                                            "measures: [drop_n]\n",
                                     "s.yaml");
    ASSERT_EQ(set.fixed.size(), 2u);
    EXPECT_EQ(set.fixed[0].value, "0,-1,0");
    EXPECT_EQ(set.fixed[1].value, "[0.07, 0.14, 0.008]");
    const std::string accepted = "is not accepted; a direction is x, y, z, -x, -y, -z or a list of three numbers such as "
                                 "[0, -1, 0] (an axis lists directions: [[0, -1, 0], [1, 0, 0]])";
    EXPECT_EQ(errorOf(head + "axes: {direction: [[0, -1], [1, 0, 0]]}\nmeasures: [drop_n]\n"),
              "s.yaml:4: run option 'direction' value '[0, -1]' " + accepted);
    EXPECT_EQ(errorOf(head + "set:\n  direction: [0, a, 0]\naxes: {rate: [4]}\nmeasures: [drop_n]\n"),
              "s.yaml:5: run option 'direction' value '[0, a, 0]' " + accepted);
    EXPECT_EQ(errorOf(head + "axes: {direction: [[0, .inf, 0]]}\nmeasures: [drop_n]\n"),
              "s.yaml:4: run option 'direction' value '[0, .inf, 0]' " + accepted);
    EXPECT_EQ(errorOf(head + "axes: {direction: [0, -1, 0]}\nmeasures: [drop_n]\n"), "s.yaml:4: run option 'direction' value '0' " + accepted);
    EXPECT_EQ(errorOf(head + "axes: {direction: [[0, -1, 0], '0,-1,0']}\nmeasures: [drop_n]\n"),
              "s.yaml:4: axis 'direction' value '0,-1,0' is listed twice; give each value once");
    // In a simulate study direction is no option at all, whatever its value.
    EXPECT_NE(errorOf(kHead + "axes: {direction: [[0, -1]]}\nmeasures: [held]\n")
                  .find("s.yaml:3: run option 'direction' is not accepted with command: simulate"),
              std::string::npos);
}

// A measure that is also an axis would be a second column of that name in results.csv; one that
// is also set only repeats the set value.
TEST(StudySpec, AMeasureThatIsAlsoAnAxisOrSetIsRefused) {
    const std::string head = kHead + "command: capacity\n";
    EXPECT_EQ(errorOf(head + "axes: {rate: [4, 8]}\nmeasures: [drop_n, rate]\n"),
              "s.yaml:5: measure 'rate' is also an axis; its values are in the axis column");
    EXPECT_EQ(errorOf(head + "set: {rate: 8}\naxes: {direction: [-y]}\nmeasures:\n  - drop_n\n  - rate\n"),
              "s.yaml:8: measure 'rate' is also a set key (line 4); every case has the value given there");
    EXPECT_NO_THROW(parseStudy(head + "axes: {direction: [-y]}\nmeasures: [drop_n, rate]\n", "s.yaml"));
}
