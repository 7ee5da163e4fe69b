#pragma once
/// @file
/// Silencing the standard output (file descriptor 1) for a scope.
///
/// Why: Debian's Simbody 3.7 is built without NDEBUG, so SemiExplicitEulerTimeStepper and its
/// impulse solvers print a debug trace to stdout at every step (about 10 kB per step with
/// contacts). graspsim writes its results to files and its progress to stderr, so the rigid
/// stepping runs with fd 1 pointed at /dev/null. This is the one place that does it.

#include <cstdio>
#include <ios>

namespace graspsim::system {

/// Points fd 1 at /dev/null, puts std::cout in a failed state and points C's `stdout` at a
/// wide-oriented /dev/null stream while alive (after flushing stdout and std::cout), and restores
/// all three.
/// Not thread-safe: fd 1 and `stdout` are shared by the whole process. Nesting is allowed.
class SilencedStdout {
public:
    /// @throws graspsim::Error if /dev/null cannot be opened or fd 1 cannot be duplicated.
    SilencedStdout();
    ~SilencedStdout();
    SilencedStdout(const SilencedStdout&) = delete;
    SilencedStdout& operator=(const SilencedStdout&) = delete;

private:
    int saved_ = -1;  // duplicate of the original fd 1
    std::ios::iostate savedState_ = std::ios::goodbit;  // std::cout's state before
    std::FILE* savedStdout_ = nullptr;  // C's stdout before
    std::FILE* wideNull_ = nullptr;  // /dev/null, wide-oriented: narrow printf returns at once
};

}  // namespace graspsim::system
