#include "output_folder.h"

#include "graspsim/error.h"

#include <filesystem>
#include <system_error>

namespace graspsim::cli {

namespace fs = std::filesystem;

namespace {

// `path` absolute, without "." or ".." and without a trailing separator.
fs::path normalize(const std::string& path) {
    std::error_code ec;
    fs::path p = fs::absolute(path, ec).lexically_normal();
    return p.has_filename() ? p : p.parent_path();
}

// The outermost of `path` and its parents that does not exist yet ("" if `path` exists).
std::string findTopMissing(const std::string& path) {
    std::error_code ec;
    fs::path top;
    for (fs::path p = normalize(path); !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
        top = p;
        if (p == p.parent_path()) break;
    }
    return top.string();
}

}  // namespace

OutputFolder::OutputFolder(const std::string& path) : path_(path), topCreated_(findTopMissing(path)) {
    std::error_code ec;
    fs::create_directories(path, ec);
    if (ec || !fs::is_directory(path)) {
        throw InputError("--out: folder '" + path + "' cannot be created or written (" + ec.message() + ")");
    }
}

// fs::remove removes a folder only while it is empty; it never throws with an error_code.
OutputFolder::~OutputFolder() {
    if (kept_ || topCreated_.empty()) return;
    std::error_code ec;
    const fs::path top = topCreated_;
    for (fs::path p = normalize(path_); !p.empty(); p = p.parent_path()) {
        if (!fs::remove(p, ec) || p == top || p == p.parent_path()) break;
    }
}

}  // namespace graspsim::cli
