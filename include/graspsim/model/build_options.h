#pragma once
/// @file
/// What a user chooses when building an anthropometric body model.

#include "graspsim/anthropometry/subject.h"

#include <string>
#include <vector>

namespace graspsim::model {

/// Which body to build.
enum class BodyKind {
    Arm,      ///< right arm and hand, fixed at the shoulder (27 DOF)
    Humanoid  ///< whole body from every de Leva segment, both arms and hands, pelvis fixed to ground
};

/// Named parameter sets that override the anthropometric defaults.
enum class Preset {
    None,   ///< de Leva masses for the subject
    Thesis  ///< the thesis's model: every finger segment 20 g, palm 250 g, arm total 5.45 kg
};

/// A named point fixed on a segment, added to the model's end-effectors: a goal that is not a
/// fingertip pad (the lateral pinch's side of the index, planning/lateral_pinch.h).
struct SegmentPoint {
    std::string name;            ///< end-effector name, e.g. "index_middle_radial"; not one the builder makes
    std::string body;            ///< the segment's body, e.g. "index_middle"
    double p_B[3] = {0, 0, 0};   ///< the point in the body's frame (m)
};

/// Options of the body model builders. Defaults: the male de Leva reference subject, right arm.
struct BuildOptions {
    anthropometry::Subject subject;  ///< sex, body mass (kg), stature (m)
    BodyKind body = BodyKind::Arm;
    Preset preset = Preset::None;
    double fingerStiffness = 0.25;   ///< passive stiffness of every finger and thumb joint (N m/rad), thesis value
    double fingerDamping = 0.05;     ///< passive damping of every finger and thumb joint (N m s/rad), thesis value
    double armStiffness = 0.0;       ///< passive stiffness of shoulder, elbow, forearm and wrist joints (N m/rad)
    double armDamping = 0.5;         ///< passive damping of shoulder, elbow, forearm and wrist joints (N m s/rad)
    double trunkDamping = 2.0;       ///< humanoid: passive damping of spine, neck and leg joints (N m s/rad)
    std::vector<SegmentPoint> segmentPoints;  ///< end-effectors added after the builder's own (none by default)
};

/// Parses "arm" or "humanoid". @throws graspsim::InputError naming `source`, the value and the accepted values.
BodyKind parseBodyKind(const std::string& text, const std::string& source);
/// Parses "none" or "thesis". @throws graspsim::InputError naming `source`, the value and the accepted values.
Preset parsePreset(const std::string& text, const std::string& source);
std::string toString(BodyKind kind);
std::string toString(Preset preset);

/// Checks the subject and the passive joint parameters.
/// @throws graspsim::InputError naming the offending option.
void validateBuildOptions(const BuildOptions& options);

}  // namespace graspsim::model
