#include "graspsim/system/silenced_stdout.h"

#include "graspsim/error.h"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <iostream>

namespace graspsim::system {

SilencedStdout::SilencedStdout() {
    std::cout.flush();
    std::fflush(stdout);
    const int null = ::open("/dev/null", O_WRONLY);
    if (null < 0) throw Error("cannot open /dev/null to silence Simbody's debug output");
    saved_ = ::dup(1);
    if (saved_ < 0 || ::dup2(null, 1) < 0) {
        ::close(null);
        throw Error("cannot redirect standard output to silence Simbody's debug output");
    }
    ::close(null);
    // Formatting the trace, not writing it, is the cost (a matrix of doubles per step): a failed
    // stream makes every insertion a no-op.
    savedState_ = std::cout.rdstate();
    std::cout.setstate(std::ios::badbit);
    // The impulse solver's C printf formats its matrices too. A narrow printf on a wide-oriented
    // stream fails before formatting anything (C11 7.21.2: a stream's orientation is fixed once
    // set). printf reads the `stdout` variable at each call, while std::cout keeps the FILE it was
    // synchronized with at start-up; so swapping the variable reaches printf only.
    wideNull_ = std::fopen("/dev/null", "w");
    if (wideNull_ != nullptr && std::fwide(wideNull_, 1) > 0) {
        savedStdout_ = stdout;
        stdout = wideNull_;
    }
}

SilencedStdout::~SilencedStdout() {
    // What was printed meanwhile sits in the C and C++ buffers: drop it into /dev/null first.
    if (savedStdout_ != nullptr) stdout = savedStdout_;
    if (wideNull_ != nullptr) std::fclose(wideNull_);
    std::cout.clear(savedState_);
    std::cout.flush();
    std::fflush(stdout);
    ::dup2(saved_, 1);
    ::close(saved_);
}

}  // namespace graspsim::system
