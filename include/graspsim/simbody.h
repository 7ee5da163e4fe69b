#pragma once
/// @file
/// Simbody's headers, seen the way Debian's Simbody 3.7 libraries were built: every graspsim header
/// includes Simbody through this one.
///
/// Debian builds libSimTKcommon without NDEBUG, and SimTK::State's implementation
/// (SimTKcommon/internal/StateImpl.h, which State.h includes inline) has members that exist only
/// without NDEBUG. Code compiled with NDEBUG (any Release build) that includes Simbody's headers
/// disagrees with the library on the layout of those classes (graspsim crashed in
/// realizeTopology()). This header includes Simbody with NDEBUG undefined and gives the includer
/// back its own NDEBUG and assert() afterwards, so a program using graspsim needs no special
/// compile flags. A program that also includes Simbody's headers itself should include this
/// header first, or instead.

#pragma push_macro("NDEBUG")
#undef NDEBUG
#include <simbody/Simbody.h>
#pragma pop_macro("NDEBUG")
#include <cassert>  // no include guard by design: assert() follows the includer's NDEBUG again
