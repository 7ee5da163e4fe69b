#include "graspsim/io/filtered_stderr.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <mutex>
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

// Bytes [from, to) by pread, which leaves the offset fd 2 shares with the file to the writers.
// Zero bytes are left out: a write that raced the reset of the file between two redirections
// lands past its end, after a hole that reads as zeros, and stderr text has none of its own.
std::string readRange(int fd, off_t from, off_t to) {
    std::string text;
    char buffer[4096];
    for (off_t at = from; at < to;) {
        const ssize_t n = ::pread(fd, buffer, static_cast<std::size_t>(std::min<off_t>(sizeof buffer, to - at)), at);
        if (n <= 0) break;
        text.append(buffer, static_cast<std::size_t>(n));
        at += n;
    }
    text.erase(std::remove(text.begin(), text.end(), '\0'), text.end());
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

namespace {

// The redirection all live instances share (see the header), under `mutex`.
struct SharedRedirection {
    std::mutex mutex;
    int users = 0;
    int saved = -1;    // duplicate of the original fd 2, -1 when not redirected
    int capture = -1;  // the scratch file, -1 when not redirected
    off_t forwarded = 0;  // the scratch file's bytes already passed on (or dropped)
};

SharedRedirection& getRedirection() {
    static SharedRedirection shared;
    return shared;
}

// Passes on what the scratch file gained since the last time, minus the dropped blocks; with the
// lock held. The file is not emptied while fd 2 points at it: other threads write to it without
// the lock, and a write after a truncation would land at the old offset, past the new end.
void forwardCaptured(SharedRedirection& r, const std::vector<std::string>& dropPrefixes, std::string& dropped) {
    std::cerr.flush();
    std::fflush(stderr);
    // fd 2 shares the scratch file's offset: where the next write lands, past everything written.
    const off_t end = ::lseek(r.capture, 0, SEEK_CUR);
    if (end <= r.forwarded) return;
    const std::string kept = filterBlocks(readRange(r.capture, r.forwarded, end), dropPrefixes, dropped);
    r.forwarded = end;
    writeAll(r.saved, kept);
}

}  // namespace

FilteredStderr::FilteredStderr(std::vector<std::string> dropPrefixes) : dropPrefixes_(std::move(dropPrefixes)) {
#ifndef GRASPSIM_SANITIZED
    SharedRedirection& r = getRedirection();
    const std::lock_guard<std::mutex> lock(r.mutex);
    if (r.users > 0) {  // another instance's redirection (or none, if the scratch file failed under it)
        joined_ = true;
        ++r.users;
        return;
    }
    std::cerr.flush();
    std::fflush(stderr);
    const int capture = findScratchFile();
    if (capture < 0 || ::ftruncate(capture, 0) != 0 || ::lseek(capture, 0, SEEK_SET) < 0) return;
    const int saved = ::dup(2);
    if (saved < 0 || ::dup2(capture, 2) < 0) {
        if (saved >= 0) ::close(saved);
        return;
    }
    r.saved = saved;
    r.capture = capture;
    r.forwarded = 0;
    r.users = 1;
    joined_ = true;
#endif
}

FilteredStderr::~FilteredStderr() { release(); }

void FilteredStderr::forward() {
    if (!joined_) return;
    SharedRedirection& r = getRedirection();
    const std::lock_guard<std::mutex> lock(r.mutex);
    if (r.saved >= 0) forwardCaptured(r, dropPrefixes_, dropped_);
}

void FilteredStderr::release() {
    if (!joined_) return;
    joined_ = false;
    SharedRedirection& r = getRedirection();
    const std::lock_guard<std::mutex> lock(r.mutex);
    if (r.saved >= 0) forwardCaptured(r, dropPrefixes_, dropped_);
    if (--r.users > 0 || r.saved < 0) return;
    ::dup2(r.saved, 2);
    ::close(r.saved);
    r.saved = r.capture = -1;  // the scratch file stays open for the next scope
}

}  // namespace graspsim::io
