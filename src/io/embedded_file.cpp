#include "graspsim/io/embedded_file.h"

#include "graspsim/error.h"

namespace graspsim::io {

std::string_view findEmbeddedFile(const EmbeddedFile* files, std::size_t count, const std::string& name) {
    std::string known;
    for (std::size_t i = 0; i < count; ++i) {
        if (files[i].name == name) return files[i].text;
        known += (i == 0 ? "" : ", ") + std::string(files[i].name);
    }
    throw Error("embedded file '" + name + "' is not in the library; embedded: " + known);
}

}  // namespace graspsim::io
