#pragma once
/// @file
/// The grasp types graspsim plans, named after the GRASP taxonomy of
/// T. Feix, J. Romero, H.-B. Schmiedmayer, A. M. Dollar and D. Kragic (2016), "The GRASP
/// Taxonomy of Human Grasp Types", IEEE Transactions on Human-Machine Systems 46(1):66-77,
/// doi:10.1109/THMS.2015.2470657.

#include <string>
#include <vector>

namespace graspsim::planning {

/// A grasp type of Feix et al. (2016). The scenario spelling is given with each.
enum class GraspType {
    PowerSphere,    ///< "power-sphere": Feix 'power sphere', five fingers round a ball, thumb opposing
    Pinch,          ///< "pinch": Feix 'palmar pinch', thumb pad against the index pad
    Tripod,         ///< "tripod": Feix 'tripod', thumb pad against the index and middle pads
    PowerCylinder,  ///< "power-cylinder": Feix 'medium wrap', fingers round a cylinder, thumb opposing
    Lateral         ///< "lateral": Feix 'lateral pinch', thumb pad on the radial side of the index
};

/// The scenario spelling ("power-sphere", "pinch", "tripod", "power-cylinder", "lateral").
std::string toString(GraspType type);

/// The grasp type spelled `text`.
/// @param what names the value in the message (e.g. "--type" or "my.yaml: field 'grasp.type'").
/// @throws graspsim::InputError naming `what`, the value and the accepted spellings.
GraspType parseGraspType(const std::string& text, const std::string& what);

/// Every grasp type, in enum order.
std::vector<GraspType> getGraspTypes();

}  // namespace graspsim::planning
