#pragma once
// The link/joint graph of a URDF <robot>, checked before urdfdom sees it. urdfdom reports some of
// these mistakes only on the console and misses others (a link with two parents, a cycle that
// does not contain the root), so we check them all here, each with its line number.

#include "urdf_source.h"

class TiXmlElement;

namespace graspsim::model {

/// The joint types graspsim accepts, as the message text of a rejected type.
inline constexpr const char* kAcceptedJointTypes = "accepted: revolute, continuous, prismatic, fixed";

/// Checks that every <link> and <joint> has a unique name, every joint type is one graspsim
/// accepts, every joint's parent and child name a defined link (and differ), each link is the
/// child of at most one joint, there is no cycle and exactly one link has no parent.
/// @throws graspsim::InputError naming the source, line, field and value.
void checkUrdfTree(const TiXmlElement& robot, const UrdfSource& source);

}  // namespace graspsim::model
