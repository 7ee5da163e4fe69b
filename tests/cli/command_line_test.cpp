// The command line's own checks, before any command runs: an option given an empty value is bad
// input naming the option, not "left out" (which would silently take the option's default).
// Oracle: the exception's message, and that a flag or a non-empty value still parses.

#include "command_line.h"

#include "graspsim/error.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace graspsim::cli {
namespace {

// Parses `arguments` (without the program name); returns the InputError's message, "" if none.
std::string findParseError(std::vector<const char*> arguments) {
    arguments.insert(arguments.begin(), "graspsim");
    CommandLine commandLine;
    try {
        commandLine.parse(static_cast<int>(arguments.size()), arguments.data());
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(CommandLine, RefusesAnOptionGivenAnEmptyValue) {
    EXPECT_EQ(findParseError({"simulate", "ball-clutch", "--duration", ""}),
              "--duration: value '' (empty) is not accepted; give a value or leave --duration out");
    EXPECT_EQ(findParseError({"model", "build", "--mass", "", "-o", "arm.urdf"}),
              "--mass: value '' (empty) is not accepted; give a value or leave --mass out");
    EXPECT_EQ(findParseError({"grasp", "plan", "--object", "sphere:radius=0.04,mass=0.2", "--name", "", "-o", "x.yaml"}),
              "--name: value '' (empty) is not accepted; give a value or leave --name out");
    // A required option or argument cannot be left out.
    EXPECT_EQ(findParseError({"model", "build", "-o", ""}), "--output: value '' (empty) is not accepted; give a value");
    EXPECT_EQ(findParseError({"simulate", ""}), "scenario: value '' (empty) is not accepted; give a value");
}

// Parses `arguments` (without the program name) as main does a CLI11 parse error: what it prints
// on stderr and the exit code.
std::pair<std::string, int> findParseExit(std::vector<const char*> arguments) {
    arguments.insert(arguments.begin(), "graspsim");
    CommandLine commandLine;
    ::testing::internal::CaptureStderr();
    int code = 0;
    try {
        commandLine.parse(static_cast<int>(arguments.size()), arguments.data());
    } catch (const CLI::ParseError& e) {
        code = commandLine.exit(e);
    }
    return {::testing::internal::GetCapturedStderr(), code};
}

// CLI11's own text for an option given twice counts values, not options ("received 3").
TEST(CommandLine, AnOptionGivenTwiceIsNamedInOneLine) {
    EXPECT_EQ(findParseExit({"simulate", "ball-clutch", "--duration", "0.1", "--duration", "0.3"}),
              std::make_pair(std::string("graspsim: --duration: given more than once; give each option once (see graspsim --help)\n"), 2));
}

// CLI11 lists the words it did not expect last first; the line gives them as they were typed.
TEST(CommandLine, AnUnknownOptionIsNamedAsTyped) {
    EXPECT_EQ(findParseExit({"simulate", "ball-clutch", "--output-interval", "0.1"}),
              std::make_pair(std::string("graspsim: not an option or argument of this command: --output-interval 0.1 (see graspsim --help)\n"), 2));
}

TEST(CommandLine, AcceptsFlagsAndGivenValues) {
    EXPECT_EQ(findParseError({"simulate", "ball-clutch", "--duration", "0.2", "-q", "--view"}), "");
    EXPECT_EQ(findParseError({"model", "build", "--sex", "female", "-o", "arm.urdf"}), "");
    EXPECT_EQ(findParseError({"bench", "--json", "-q"}), "");
}

}  // namespace
}  // namespace graspsim::cli
