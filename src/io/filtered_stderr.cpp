#include "graspsim/io/filtered_stderr.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <utility>

namespace graspsim::io {

namespace {

bool startsWithAny(const std::string& block, const std::vector<std::string>& prefixes) {
    const std::size_t first = block.find_first_not_of("\r\n");
    if (first == std::string::npos) return false;
    for (const std::string& p : prefixes) {
        if (block.compare(first, p.size(), p) == 0) return true;
    }
    return false;
}

// One scratch file for the process, made once and emptied at every use: a scope may be entered
// hundreds of times per simulated second (once per output sample).
int findScratchFile() {
    static const int fd = [] {
        char name[] = "/tmp/graspsim-stderr-XXXXXX";
        const int made = ::mkstemp(name);
        if (made >= 0) ::unlink(name);  // gone when the process ends
        return made;
    }();
    return fd;
}

std::string readAll(int fd) {
    std::string text;
    if (::lseek(fd, 0, SEEK_SET) < 0) return text;
    char buffer[4096];
    for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0;) text.append(buffer, static_cast<std::size_t>(n));
    return text;
}

// std::cerr cannot be used while it goes to the scratch file.
void writeAll(int fd, const std::string& text) {
    for (std::size_t done = 0; done < text.size();) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n <= 0) return;
        done += static_cast<std::size_t>(n);
    }
}

}  // namespace

std::string filterBlocks(const std::string& text, const std::vector<std::string>& dropPrefixes, std::string& dropped) {
    std::string kept;
    for (std::size_t begin = 0; begin < text.size();) {
        // A block runs to the end of its first blank line (two line breaks in a row), or to the end.
        std::size_t end = text.find("\n\n", text.find_first_not_of('\n', begin));
        end = end == std::string::npos ? text.size() : end + 2;
        const std::string block = text.substr(begin, end - begin);
        if (startsWithAny(block, dropPrefixes)) {
            dropped += block;
        } else {
            kept += block;
        }
        begin = end;
    }
    return kept;
}

FilteredStderr::FilteredStderr(std::vector<std::string> dropPrefixes) : dropPrefixes_(std::move(dropPrefixes)) {
#ifndef GRASPSIM_SANITIZED
    std::cerr.flush();
    std::fflush(stderr);
    capture_ = findScratchFile();
    if (capture_ < 0 || ::ftruncate(capture_, 0) != 0 || ::lseek(capture_, 0, SEEK_SET) < 0) {
        capture_ = -1;
        return;
    }
    saved_ = ::dup(2);
    if (saved_ < 0 || ::dup2(capture_, 2) < 0) {
        if (saved_ >= 0) ::close(saved_);
        saved_ = capture_ = -1;
    }
#endif
}

FilteredStderr::~FilteredStderr() { release(); }

void FilteredStderr::forward() {
    if (saved_ < 0) return;
    std::cerr.flush();
    std::fflush(stderr);
    // fd 2 shares the scratch file's offset: a non-zero offset means something was written.
    if (::lseek(capture_, 0, SEEK_CUR) <= 0) return;
    const std::string kept = filterBlocks(readAll(capture_), dropPrefixes_, dropped_);
    if (::ftruncate(capture_, 0) != 0 || ::lseek(capture_, 0, SEEK_SET) < 0) {
        // The scratch file cannot be reused: stop filtering rather than lose or repeat text.
        ::dup2(saved_, 2);
        ::close(saved_);
        saved_ = capture_ = -1;
    }
    writeAll(saved_ >= 0 ? saved_ : 2, kept);
}

void FilteredStderr::release() {
    if (saved_ < 0) return;
    std::cerr.flush();
    std::fflush(stderr);
    ::dup2(saved_, 2);
    ::close(saved_);
    saved_ = -1;
    const std::string kept = filterBlocks(readAll(capture_), dropPrefixes_, dropped_);
    capture_ = -1;  // the scratch file stays open for the next scope
    if (!kept.empty()) std::cerr << kept << std::flush;
}

}  // namespace graspsim::io
