// A case's scenario: axis values land in the base scenario's fields (read back by the scenario
// reader), and values the reader refuses are refused with its message, naming the study file's
// line and axis.

#include "graspsim/error.h"
#include "graspsim/study/case_setup.h"

#include <gtest/gtest.h>

using namespace graspsim::study;
namespace scenario = graspsim::scenario;

namespace {

StudySpec makeSpec(const std::string& axes, const std::string& set = "") {
    return parseStudy("name: t\nbase: ball-clutch\n" + set + "axes:\n" + axes + "measures: [held]\n", "s.yaml");
}

std::string checkError(const std::string& axes, const std::string& set = "") {
    const StudySpec spec = makeSpec(axes, set);
    try {
        checkStudyValues(spec, readBaseScenarios(spec));
    } catch (const graspsim::InputError& e) {
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
        return e.what();
    }
    ADD_FAILURE() << "accepted: " << axes;
    return "";
}

}  // namespace

TEST(CaseSetup, ValuesLandInTheScenarioFields) {
    const StudySpec spec = makeSpec("  subject.stature: [1.6]\n  perturbations.f1.force: [[0, -3, 1]]\n  mode: [approx]\n"
                                    "  contact.static_friction: [0.75]\n",
                                    "set: {perturbation: f1, simulation.duration: 2.5, integrator: cvode}\n");
    const std::vector<scenario::ScenarioText> base = readBaseScenarios(spec);
    checkStudyValues(spec, base);
    const CaseSetup setup = makeCaseSetup(spec, base, expandCases(spec).at(0));
    const scenario::Scenario parsed = scenario::parseScenario(setup.scenarioYaml, "case");
    EXPECT_EQ(parsed.bodyOptions.subject.stature, 1.6);
    EXPECT_EQ(parsed.contact.staticFriction, 0.75);
    EXPECT_EQ(parsed.simulation.duration, 2.5);
    ASSERT_NE(parsed.findPerturbation("f1"), nullptr);
    EXPECT_EQ(parsed.findPerturbation("f1")->force[1], -3.0);
    EXPECT_EQ(parsed.findPerturbation("f1")->force[2], 1.0);
    // The other fields stay the base's.
    const scenario::Scenario original = scenario::findBuiltinScenario("ball-clutch");
    EXPECT_EQ(parsed.object.mass, original.object.mass);
    EXPECT_EQ(parsed.graspPose, original.graspPose);
    using Options = std::vector<std::pair<std::string, std::string>>;
    EXPECT_EQ(setup.options, (Options{{"--mode", "approx"}, {"--integrator", "cvode"}, {"--perturbation", "f1"}}));
}

// A set constraint is the approximation's: its full-contact cases run without it (simulate
// refuses --constraint without --mode approx), its approx cases with it.
TEST(CaseSetup, ApproximationOptionsGoToApproxCasesOnly) {
    const StudySpec spec = makeSpec("  mode: [full, approx]\n", "set: {constraint: weld, attach: merged}\n");
    const std::vector<scenario::ScenarioText> base = readBaseScenarios(spec);
    checkStudyValues(spec, base);
    using Options = std::vector<std::pair<std::string, std::string>>;
    EXPECT_EQ(makeCaseSetup(spec, base, expandCases(spec).at(0)).options, (Options{{"--mode", "full"}}));
    EXPECT_EQ(makeCaseSetup(spec, base, expandCases(spec).at(1)).options,
              (Options{{"--mode", "approx"}, {"--constraint", "weld"}, {"--attach", "merged"}}));
}

// The bushing's give likewise, as simulate's and capacity's --bushing-give.
TEST(CaseSetup, TheBushingsGiveGoesToApproxCasesOnly) {
    const StudySpec spec = makeSpec("  mode: [full, approx]\n", "set: {bushing_give: model}\n");
    const std::vector<scenario::ScenarioText> base = readBaseScenarios(spec);
    checkStudyValues(spec, base);
    using Options = std::vector<std::pair<std::string, std::string>>;
    EXPECT_EQ(makeCaseSetup(spec, base, expandCases(spec).at(0)).options, (Options{{"--mode", "full"}}));
    EXPECT_EQ(makeCaseSetup(spec, base, expandCases(spec).at(1)).options, (Options{{"--mode", "approx"}, {"--bushing-give", "model"}}));
}

