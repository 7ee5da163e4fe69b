#include "graspsim/planning/grasp_type.h"

#include "graspsim/error.h"

namespace graspsim::planning {

std::string toString(GraspType type) {
    switch (type) {
        case GraspType::PowerSphere: return "power-sphere";
        case GraspType::Pinch: return "pinch";
        case GraspType::Tripod: return "tripod";
        case GraspType::PowerCylinder: return "power-cylinder";
        case GraspType::Lateral: return "lateral";
    }
    return "unknown";
}

std::vector<GraspType> getGraspTypes() {
    return {GraspType::PowerSphere, GraspType::Pinch, GraspType::Tripod, GraspType::PowerCylinder,
            GraspType::Lateral};
}

GraspType parseGraspType(const std::string& text, const std::string& what) {
    std::string accepted;
    for (GraspType type : getGraspTypes()) {
        if (toString(type) == text) return type;
        accepted += (accepted.empty() ? "" : " | ") + toString(type);
    }
    throw InputError(what + " value '" + text + "' is not a grasp type; accepted: " + accepted);
}

}  // namespace graspsim::planning
