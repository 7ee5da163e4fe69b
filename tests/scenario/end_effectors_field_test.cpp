// The scenario field `end_effectors:` (points fixed on a segment that goals may name, as the
// lateral pinch's side of the index): read into the body options, added to the arm's
// end-effectors, written back unchanged; bad entries are one line naming the file, field and
// value. Oracle: the point read is the point written, and the model's end-effector sits there.

#include "graspsim/scenario/scenario_file.h"
#include "graspsim/scenario/scenario_writer.h"

#include "graspsim/error.h"
#include "graspsim/model/body_model.h"

#include <gtest/gtest.h>

using namespace graspsim;

namespace {

const std::string kKey = R"(name: key
object: {shape: box, mass: 0.02, size: [0.05, 0.02, 0.003], position: [0.45, -0.05, -0.05]}
grasp_pose: {elbow_flexion: 90}
end_effectors:
  index_side: {body: index_middle, point: [0, -0.0134, 0.0081]}
goals:
  thumb_tip: [0, 0, -0.0015]
  index_side: [0, 0, 0.0015]
controller: {press_depth: 0.0008}
)";

std::string replace(std::string text, const std::string& from, const std::string& to) {
    text.replace(text.find(from), from.size(), to);
    return text;
}

void expectRefused(const std::string& text, std::initializer_list<const char*> fragments) {
    try {
        scenario::parseScenario(text, "key.yaml");
        FAIL() << "accepted:\n" << text;
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        for (const char* f : fragments) EXPECT_NE(message.find(f), std::string::npos) << "'" << f << "' not in: " << message;
    }
}

}  // namespace

TEST(EndEffectorsField, APointOnASegmentBecomesAnEndEffectorAGoalMayName) {
    const scenario::Scenario s = scenario::parseScenario(kKey, "key.yaml");
    ASSERT_EQ(s.bodyOptions.segmentPoints.size(), 1u);
    const model::SegmentPoint& p = s.bodyOptions.segmentPoints[0];
    EXPECT_EQ(p.name, "index_side");
    EXPECT_EQ(p.body, "index_middle");
    EXPECT_DOUBLE_EQ(p.p_B[1], -0.0134);
    EXPECT_DOUBLE_EQ(p.p_B[2], 0.0081);
    const model::ModelDescription built = model::buildBodyModel(s.bodyOptions);
    const model::EndEffector* e = built.findEndEffector("index_side");
    ASSERT_NE(e, nullptr);
    EXPECT_EQ(e->body, "index_middle");
    EXPECT_DOUBLE_EQ(e->p_BE[2], 0.0081);
    EXPECT_EQ(s.goals.count("index_side"), 1u);
    // Written and read back: the same point.
    const scenario::Scenario reread = scenario::parseScenario(scenario::formatScenarioYaml(s), "written.yaml");
    ASSERT_EQ(reread.bodyOptions.segmentPoints.size(), 1u);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(reread.bodyOptions.segmentPoints[0].p_B[i], p.p_B[i]);
}

TEST(EndEffectorsField, AScenarioWithoutTheFieldWritesNoSection) {
    const scenario::Scenario ball = scenario::findBuiltinScenario("ball-clutch");
    EXPECT_TRUE(ball.bodyOptions.segmentPoints.empty());
    EXPECT_EQ(scenario::formatScenarioYaml(ball).find("end_effectors"), std::string::npos);
}

TEST(EndEffectorsField, BadEntriesNameTheFileFieldAndValue) {
    expectRefused(replace(kKey, "body: index_middle", "body: index_knuckle"),
                  {"key.yaml", "end_effectors.index_side.body", "index_knuckle", "not a body"});
    expectRefused(replace(replace(kKey, "  index_side: {body", "  index_tip: {body"), "index_side: [0", "index_tip: [0"),
                  {"key.yaml", "end_effectors.index_tip", "already"});
    expectRefused(replace(kKey, "point: [0, -0.0134, 0.0081]", "point: [0, -0.0134]"), {"key.yaml", "end_effectors.index_side.point"});
    expectRefused(replace(kKey, "body: index_middle, ", ""), {"key.yaml", "end_effectors.index_side.body", "missing"});
    expectRefused(replace(kKey, "  index_side: [0, 0, 0.0015]", "  index_edge: [0, 0, 0.0015]"),
                  {"key.yaml", "goals.index_edge", "index_side"});
}

TEST(EndEffectorsField, APlannedGraspLeavesItToThePlanner) {
    expectRefused("name: k\nobject: {shape: box, mass: 0.02, size: [0.05, 0.02, 0.003]}\ngrasp: {type: lateral}\n"
                  "controller: {press_depth: 0.0008}\nend_effectors: {s: {body: index_middle, point: [0, 0, 0]}}\n",
                  {"end_effectors", "grasp.type"});
}
