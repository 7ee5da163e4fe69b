#include "output_file.h"

#include "graspsim/error.h"

#include <filesystem>
#include <system_error>

namespace graspsim::cli {

void checkOutputFile(const std::string& path, const std::string& option) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path file(path);
    if (fs::is_directory(file, ec) || !file.has_filename()) {
        throw InputError(option + ": value '" + path + "' is a folder; give the path of the file to write");
    }
    const fs::path folder = file.parent_path();
    if (!folder.empty() && !fs::is_directory(folder, ec)) {
        throw InputError(option + ": value '" + path + "' is not accepted; its folder '" + folder.string() +
                         "' does not exist (create it, or give a path in an existing folder)");
    }
}

}  // namespace graspsim::cli
