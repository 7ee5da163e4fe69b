// libFuzzer target: URDF text, as `graspsim model info file.urdf` reads it: import, then build the
// Simbody system from the description. Every input is either accepted by both or a
// graspsim::InputError from the import; anything else (a crash, another exception, e.g. Simbody
// rejecting what the import let through, a sanitizer report) is a finding.

#include "graspsim/error.h"
#include "graspsim/model/urdf_import.h"
#include "graspsim/system/multibody_model.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string xml(reinterpret_cast<const char*>(data), size);
    try {
        const graspsim::model::ModelDescription description = graspsim::model::readUrdf(xml, "fuzz.urdf");
        graspsim::system::MultibodyModel multibody(description);
        multibody.realizeTopology();
    } catch (const graspsim::InputError&) {
    }
    return 0;
}
