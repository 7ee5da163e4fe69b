// libFuzzer target: scenario YAML text, as `graspsim simulate my.yaml` reads it. Every input is
// either an accepted scenario or a graspsim::InputError; anything else (a crash, another
// exception, a sanitizer report) is a finding.

#include "graspsim/error.h"
#include "graspsim/scenario/scenario_file.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        graspsim::scenario::parseScenario(text, "fuzz.yaml");
    } catch (const graspsim::InputError&) {
    }
    return 0;
}
