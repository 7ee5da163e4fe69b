// libFuzzer target: graspsim's command line. The input is the argument list, one argument per
// line. Only parsing and the option checks run (CommandLine::parse, checkOptions): no
// simulation, no file read or written. Every input is either accepted, a CLI11 parse error
// (help and version requests included) or a graspsim::InputError; anything else is a finding.

#include "command_line.h"

#include "graspsim/error.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace {

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t begin = 0;
    while (begin <= text.size()) {
        const std::size_t end = std::min(text.find('\n', begin), text.size());
        lines.push_back(text.substr(begin, end - begin));
        begin = end + 1;
    }
    return lines;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> args{"graspsim"};
    for (std::string& a : splitLines(std::string(reinterpret_cast<const char*>(data), size))) args.push_back(std::move(a));
    std::vector<const char*> argv;
    for (const std::string& a : args) argv.push_back(a.c_str());
    graspsim::cli::CommandLine commandLine;
    try {
        commandLine.parse(static_cast<int>(argv.size()), argv.data());
        commandLine.checkOptions();
    } catch (const CLI::ParseError&) {
    } catch (const graspsim::InputError&) {
    }
    return 0;
}
