#include "graspsim/contact/contact_force_law.h"

#include <algorithm>
#include <cmath>

namespace graspsim::contact {

double calcHertzForce(const ContactParameters& parameters, double radius, double depth) {
    return (4.0 / 3.0) * parameters.effectiveStiffness * std::sqrt(radius) * depth *
           std::sqrt(depth);
}

double calcHertzEnergy(const ContactParameters& parameters, double radius, double depth) {
    return 0.4 * calcHertzForce(parameters, radius, depth) * depth;  // (2/5) f_H x
}

double calcNormalForce(const ContactParameters& parameters, double radius, double depth,
                       double depthRate) {
    const double force =
        calcHertzForce(parameters, radius, depth) * (1 + 1.5 * parameters.dissipation * depthRate);
    return force > 0 ? force : 0;
}

double calcFrictionCoefficient(const ContactParameters& parameters, double slipSpeed) {
    const double ratio = slipSpeed / parameters.transitionVelocity;
    return std::min(ratio, 1.0) * (parameters.dynamicFriction +
                                   2 * (parameters.staticFriction - parameters.dynamicFriction) /
                                       (1 + ratio * ratio)) +
           parameters.viscousFriction * slipSpeed;
}

SimTK::Vec3 calcFrictionForce(const ContactParameters& parameters, double normalForce,
                              const SimTK::Vec3& slipVelocity) {
    const double slipSpeed = slipVelocity.norm();
    if (slipSpeed == 0 || normalForce == 0) return SimTK::Vec3(0);
    return (-calcFrictionCoefficient(parameters, slipSpeed) * normalForce / slipSpeed) *
           slipVelocity;
}

}  // namespace graspsim::contact
