#pragma once
/// @file
/// The Simbody system built from a model description: one `MultibodySystem` with its matter
/// and force subsystems, gravity, and the passive joint forces (springs, dampers, limit stops).
///
/// Mapping from the description (frames in monogram notation; P parent, J joint, B child body):
///  - the root body is welded to Ground G at `X_GR`;
///  - Revolute and Continuous joints become `MobilizedBody::Pin`, Prismatic joints
///    `MobilizedBody::Slider`, Fixed joints `MobilizedBody::Weld`. The pin rotates about, and the
///    slider translates along, the joint axis; at q = 0 the child frame B coincides with J, so
///    `X_PB(q) = X_PJ * X_JB(q)` where X_JB(q) is a rotation by q about (or a translation by q
///    along) the axis;
///  - each joint gets `Force::MobilityLinearSpring` (stiffness > 0), `Force::MobilityLinearDamper`
///    (damping > 0) and, for Revolute and Prismatic joints when limits are enforced,
///    `Force::MobilityLinearStop` at [lower, upper];
///  - `Force::Gravity` acts on every body; its potential energy is zero at Ground's origin.
///
/// Massless virtual bodies (multi-DOF joint chains) become `Body::Massless`. Simbody accepts them
/// as long as every movable joint has mass outboard of it (checked at construction) and a chain's
/// axes are not aligned: a 3-pin shoulder chain has a singular mass matrix at gimbal lock (middle
/// angle +-90 degrees for z-x-y axes), like any Euler-angle joint. Simbody does not throw there:
/// accelerations come out NaN at the lock and enormous (1e11 rad/s^2) within 1e-9 rad of it.

#include "graspsim/simbody.h"

#include <map>
#include <string>
#include <vector>

#include "graspsim/model/model_description.h"
#include "graspsim/system/passive_joint_forces.h"
#include "graspsim/system/system_options.h"

namespace graspsim::system {

/// A Simbody `MultibodySystem` built from a `model::ModelDescription`, with lookups by the
/// description's body, joint and end-effector names.
///
/// Later layers add their own elements through `updMatter()` and `updForces()` and then call
/// `realizeTopology()` again. The object is neither copyable nor movable because Simbody's
/// subsystems keep references to the system.
///
/// Errors: unknown names throw `graspsim::InputError`; Simbody failures are rethrown as
/// `graspsim::Error` naming the model and the body or joint concerned.
class MultibodyModel {
public:
    /// Builds the system and realizes its topology.
    /// @throws graspsim::InputError if the description is invalid (see
    ///         ModelDescription::validate), a rotation is not proper, or a movable joint moves
    ///         only massless bodies.
    /// @throws graspsim::Error if Simbody rejects a body or joint.
    explicit MultibodyModel(const model::ModelDescription& description,
                            const SystemOptions& options = {});

    MultibodyModel(const MultibodyModel&) = delete;
    MultibodyModel& operator=(const MultibodyModel&) = delete;
    MultibodyModel(MultibodyModel&&) = delete;
    MultibodyModel& operator=(MultibodyModel&&) = delete;
    ~MultibodyModel();

    const SimTK::MultibodySystem& getSystem() const { return system_; }
    SimTK::MultibodySystem& updSystem() { return system_; }
    const SimTK::SimbodyMatterSubsystem& getMatter() const { return matter_; }
    SimTK::SimbodyMatterSubsystem& updMatter() { return matter_; }
    const SimTK::GeneralForceSubsystem& getForces() const { return forces_; }
    SimTK::GeneralForceSubsystem& updForces() { return forces_; }
    /// The gravity element (its vector can be changed per state with setGravityVector()).
    const SimTK::Force::Gravity& getGravity() const { return gravity_; }
    const model::ModelDescription& getDescription() const { return description_; }
    const SystemOptions& getOptions() const { return options_; }

    /// Realizes the system's topology (again, after others added elements) and returns its
    /// default state: every joint at q = 0, at rest, time 0, stop bounds and spring rest
    /// angles from the description.
    /// @throws graspsim::Error if Simbody rejects the system.
    const SimTK::State& realizeTopology();

