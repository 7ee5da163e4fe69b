#include "graspsim/planning/grasp_template.h"

#include "graspsim/planning/lateral_pinch.h"

#include "graspsim/simbody.h"

namespace graspsim::planning {

namespace {

using Degrees = std::map<std::string, double>;

std::map<std::string, double> toRadians(const Degrees& degrees) {
    std::map<std::string, double> radians;
    for (const auto& [joint, angle] : degrees) radians[joint] = angle * SimTK::Pi / 180;
    return radians;
}

// models/scenarios/ball-clutch.yaml, found by hand for the thesis's ball (section 5.1.1).
const Degrees kBallClutch{
    {"shoulder_flexion", 30}, {"elbow_flexion", 90}, {"forearm_pronation", 75}, {"wrist_flexion", 30},
    {"index_mcp_abduction", 18}, {"index_mcp_flexion", 48}, {"index_pip_flexion", 32}, {"index_dip_flexion", 25},
    {"middle_mcp_abduction", -3}, {"middle_mcp_flexion", 29}, {"middle_pip_flexion", 42}, {"middle_dip_flexion", 28},
    {"ring_mcp_abduction", -1}, {"ring_mcp_flexion", 24}, {"ring_pip_flexion", 37}, {"ring_dip_flexion", 27},
    {"little_mcp_abduction", 18}, {"little_mcp_flexion", 40}, {"little_pip_flexion", 19}, {"little_dip_flexion", 7},
    {"thumb_cmc_abduction", 68}, {"thumb_cmc_flexion", -18}, {"thumb_mcp_flexion", 2}, {"thumb_ip_flexion", 65}};

// models/scenarios/phone-pinch.yaml, found by hand for the thesis's phone (section 5.1.2).
const Degrees kPhonePinch{
    {"shoulder_flexion", 30}, {"elbow_flexion", 90}, {"wrist_deviation", -25},
    {"index_mcp_abduction", -8}, {"index_mcp_flexion", 59}, {"index_pip_flexion", 21}, {"index_dip_flexion", 12},
    {"middle_mcp_flexion", 60}, {"middle_pip_flexion", 70}, {"middle_dip_flexion", 45},
    {"ring_mcp_flexion", 60}, {"ring_pip_flexion", 70}, {"ring_dip_flexion", 45},
    {"little_mcp_flexion", 60}, {"little_pip_flexion", 70}, {"little_dip_flexion", 45},
    {"thumb_cmc_abduction", 41}, {"thumb_cmc_flexion", -12}, {"thumb_mcp_flexion", 2}, {"thumb_ip_flexion", -18}};

}  // namespace

bool isFingerJoint(const std::string& joint) {
    for (const char* digit : {"thumb_", "index_", "middle_", "ring_", "little_"}) {
        if (joint.rfind(digit, 0) == 0) return true;
    }
    return false;
}

GraspTemplate findGraspTemplate(GraspType type) {
    GraspTemplate t;
    switch (type) {
        case GraspType::PowerSphere:
        case GraspType::PowerCylinder:
            t.startPose = toRadians(kBallClutch);
            t.goalEffectors = {"thumb_tip", "index_tip", "middle_tip", "ring_tip", "little_tip"};
            t.kp = 10;  // as ball-clutch.yaml: five fingers hold a 9.5 N pull
            t.startUnderPalm = true;
            // A wrap carries the object on the fingers (docs/planning.md): squeezed level
            // between thumb and fingertips, a 200 g cylinder hung on friction alone, the thumb's
            // friction at its cone's edge, and slid out.
            if (type == GraspType::PowerCylinder) {
                t.minSupport = 0.3;
                // Fingers side by side along the cylinder, as in a wrap, not spread as round the
                // ball: spread, a 1.90 m man's index and little pads reached past the ends of a
                // 120 mm cylinder onto its rims, where they cannot press.
                for (const char* finger : {"index", "middle", "ring", "little"}) {
                    t.startPose[std::string(finger) + "_mcp_abduction"] = 0;
                }
            }
            break;
        case GraspType::Lateral: return findLateralTemplate();
        case GraspType::Pinch:
            t.startPose = toRadians(kPhonePinch);
            t.goalEffectors = {"thumb_tip", "index_tip"};
            break;
        case GraspType::Tripod: {
            Degrees tripod = kPhonePinch;  // the middle finger joins the index
            tripod["middle_mcp_flexion"] = 59;
            tripod["middle_pip_flexion"] = 21;
            tripod["middle_dip_flexion"] = 12;
            tripod["middle_mcp_abduction"] = -8;
            t.startPose = toRadians(tripod);
            t.goalEffectors = {"thumb_tip", "index_tip", "middle_tip"};
            // At 5 (the pinch's gain) the index and middle pads stop short of their goals on a
            // small ball (0.05 N at the index) and the thumb alone pushes it out when released.
            t.kp = 10;
            break;
        }
    }
    return t;
}

}  // namespace graspsim::planning