// The approximation's release options likewise, so a study can compare its variants across subjects.
TEST(CaseSetup, TheReleaseOptionsGoToApproxCasesOnly) {
    const StudySpec spec =
        makeSpec("  mode: [full, approx]\n", "set: {release_at: compliance, release_give: 0.0015, release_creep: off, hand_back: deflected}\n");
    const std::vector<scenario::ScenarioText> base = readBaseScenarios(spec);
    checkStudyValues(spec, base);
    using Options = std::vector<std::pair<std::string, std::string>>;
    EXPECT_EQ(makeCaseSetup(spec, base, expandCases(spec).at(0)).options, (Options{{"--mode", "full"}}));
    EXPECT_EQ(makeCaseSetup(spec, base, expandCases(spec).at(1)).options,
              (Options{{"--mode", "approx"}, {"--release-at", "compliance"}, {"--release-give", "0.0015"}, {"--release-creep", "off"},
                       {"--hand-back", "deflected"}}));
    EXPECT_NE(checkError("  mode: [full, approx]\n  release_creep: [on, maybe]\n").find("run option 'release_creep': 'maybe' is not accepted"),
              std::string::npos);
    EXPECT_NE(checkError("  mode: [full, approx]\n  release_give: [0.001, -1]\n").find("run option 'release_give'"), std::string::npos);
    EXPECT_NE(checkError("  mode: [full, approx]\n  hand_back: [bent]\n").find("run option 'hand_back'"), std::string::npos);
    EXPECT_NE(checkError("  subject.stature: [1.741]\n", "set: {release_at: none}\n")
                  .find("s.yaml:3: run option 'release_at' is not accepted without mode approx"),
              std::string::npos);
}

TEST(CaseSetup, ApproximationOptionsWithoutModeAreRefused) {
    EXPECT_NE(checkError("  subject.stature: [1.741]\n", "set: {constraint: weld}\n")
                  .find("s.yaml:3: run option 'constraint' is not accepted without mode approx"),
              std::string::npos);
    EXPECT_NE(checkError("  subject.stature: [1.741]\n", "set: {bushing_give: model}\n")
                  .find("s.yaml:3: run option 'bushing_give' is not accepted without mode approx"),
              std::string::npos);
    // A bad value is refused before anything runs, also where an axis of modes would leave it to
    // the approx cases.
    EXPECT_NE(checkError("  mode: [full, approx]\n  bushing_give: [stiff, soft]\n").find("run option 'bushing_give': bushing give 'soft'"),
              std::string::npos);
    EXPECT_NE(checkError("  mode: [full, approx]\n  constraint: [bushing, wled]\n").find("run option 'constraint'"), std::string::npos);
}

TEST(CaseSetup, SectionsMissingFromTheBaseAreAdded) {
    // A minimal base without an approximation section.
    const StudySpec spec = makeSpec("  approximation.q_threshold: [2.5]\n");
    scenario::ScenarioText base = scenario::readScenarioText("ball-clutch");
    const std::size_t section = base.text.find("\napproximation:");  // the file's last section
    ASSERT_NE(section, std::string::npos);
    base.text.resize(section + 1);
    ASSERT_EQ(scenario::parseScenario(base.text, "cut").approximation.qThreshold, 0.0);
    const CaseSetup setup = makeCaseSetup(spec, {base}, expandCases(spec).at(0));
    EXPECT_EQ(scenario::parseScenario(setup.scenarioYaml, "case").approximation.qThreshold, 2.5);
}

TEST(CaseSetup, RefusedValuesGetTheReadersMessage) {
    EXPECT_NE(checkError("  subject.height: [1.7]\n").find("s.yaml:4: axis 'subject.height': field 'subject.height' is not accepted"),
              std::string::npos);
    EXPECT_NE(checkError("  subject.mass: [heavy]\n").find("field 'subject.mass' value 'heavy' is not accepted; body mass must be"),
              std::string::npos);
    EXPECT_NE(checkError("  subject.mass: [70, 500]\n").find("value '500' is not accepted"), std::string::npos);
    EXPECT_NE(checkError("  contact.static_friction: {from: -1, to: 1, steps: 3}\n").find("value '-1' is not accepted"), std::string::npos);
    EXPECT_NE(checkError("  object.mass.value: [1]\n").find("'object.mass' is a value, not a section"), std::string::npos);
    EXPECT_NE(checkError("  mode: [full, fast]\n").find("run option 'mode'"), std::string::npos);
    EXPECT_NE(checkError("  perturbation: [f1, f9]\n").find("'f9' is not accepted; the scenario has none, f1, f2"), std::string::npos);
    EXPECT_NE(checkError("  mode: [full]\n", "set: {subject.sex: other}\n").find("with the 'set' values"), std::string::npos);
}