    /// The mobilized body that carries body `bodyName` (welded bodies included).
    /// @throws graspsim::InputError if there is no such body.
    const SimTK::MobilizedBody& getMobilizedBody(const std::string& bodyName) const;

    /// Degrees of freedom of the description's joints (bodies others add are not counted).
    int getDofCount() const { return static_cast<int>(movableJoints_.size()); }

    /// Names of the movable (non-Fixed) joints, in the order of their q in the state.
    std::vector<std::string> getJointNames() const;

    /// Index of joint `jointName`'s coordinate q in the state's q vector.
    /// @throws graspsim::InputError if there is no such movable joint.
    SimTK::QIndex getJointQIndex(const std::string& jointName) const;
    /// Index of joint `jointName`'s speed u (= qdot) in the state's u vector.
    /// @throws graspsim::InputError if there is no such movable joint.
    SimTK::UIndex getJointUIndex(const std::string& jointName) const;

    /// Joint coordinate q (rad, or m for prismatic joints). Needs no realization.
    double getJointPosition(const SimTK::State& state, const std::string& jointName) const;
    /// Sets joint coordinate q (rad or m); invalidates Stage::Position and later.
    void setJointPosition(SimTK::State& state, const std::string& jointName, double value) const;
    /// Joint speed u = qdot (rad/s or m/s). Needs no realization.
    double getJointSpeed(const SimTK::State& state, const std::string& jointName) const;
    /// Sets joint speed u (rad/s or m/s); invalidates Stage::Velocity and later.
    void setJointSpeed(SimTK::State& state, const std::string& jointName, double value) const;

    /// Location of end-effector point E in Ground, p_GE (m). The state must be realized to
    /// Stage::Position.
    /// @throws graspsim::InputError if there is no such end-effector.
    SimTK::Vec3 findEndEffectorLocationInGround(const SimTK::State& state,
                                                const std::string& endEffectorName) const;

    /// Mechanical energy (J): kinetic energy plus the potential energy of gravity, the joint
    /// springs and the limit stops (and of any conservative force others added). The state
    /// must be realized to Stage::Dynamics.
    double calcMechanicalEnergy(const SimTK::State& state) const;

    /// Power (W, >= 0) that the passive joint forces take out of the system at this state:
    /// the dampers' c u^2 plus the stops' dissipation. With no other non-conservative forces,
    /// dE/dt = -calcPassiveDissipationPower(state) for E = calcMechanicalEnergy(state).
    /// The state must be realized to Stage::Velocity.
    double calcPassiveDissipationPower(const SimTK::State& state) const;

    /// The spring, damper and stop of movable joint `jointName`.
    /// @throws graspsim::InputError if there is no such movable joint.
    const PassiveJointForces& getPassiveJointForces(const std::string& jointName) const;

private:
    /// What the model keeps per movable joint. The indices are valid once the topology has
    /// been realized.
    struct JointEntry {
        SimTK::MobilizedBodyIndex mobodIndex;
        SimTK::QIndex qIndex;
        SimTK::UIndex uIndex;
        PassiveJointForces passive;
    };

    void addBodies();
    void addBody(const model::Joint& joint);
    void cacheStateIndices(const SimTK::State& defaultState);
    const JointEntry& getJointEntry(const std::string& jointName) const;
    /// "model '<name>': <what>", the context every message starts with.
    std::string describe(const std::string& what) const;

    model::ModelDescription description_;
    SystemOptions options_;
    SimTK::MultibodySystem system_;
    SimTK::SimbodyMatterSubsystem matter_;
    SimTK::GeneralForceSubsystem forces_;
    SimTK::Force::Gravity gravity_;

    std::map<std::string, SimTK::MobilizedBodyIndex> bodyIndexByName_;
    std::map<std::string, JointEntry> movableJoints_;
    std::vector<std::string> jointNamesInQOrder_;
};

}  // namespace graspsim::system
