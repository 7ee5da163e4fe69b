#pragma once
/// @file
/// The direction of a capacity load as a user writes it: an axis of G (x, y, z, -x, -y, -z) or a
/// vector of three numbers ("0,-1,0" or "0 -1 0"), normalized.

#include "graspsim/simbody.h"

#include <string>
#include <vector>

namespace graspsim::capacity {

/// A named direction in G.
struct LoadDirection {
    std::string name;  ///< the axis name, or the text as given
    SimTK::UnitVec3 direction;
};

/// Parses `text`. @throws graspsim::InputError naming `source`, the value and what is accepted, for
/// anything else, a zero vector or non-finite components.
LoadDirection parseLoadDirection(const std::string& text, const std::string& source);

/// The six axis directions x, -x, y, -y, z, -z.
std::vector<LoadDirection> findAxisDirections();

}  // namespace graspsim::capacity