// A combination the reader refuses, each value accepted alone, fails only its own case.
TEST(CaseSetup, CombinationRefusedByTheReaderFailsItsCase) {
    // Alone, each is accepted against the base's 0.9 / 0.7; 0.75 with 0.8 is not.
    const StudySpec spec = makeSpec("  contact.static_friction: [0.75, 0.9]\n  contact.dynamic_friction: [0.8]\n");
    const std::vector<scenario::ScenarioText> base = readBaseScenarios(spec);
    EXPECT_NO_THROW(checkStudyValues(spec, base));
    const std::vector<StudyCase> cases = expandCases(spec);
    EXPECT_THROW(makeCaseSetup(spec, base, cases[0]), graspsim::InputError);
    EXPECT_NO_THROW(makeCaseSetup(spec, base, cases[1]));
}

// A list of bases is the first axis: each case starts from its own base, the other axes apply to
// every base.
TEST(CaseSetup, EachCaseStartsFromTheBaseItsBaseAxisNames) {
    const StudySpec spec = parseStudy("name: t\nbase: [ball-clutch, phone-pinch]\naxes: {subject.stature: [1.6, 1.8]}\n"
                                      "measures: [held]\n", "s.yaml");
    ASSERT_EQ(spec.axes.size(), 2u);
    EXPECT_TRUE(spec.axes[0].isBase);
    const std::vector<scenario::ScenarioText> bases = readBaseScenarios(spec);
    checkStudyValues(spec, bases);
    const std::vector<StudyCase> cases = expandCases(spec);
    ASSERT_EQ(cases.size(), 4u);
    const double ballMass = scenario::findBuiltinScenario("ball-clutch").object.mass;
    const double phoneMass = scenario::findBuiltinScenario("phone-pinch").object.mass;
    const double expectedMass[] = {ballMass, ballMass, phoneMass, phoneMass};
    const double expectedStature[] = {1.6, 1.8, 1.6, 1.8};
    for (std::size_t c = 0; c < cases.size(); ++c) {
        const scenario::Scenario parsed = scenario::parseScenario(makeCaseSetup(spec, bases, cases[c]).scenarioYaml, "case");
        EXPECT_EQ(parsed.object.mass, expectedMass[c]) << c;
        EXPECT_EQ(parsed.bodyOptions.subject.stature, expectedStature[c]) << c;
    }
}

// The shipped grasp-types study: five planned bases, each with the four subjects' sections.
TEST(CaseSetup, ShippedGraspTypesStudyIsAccepted) {
    const StudySpec spec = loadStudyFile(std::string(GRASPSIM_SOURCE_DIR) + "/models/studies/grasp-types.yaml");
    ASSERT_EQ(spec.bases.size(), 5u);
    const std::vector<scenario::ScenarioText> bases = readBaseScenarios(spec);
    EXPECT_NO_THROW(checkStudyValues(spec, bases));
    const std::vector<StudyCase> cases = expandCases(spec);
    ASSERT_EQ(cases.size(), 40u);
    const scenario::Scenario last = scenario::parseScenario(makeCaseSetup(spec, bases, cases.back()).scenarioYaml, "case");
    EXPECT_EQ(last.graspType, "lateral");
    EXPECT_EQ(last.bodyOptions.subject.stature, 1.90);
}

// The shipped capacity study: the grasp-types bases and subjects, each case a -y ramp.
TEST(CaseSetup, ShippedCapacityStudyIsAccepted) {
    const StudySpec spec = loadStudyFile(std::string(GRASPSIM_SOURCE_DIR) + "/models/studies/capacity-grasp-types.yaml");
    EXPECT_EQ(spec.command, StudyCommand::Capacity);
    const std::vector<scenario::ScenarioText> bases = readBaseScenarios(spec);
    EXPECT_NO_THROW(checkStudyValues(spec, bases));
    const std::vector<StudyCase> cases = expandCases(spec);
    ASSERT_EQ(cases.size(), 40u);
    using Options = std::vector<std::pair<std::string, std::string>>;
    EXPECT_EQ(makeCaseSetup(spec, bases, cases.back()).options,
              (Options{{"--mode", "approx"}, {"--integrator", "implicit"}, {"--direction", "-y"}}));
}

