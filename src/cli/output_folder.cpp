#include "output_folder.h"

#include "graspsim/error.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

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

// The file probeWriting creates and removes in `folder`.
std::string findProbeFile(const std::string& folder) {
    return (fs::path(folder) / (".graspsim-write-test-" + std::to_string(::getpid()))).string();
}

// Why `folder` takes no file ("" when it does): a file is created, written and removed, as the
// folder's permission bits alone do not say (root ignores them; a read-only mount does not).
std::string probeWriting(const std::string& folder) {
    const std::string probe = findProbeFile(folder);
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

// What the signal handler may touch: fixed buffers written before a slot is published, so the
// handler needs no allocation or lock (rmdir, write and raise are async-signal-safe).
constexpr int kInterruptSlots = 4;
constexpr int kInterruptLevels = 8;
constexpr std::size_t kInterruptPath = 4096;
struct InterruptSlot {
    std::atomic<bool> used{false};
    int levels = 0;                                   // created folders, leaf first
    char paths[kInterruptLevels][kInterruptPath] = {};
    char probe[kInterruptPath] = {};                  // the writing probe's file in the leaf
};
InterruptSlot gInterruptSlots[kInterruptSlots];

// The folders from `leaf` up to `top`, leaf first, in a free slot; -1 if none is free or a path
// does not fit (the folder is then left to the default signal action, as before).
int publishCreated(const fs::path& leaf, const fs::path& top, const std::string& probe) {
    if (probe.size() >= kInterruptPath) return -1;
    std::vector<std::string> levels;
    for (fs::path p = leaf; !p.empty(); p = p.parent_path()) {
        levels.push_back(p.string());
        if (p == top || p == p.parent_path()) break;
    }
    if (levels.size() > static_cast<std::size_t>(kInterruptLevels)) return -1;
    for (const std::string& level : levels) if (level.size() >= kInterruptPath) return -1;
    for (int k = 0; k < kInterruptSlots; ++k) {
        InterruptSlot& slot = gInterruptSlots[k];
        if (slot.used.load()) continue;
        for (std::size_t i = 0; i < levels.size(); ++i) std::memcpy(slot.paths[i], levels[i].c_str(), levels[i].size() + 1);
        std::memcpy(slot.probe, probe.c_str(), probe.size() + 1);
        slot.levels = static_cast<int>(levels.size());
        slot.used.store(true);
        return k;
    }
    return -1;
}

void writeError(const char* text) {
    const ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
    (void)ignored;
}

extern "C" void removeCreatedAndReraise(int signal) {
    writeError("graspsim: interrupted");
    for (InterruptSlot& slot : gInterruptSlots) {
        if (!slot.used.load() || slot.levels == 0) continue;
        // Published before the folders are made: a signal may come before they all exist, or
        // while the writing probe's file is in the leaf. A folder not made yet is not left.
        ::unlink(slot.probe);
        const bool removed = ::rmdir(slot.paths[0]) == 0 || errno == ENOENT;
        for (int i = 1; removed && i < slot.levels; ++i) {
            if (::rmdir(slot.paths[i]) != 0 && errno != ENOENT) break;
        }
        writeError(removed ? "; removed the unfinished folder " : "; left ");
        writeError(slot.paths[0]);
        if (!removed) writeError(", which holds part of the results");
    }
    writeError("\n");
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

}  // namespace

void removeFoldersOnInterrupt() {
    for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
        struct sigaction action {};
        action.sa_handler = removeCreatedAndReraise;
        sigemptyset(&action.sa_mask);
        for (int other : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&action.sa_mask, other);  // one cleanup at a time
        ::sigaction(signal, &action, nullptr);
    }
}

OutputFolder::OutputFolder(const std::string& path) : path_(path), topCreated_(findTopMissing(path)) {
    // Published before anything is made, so that no signal finds a folder the handler does not know.
    if (!topCreated_.empty()) interruptSlot_ = publishCreated(normalize(path_), topCreated_, findProbeFile(normalize(path_).string()));
    std::error_code ec;
    fs::create_directories(path, ec);
    const std::string reason = ec ? ec.message() : !fs::is_directory(path, ec) ? "not a folder" : probeWriting(path);
    if (!reason.empty()) {
        if (interruptSlot_ >= 0) gInterruptSlots[interruptSlot_].used.store(false);
        removeCreated();  // a failed creation may have made some of the parents
        throw InputError("--out: folder '" + path + "' cannot be created or written (" + reason + ")");
    }
}

OutputFolder::~OutputFolder() {
    if (interruptSlot_ >= 0) gInterruptSlots[interruptSlot_].used.store(false);
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
