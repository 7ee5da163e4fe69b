// Counting a YAML text's documents from its markers (yaml_documents.h). Oracle: the YAML 1.2
// rules for document markers, on texts written by hand; and the scenario file fuzzer's input that
// made yaml-cpp's LoadAll loop for good, which must now be refused as malformed YAML.

#include "graspsim/scenario/yaml_documents.h"

#include "graspsim/error.h"
#include "graspsim/scenario/scenario_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace graspsim::scenario {
namespace {

TEST(YamlDocuments, OneDocumentWithOrWithoutItsMarkers) {
    EXPECT_EQ(findSecondYamlDocument(""), 0);
    EXPECT_EQ(findSecondYamlDocument("name: a\nmass: 1\n"), 0);
    EXPECT_EQ(findSecondYamlDocument("# comment\n%YAML 1.2\n---\nname: a\n...\n# trailing comment\n\n"), 0);
    EXPECT_EQ(findSecondYamlDocument("---\nname: a\n"), 0);
    EXPECT_EQ(findSecondYamlDocument("name: '---'\nnote: a---b\n  ---x\n"), 0);  // not markers
}

TEST(YamlDocuments, ASecondDocumentIsFoundAtItsLine) {
    EXPECT_EQ(findSecondYamlDocument("name: a\n---\nname: b\n"), 2);
    EXPECT_EQ(findSecondYamlDocument("---\nname: a\n--- # second\nname: b\n"), 3);
    EXPECT_EQ(findSecondYamlDocument("name: a\n---\n"), 2);  // an empty second document is one too
    EXPECT_EQ(findSecondYamlDocument("name: a\n...\n\nname: b\n"), 4);
    EXPECT_EQ(findSecondYamlDocument("name: a\r\n---\r\nname: b\r\n"), 2);
}

TEST(YamlDocuments, TheFuzzersLoopingInputIsRefusedAsMalformed) {
    std::ifstream file(GRASPSIM_SOURCE_DIR "/tests/fuzz/corpus/scenario_file/loadall_loop.yaml", std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    ASSERT_FALSE(text.str().empty());
    try {
        parseScenario(text.str(), "fuzz.yaml");
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("fuzz.yaml:2:"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace graspsim::scenario
