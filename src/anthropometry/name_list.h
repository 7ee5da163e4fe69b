#pragma once
// Formats the accepted names that an InputError lists ("a, b, c"), so that every
// "unknown name" message in the anthropometry layer reads the same.

#include <string>
#include <vector>

namespace graspsim::anthropometry {

std::string joinNames(const std::vector<std::string>& names);

}  // namespace graspsim::anthropometry
