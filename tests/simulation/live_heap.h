#pragma once
// The bytes a test process holds in live heap blocks: what a leak makes grow. Under
// AddressSanitizer from its allocator (freed blocks wait in its quarantine, which is not counted),
// otherwise from glibc's mallinfo2().

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define GRASPSIM_TEST_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define GRASPSIM_TEST_ASAN 1
#endif

#ifdef GRASPSIM_TEST_ASAN
#include <sanitizer/allocator_interface.h>
#else
#include <malloc.h>
#endif

namespace graspsim::testing {

inline double findLiveHeapBytes() {
#ifdef GRASPSIM_TEST_ASAN
    return static_cast<double>(__sanitizer_get_current_allocated_bytes());
#else
    const struct mallinfo2 info = ::mallinfo2();
    return static_cast<double>(info.uordblks + info.hblkhd);
#endif
}

}  // namespace graspsim::testing
