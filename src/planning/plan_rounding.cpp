#include "graspsim/planning/plan_rounding.h"

#include "graspsim/anthropometry/units.h"

#include <cmath>

namespace graspsim::planning {

namespace {

// Steps and their counts per unit. The count of steps is value / step (as the planner's search
// counts them); the result is count / (steps per unit), both exact constants.
constexpr double kTenthMillimetre = 1e-4;  // m
constexpr double kTenthsPerMetre = 1e4;
constexpr double kTenthDegree = 0.1;       // deg
constexpr double kTenthsPerDegree = 10;

void snapVec3(SimTK::Vec3& p) {
    for (int i = 0; i < 3; ++i) p[i] = roundToTenthMillimetre(p[i]);
}

}  // namespace

double fromTenthMillimetres(double count) { return count / kTenthsPerMetre; }

double roundToTenthMillimetre(double metres) { return fromTenthMillimetres(std::round(metres / kTenthMillimetre)); }

double roundToTenthDegree(double radians) {
    const double degrees = radians / anthropometry::fromDegrees(1.0);
    return anthropometry::fromDegrees(std::round(degrees / kTenthDegree) / kTenthsPerDegree);
}

SimTK::Vec3 findRoundedOrientation(const SimTK::Rotation& R_GO) {
    const SimTK::Vec3 xyz = R_GO.convertRotationToBodyFixedXYZ();
    return {roundToTenthDegree(xyz[0]), roundToTenthDegree(xyz[1]), roundToTenthDegree(xyz[2])};
}

void snapToWrittenDecimals(GraspPlan& plan) {
    for (auto& [joint, angle] : plan.jointAngles) angle = roundToTenthDegree(angle);
    const SimTK::Vec3 xyz = findRoundedOrientation(plan.X_GO.R());
    SimTK::Vec3 p_GO = plan.X_GO.p();
    snapVec3(p_GO);
    plan.X_GO = SimTK::Transform(
        SimTK::Rotation(SimTK::BodyRotationSequence, xyz[0], SimTK::XAxis, xyz[1], SimTK::YAxis, xyz[2], SimTK::ZAxis), p_GO);
    for (auto& [effector, p_OP] : plan.goals) snapVec3(p_OP);
    for (model::SegmentPoint& point : plan.segmentPoints) {
        for (double& x : point.p_B) x = roundToTenthMillimetre(x);
    }
}

}  // namespace graspsim::planning
