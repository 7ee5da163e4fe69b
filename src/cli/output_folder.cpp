#include "output_folder.h"

#include "graspsim/error.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
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

// Why `folder` takes no file ("" when it does): a file is created, written and removed, as the
// folder's permission bits alone do not say (root ignores them; a read-only mount does not).
std::string probeWriting(const std::string& folder) {
    const std::string probe = (fs::path(folder) / (".graspsim-write-test-" + std::to_string(::getpid()))).string();
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
    if (fd < 0) return std::strerror(errno);
    const bool written = ::write(fd, "x", 1) == 1;
    const int writeError = errno;
    const bool closed = ::close(fd) == 0;
    const int closeError = errno;
    ::unlink(probe.c_str());
    if (!written) return std::strerror(writeError);
    return closed ? "" : std::strerror(closeError);
}

}  // namespace

OutputFolder::OutputFolder(const std::string& path) : path_(path), topCreated_(findTopMissing(path)) {
    std::error_code ec;
    fs::create_directories(path, ec);
    const std::string reason = ec ? ec.message() : !fs::is_directory(path, ec) ? "not a folder" : probeWriting(path);
    if (!reason.empty()) {
        removeCreated();  // a failed creation may have made some of the parents
        throw InputError("--out: folder '" + path + "' cannot be created or written (" + reason + ")");
    }
}

OutputFolder::~OutputFolder() {
    if (!kept_) removeCreated();
}

// fs::remove removes a folder only while it is empty; it never throws with an error_code. A folder
// that is not there (a leaf whose creation failed, its name too long, ...) is passed over.
void OutputFolder::removeCreated() const {
    if (topCreated_.empty()) return;
    std::error_code ec;
    const fs::path top = topCreated_;
    for (fs::path p = normalize(path_); !p.empty(); p = p.parent_path()) {
        if (!fs::remove(p, ec) && fs::exists(p, ec)) break;  // it holds files: it and its parents stay
        if (p == top || p == p.parent_path()) break;
    }
}

}  // namespace graspsim::cli
