#include "graspsim/integration/joint_impedance_jacobian.h"

#include "graspsim/error.h"

#include <algorithm>
#include <string>
#include <utility>

namespace graspsim::integration {

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
        if (j.stop.isEmptyHandle() || forces_.isForceDisabled(s, j.stop.getForceIndex())) continue;
        const double q = mobod.getOneQ(s, 0);
        const double x = std::max(q - j.stop.getUpperBound(s), j.stop.getLowerBound(s) - q);
        if (x <= 0) continue;
        K(i, i) -= j.stop.getStiffness(s);
        D(i, i) -= j.stop.getStiffness(s) * j.stop.getDissipation(s) * x;
    }
}

}  // namespace graspsim::integration
