#pragma once
/// @file
/// The passive force elements acting at one joint: spring, damper and limit stop.

#include "graspsim/simbody.h"

#include "graspsim/model/model_description.h"
#include "graspsim/system/system_options.h"

namespace graspsim::system {

/// The passive forces of one 1-DOF joint, as Simbody force elements on its mobilizer's only
/// coordinate q and speed u (for which qdot = u):
///  - spring  `Force::MobilityLinearSpring`: tau = -k (q - q0), stored energy k (q - q0)^2 / 2;
///  - damper  `Force::MobilityLinearDamper`: tau = -c u, dissipating c u^2;
///  - stop    `Force::MobilityLinearStop` on [lower, upper], see SystemOptions.
/// tau is a generalized force (N m for revolute joints, N for prismatic joints).
/// Elements with zero coefficient are not created.
class PassiveJointForces {
public:
    /// No elements.
    PassiveJointForces() = default;

    /// Adds the joint's elements to `forces`, acting on `mobod`'s coordinate. Spring when
    /// joint.stiffness > 0, damper when joint.damping > 0, stop when joint.hasLimits() and
    /// options.enforceLimits.
    PassiveJointForces(SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& mobod,
                       const model::Joint& joint, const SystemOptions& options);

    bool hasSpring() const { return !spring_.isEmptyHandle(); }
    bool hasDamper() const { return !damper_.isEmptyHandle(); }
    bool hasStop() const { return !stop_.isEmptyHandle(); }
    /// The stop element; an empty handle when hasStop() is false.
    const SimTK::Force::MobilityLinearStop& getStop() const { return stop_; }

    /// Generalized force of spring + damper + stop on the joint (N m or N). The state must be
    /// realized to Stage::Velocity.
    double calcGeneralizedForce(const SimTK::State& state) const;

    /// Energy stored in the spring and the stop (J). The state must be realized to
    /// Stage::Position.
    double calcPotentialEnergy(const SimTK::State& state) const;

    /// Power (W, >= 0) the damper and the stop take out of the system: c u^2 plus the part of
    /// the stop's force that is not the elastic -k x. The state must be realized to
    /// Stage::Velocity.
    double calcDissipationPower(const SimTK::State& state) const;

private:
    double getQ(const SimTK::State& state) const;
    double getU(const SimTK::State& state) const;
    double calcStopForce(const SimTK::State& state) const;
    double calcStopElasticForce(const SimTK::State& state) const;

    SimTK::MobilizedBody mobod_;
    SimTK::Force::MobilityLinearSpring spring_;
    SimTK::Force::MobilityLinearDamper damper_;
    SimTK::Force::MobilityLinearStop stop_;
};

}  // namespace graspsim::system
