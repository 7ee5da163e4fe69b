#pragma once
// The anthropometry CSV files, compiled into the library by cmake/EmbedFiles.cmake so that
// the CSVs stay the single source of truth and nothing reads the source tree at run time.

#include "graspsim/io/embedded_file.h"

#include <cstddef>
#include <string>
#include <string_view>

namespace graspsim::anthropometry {

using io::EmbeddedFile;

// Defined in the generated embedded_tables_data.cpp.
extern const EmbeddedFile kEmbeddedFiles[];
extern const std::size_t kEmbeddedFileCount;

/// The text of the embedded file `fileName` (e.g. "joint_ranges.csv"). Throws graspsim::Error
/// if no such file was embedded, which is a build mistake rather than bad user input.
std::string_view findEmbeddedTable(const std::string& fileName);

/// The name used in error messages for an embedded file: "anthropometry/<fileName>".
std::string findEmbeddedTableSource(const std::string& fileName);

}  // namespace graspsim::anthropometry
