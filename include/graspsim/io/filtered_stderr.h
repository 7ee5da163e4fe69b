#pragma once
/// @file
/// Keeping a C library's diagnostics off the standard error (file descriptor 2) for a scope.
///
/// Why: Simbody's CPodes prints "[CPODES ERROR] ..." blocks to stderr itself when the
/// integration fails, before the exception that graspsim turns into its one-line message. While
/// a FilteredStderr is alive, fd 2 goes to a scratch file (one per process, emptied when a redirection starts); at the end of the scope everything
/// in it except the blocks that start with one of the given prefixes is written to the real
/// stderr, in order. The dropped text stays available (getDropped()).
///
/// In sanitizer builds (GRASPSIM_SANITIZED) nothing is redirected: a sanitizer report written
/// into the temporary file just before the process aborts would be lost.

#include <string>
#include <vector>

namespace graspsim::io {

/// Redirects fd 2 while alive (see the file comment). fd 2 and the scratch file belong to the
/// whole process, so instances share one redirection: the first to start redirects, the last to
/// end restores, and each forward() passes on what any of them captured (its dropped blocks
/// count as the caller's). So instances may overlap, in one thread or in several (capacity
/// --jobs runs CPodes steppers at once). If the redirection cannot be set up, stderr is left alone.
class FilteredStderr {
public:
    /// @param dropPrefixes a block (text between blank lines) starting with one of these, after
    ///        leading line breaks, is dropped.
    explicit FilteredStderr(std::vector<std::string> dropPrefixes);
    ~FilteredStderr();
    FilteredStderr(const FilteredStderr&) = delete;
    FilteredStderr& operator=(const FilteredStderr&) = delete;

    /// Passes on the kept text written since the last forward, leaving fd 2 redirected: a
    /// long-lived FilteredStderr calls it after each call that may print, at the cost of one
    /// system call when nothing was written.
    void forward();
    /// Restores fd 2 now and passes the kept text on (the destructor does it otherwise).
    void release();
    /// The dropped blocks so far, joined with line breaks.
    const std::string& getDropped() const { return dropped_; }

private:
    std::vector<std::string> dropPrefixes_;
    std::string dropped_;
    bool joined_ = false;  // counted among the shared redirection's users
};

/// The kept part of `text`: its blocks (separated by blank lines) minus those that start with
/// one of `dropPrefixes`; the dropped blocks are appended to `dropped`.
std::string filterBlocks(const std::string& text, const std::vector<std::string>& dropPrefixes, std::string& dropped);

}  // namespace graspsim::io
