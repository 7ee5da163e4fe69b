#include "graspsim/capacity/grasp_capacity.h"

#include "graspsim/error.h"
#include "graspsim/scenario/scenario_file.h"

#include <gtest/gtest.h>

#include <cmath>

namespace graspsim::capacity {
namespace {

// The line through the pinch's two goals, in G, from the scenario's own goals and initial pose.
SimTK::Vec3 findPinchLine(const scenario::Scenario& s) {
    const model::Transform X_GO = s.object.findPose();
    const model::Vec3 a = X_GO.xformFrameVecToBase(s.goals.at("thumb_tip"));
    const model::Vec3 b = X_GO.xformFrameVecToBase(s.goals.at("index_tip"));
    return SimTK::Vec3(b[0] - a[0], b[1] - a[1], b[2] - a[2]).normalize();
}

GraspCapacityRequest makeTorque(const SimTK::Vec3& axis) {
    GraspCapacityRequest request;
    request.torque = true;
    request.direction = SimTK::UnitVec3(axis);
    request.directionName = "v";
    return request;
}

TEST(GraspCapacity, TorqueAboutThePinchLineIsRefusedAcrossItIsMeasured) {
    const scenario::Scenario pinch = scenario::findBuiltinScenario("phone-pinch");
    const SimTK::Vec3 line = findPinchLine(pinch);
    EXPECT_THROW(checkLoadResistible(pinch, makeTorque(line)), InputError);
    EXPECT_THROW(checkLoadResistible(pinch, makeTorque(-line)), InputError);
    // 4 deg off the line: still refused; 6 deg: measured.
    const SimTK::Vec3 across = SimTK::UnitVec3(SimTK::UnitVec3(line).perp());
    const auto tilted = [&](double degrees) {
        const double a = degrees * SimTK::Pi / 180;
        return std::cos(a) * line + std::sin(a) * across;
    };
    EXPECT_THROW(checkLoadResistible(pinch, makeTorque(tilted(4))), InputError);
    EXPECT_NO_THROW(checkLoadResistible(pinch, makeTorque(tilted(6))));
    // A force along the line, and any torque on the five-finger ball clutch, are fine.
    GraspCapacityRequest force = makeTorque(line);
    force.torque = false;
    EXPECT_NO_THROW(checkLoadResistible(pinch, force));
    EXPECT_NO_THROW(checkLoadResistible(scenario::findBuiltinScenario("ball-clutch"), makeTorque(SimTK::Vec3(0, 0, 1))));
}

}  // namespace
}  // namespace graspsim::capacity
