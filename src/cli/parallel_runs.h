#pragma once
// Independent runs of one command (capacity's directions) on up to `jobs` threads. Each run builds
// its own Simbody System from a shared, read-only scenario, so the runs share nothing mutable.

#include <cstddef>
#include <functional>

namespace graspsim::cli {

// Calls work(k) for k = 0 .. count-1, up to `jobs` (>= 1) at once; with jobs 1 in order on this
// thread. After the first run that throws, no further run starts; once the started runs have
// ended, the exception of the lowest k is rethrown.
void runInParallel(std::size_t count, int jobs, const std::function<void(std::size_t)>& work);

}  // namespace graspsim::cli
