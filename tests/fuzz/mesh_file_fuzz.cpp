// libFuzzer target: the bytes of a mesh file, as a scenario's `object.mesh` hands them to
// graspsim (assimp's STL and OBJ readers, then the closed/outward/convex checks). The first byte
// picks the format (even: STL, odd: OBJ), the rest is the file. Every input is either accepted
// or a graspsim::InputError; anything else (a crash, another exception, a sanitizer report) is a finding.

#include "graspsim/error.h"
#include "graspsim/model/mesh_file.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const std::string format = data[0] % 2 == 0 ? "stl" : "obj";
    const std::string bytes(reinterpret_cast<const char*>(data + 1), size - 1);
    try {
        graspsim::model::parseMeshBytes(bytes, format, {1, 1, 1}, "fuzz." + format);
    } catch (const graspsim::InputError&) {
    }
    return 0;
}