// A capacity case's options: the study's names as the command's flags (max_duration is
// --max-duration), torque a flag given only when true; values the command would refuse are refused
// before anything runs, naming the line.
TEST(CaseSetup, CapacityOptionsBecomeTheCommandsFlags) {
    const auto capacitySpec = [](const std::string& axes) {
        return parseStudy("name: t\nbase: phone-pinch\ncommand: capacity\nset: {rate: 8, max_duration: 0.6}\naxes:\n" + axes +
                              "measures: [slip_onset_n]\n",
                          "s.yaml");
    };
    const StudySpec spec = capacitySpec("  direction: [-y, '1,0,0']\n  torque: [false, true]\n");
    const std::vector<scenario::ScenarioText> base = readBaseScenarios(spec);
    checkStudyValues(spec, base);
    using Options = std::vector<std::pair<std::string, std::string>>;
    EXPECT_EQ(makeCaseSetup(spec, base, expandCases(spec).at(0)).options,
              (Options{{"--direction", "-y"}, {"--rate", "8"}, {"--max-duration", "0.6"}}));
    EXPECT_EQ(makeCaseSetup(spec, base, expandCases(spec).at(3)).options,
              (Options{{"--direction", "1,0,0"}, {"--torque", ""}, {"--rate", "8"}, {"--max-duration", "0.6"}}));
    // A direction written as a YAML list is given as the command's three numbers.
    const StudySpec listed = capacitySpec("  direction: [[0, -1, 0], [1, 0.5, 0]]\n");
    const std::vector<scenario::ScenarioText> listedBase = readBaseScenarios(listed);
    checkStudyValues(listed, listedBase);
    EXPECT_EQ(makeCaseSetup(listed, listedBase, expandCases(listed).at(1)).options,
              (Options{{"--direction", "1,0.5,0"}, {"--rate", "8"}, {"--max-duration", "0.6"}}));
    const auto refusal = [&](const std::string& axes) {
        try {
            const StudySpec bad = capacitySpec(axes);
            checkStudyValues(bad, readBaseScenarios(bad));
        } catch (const graspsim::InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(refusal("  direction: [all]\n").find("s.yaml:6: axis 'direction': run option 'direction': 'all' is not accepted in a study"),
              std::string::npos);
    EXPECT_NE(refusal("  direction: ['0,0,0']\n").find("run option 'direction'"), std::string::npos);
    EXPECT_EQ(refusal("  direction: [[0, 0, 0]]\n"),
              "s.yaml:6: axis 'direction': run option 'direction': value '0,0,0' is not accepted (zero or non-finite); "
              "use x, y, z, -x, -y, -z or three numbers such as 0,-1,0 (not all zero)");
    EXPECT_NE(refusal("  load: [2, 0]\n").find("run option 'load': value 0 is not accepted; use a finite number > 0 (N"), std::string::npos);
    EXPECT_NE(refusal("  hold: [inf]\n").find("run option 'hold': value inf is not accepted"), std::string::npos);
    EXPECT_NE(refusal("  torque: [yes]\n").find("run option 'torque': 'yes' is not accepted; true"), std::string::npos);
    EXPECT_NE(refusal("  method: [compliance]\n").find("'compliance' is not accepted; ramp, bisection or constant"), std::string::npos);
    // The command's rule (capacity::checkSlipCriteria) against the drop threshold a study keeps.
    EXPECT_EQ(refusal("  slip_threshold: [0.001, 0.05]\n"),
              "s.yaml:6: axis 'slip_threshold': run option 'slip_threshold': value 0.05 is not accepted; the slip threshold (0.05 m) "
              "must be below the drop threshold (0.02 m, the default)");
}

// The load options each method takes (method_options.h), for every method the study runs: an
// option the method would leave unused, or a constant load without one, would fail every such
// case, so it is refused before anything runs, naming the option's line (the method's for a
// missing load).
TEST(CaseSetup, ACapacityStudysLoadOptionsAreTheMethods) {
    const auto refusal = [](const std::string& body) {
        try {
            const StudySpec spec = parseStudy("name: t\nbase: phone-pinch\ncommand: capacity\n" + body + "measures: [slip_onset_n]\n", "s.yaml");
            checkStudyValues(spec, readBaseScenarios(spec));
        } catch (const graspsim::InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(refusal("set: {load: 2}\naxes:\n  mode: [full]\n"),
              "s.yaml:4: run option 'load': only with method constant (the constant load), not method ramp");
    EXPECT_EQ(refusal("set: {rate: 8, load: 2}\naxes:\n  method: [constant, bisection]\n"),
              "s.yaml:4: run option 'rate': only with method ramp, bisection or compliance (the ramp's rate, the compliance model's creep ramp's too; bisection's first load is rate x 1 s), "
              "not method constant");
    EXPECT_EQ(refusal("set: {method: constant}\naxes:\n  mode: [full]\n"),
              "s.yaml:4: run option 'load': missing; method constant needs the load, N (N m with a torque), a number > 0");
    EXPECT_EQ(refusal("axes:\n  hold: [0.5]\n"),
              "s.yaml:5: run option 'hold': only with method bisection or constant (how long each constant load is held), not method ramp");
    EXPECT_EQ(refusal("set: {method: constant, hold: 0.5}\naxes:\n  load: [1, 2]\n"), "accepted");
    EXPECT_EQ(refusal("set: {method: bisection, hold: 0.5, rate: 2}\naxes:\n  mode: [full]\n"), "accepted");
}
