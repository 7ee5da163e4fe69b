#include "graspsim/integration/joint_impedance_jacobian.h"

#include "graspsim/error.h"

#include <algorithm>
#include <string>
#include <utility>

namespace graspsim::integration {

namespace {

// How far joint j's coordinate is beyond its stop's range (rad or m), <= 0 inside it; NaN for a
// joint without a stop or with its stop disabled.
double findStopViolation(const SimTK::State& s, const SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& mobod,
                         const system::JointImpedance& j) {
    if (j.stop.isEmptyHandle() || forces.isForceDisabled(s, j.stop.getForceIndex())) return SimTK::NaN;
    const double q = mobod.getOneQ(s, 0);
    return std::max(q - j.stop.getUpperBound(s), j.stop.getLowerBound(s) - q);
}

}  // namespace

JointImpedanceJacobian::JointImpedanceJacobian(const SimTK::SimbodyMatterSubsystem& matter,
                                               const SimTK::GeneralForceSubsystem& forces,
                                               std::vector<system::JointImpedance> joints)
    : matter_(matter), forces_(forces), joints_(std::move(joints)) {}

void JointImpedanceJacobian::addForceJacobians(const SimTK::State& s, SimTK::Matrix& D, SimTK::Matrix& K) const {
    for (const system::JointImpedance& j : joints_) {
        const SimTK::MobilizedBody& mobod = matter_.getMobilizedBody(j.mobod);
        if (mobod.getNumU(s) != 1) {
            throw InputError("joint impedance Jacobian: mobilized body " + std::to_string(int(j.mobod)) + " has " +
                             std::to_string(mobod.getNumU(s)) + " mobilities; must have 1");
        }
        const int i = mobod.getFirstUIndex(s);
        K(i, i) -= j.stiffness;
        D(i, i) -= j.damping;
        const double x = findStopViolation(s, forces_, mobod, j);
        if (!(x > 0)) continue;
        K(i, i) -= j.stop.getStiffness(s);
        D(i, i) -= j.stop.getStiffness(s) * j.stop.getDissipation(s) * x;
    }
}

void JointImpedanceJacobian::appendActiveSet(const SimTK::State& s, std::vector<int>& active) const {
    for (const system::JointImpedance& j : joints_) {
        if (findStopViolation(s, forces_, matter_.getMobilizedBody(j.mobod), j) > 0) active.push_back(int(j.mobod));
    }
}

double JointImpedanceJacobian::findTermMargin(const SimTK::State& s, int id) const {
    for (const system::JointImpedance& j : joints_) {
        if (int(j.mobod) == id) return findStopViolation(s, forces_, matter_.getMobilizedBody(j.mobod), j);
    }
    return SimTK::NaN;
}

}  // namespace graspsim::integration
