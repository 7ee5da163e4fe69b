#include "graspsim/system/passive_joint_forces.h"

#include <cmath>

namespace graspsim::system {

using SimTK::Force;

PassiveJointForces::PassiveJointForces(SimTK::GeneralForceSubsystem& forces,
                                       const SimTK::MobilizedBody& mobod, const model::Joint& joint,
                                       const SystemOptions& options)
    : mobod_(mobod) {
    // Every joint here is a Pin or a Slider: one q, one u, and qdot = u, which is what
    // MobilityLinearStop requires (it is wrong for quaternion mobilizers).
    const SimTK::MobilizerQIndex q0(0);
    const SimTK::MobilizerUIndex u0(0);
    if (joint.stiffness > 0) {
        spring_ = Force::MobilityLinearSpring(forces, mobod, q0, joint.stiffness, joint.restAngle);
    }
    if (joint.damping > 0) {
        damper_ = Force::MobilityLinearDamper(forces, mobod, u0, joint.damping);
    }
    if (joint.hasLimits() && options.enforceLimits) {
        stop_ = Force::MobilityLinearStop(forces, mobod, q0, options.stopStiffness,
                                          options.stopDissipation, joint.lower, joint.upper);
    }
}

double PassiveJointForces::getQ(const SimTK::State& state) const {
    return mobod_.getOneQ(state, SimTK::MobilizerQIndex(0));
}

double PassiveJointForces::getU(const SimTK::State& state) const {
    return mobod_.getOneU(state, SimTK::MobilizerUIndex(0));
}

double PassiveJointForces::calcStopForce(const SimTK::State& state) const {
    // Ask Simbody for the stop's own force rather than re-deriving its clamped
    // Hunt-Crossley law, so the dissipation below can never drift from what is integrated.
    SimTK::Vector_<SimTK::SpatialVec> bodyForces;
    SimTK::Vector_<SimTK::Vec3> particleForces;
    SimTK::Vector mobilityForces;
    stop_.calcForceContribution(state, bodyForces, particleForces, mobilityForces);
    return mobilityForces[mobod_.getFirstUIndex(state)];
}

double PassiveJointForces::calcStopElasticForce(const SimTK::State& state) const {
    // The conservative part -k x of the stop, whose energy k x^2 / 2 Simbody reports.
    const double q = getQ(state);
    const double k = stop_.getStiffness(state);
    if (q > stop_.getUpperBound(state)) return -k * (q - stop_.getUpperBound(state));
    if (q < stop_.getLowerBound(state)) return -k * (q - stop_.getLowerBound(state));
    return 0;
}

double PassiveJointForces::calcGeneralizedForce(const SimTK::State& state) const {
    double tau = 0;
    if (hasSpring()) tau -= spring_.getStiffness(state) * (getQ(state) - spring_.getQZero(state));
    if (hasDamper()) tau -= damper_.getDamping(state) * getU(state);
    if (hasStop()) tau += calcStopForce(state);
    return tau;
}

double PassiveJointForces::calcPotentialEnergy(const SimTK::State& state) const {
    double energy = 0;
    if (hasSpring()) energy += spring_.calcPotentialEnergyContribution(state);
    if (hasStop()) energy += stop_.calcPotentialEnergyContribution(state);
    return energy;
}

double PassiveJointForces::calcDissipationPower(const SimTK::State& state) const {
    const double u = getU(state);
    double power = 0;
    if (hasDamper()) power += damper_.getDamping(state) * u * u;
    if (hasStop()) {
        // Power of the stop's non-elastic part, (f - f_elastic) u, is what leaves the system.
        power -= (calcStopForce(state) - calcStopElasticForce(state)) * u;
    }
    return power;
}

}  // namespace graspsim::system
