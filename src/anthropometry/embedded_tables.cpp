#include "embedded_tables.h"


namespace graspsim::anthropometry {

std::string_view findEmbeddedTable(const std::string& fileName) {
    return io::findEmbeddedFile(kEmbeddedFiles, kEmbeddedFileCount, fileName);
}

std::string findEmbeddedTableSource(const std::string& fileName) {
    return "anthropometry/" + fileName;
}

}  // namespace graspsim::anthropometry
