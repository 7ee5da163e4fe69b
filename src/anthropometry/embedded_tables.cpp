#include "embedded_tables.h"

#include <graspsim/error.h>

namespace graspsim::anthropometry {

std::string_view findEmbeddedTable(const std::string& fileName) {
    std::string known;
    for (std::size_t i = 0; i < kEmbeddedFileCount; ++i) {
        if (kEmbeddedFiles[i].name == fileName) return kEmbeddedFiles[i].text;
        known += (i == 0 ? "" : ", ") + std::string(kEmbeddedFiles[i].name);
    }
    throw Error("embedded table '" + fileName + "' is not in the library; embedded: " + known);
}

std::string findEmbeddedTableSource(const std::string& fileName) {
    return "anthropometry/" + fileName;
}

}  // namespace graspsim::anthropometry
