#pragma once
/// @file
/// Independent runs on up to `jobs` threads: capacity --jobs (its directions) and validate --jobs
/// (its capacity ramps). Each run builds its own Simbody System from shared, read-only inputs, so
/// the runs share nothing mutable; fd 2's filtering is shared safely (filtered_stderr.h).

#include <cstddef>
#include <functional>

namespace graspsim::io {

/// Calls work(k) for k = 0 .. count-1, up to `jobs` (values below 1 count as 1) at once; with one
/// job in order on the calling thread. After the first run that throws no further run starts; once
/// the started runs have ended, the exception of the lowest k is rethrown.
void runInParallel(std::size_t count, int jobs, const std::function<void(std::size_t)>& work);

}  // namespace graspsim::io
