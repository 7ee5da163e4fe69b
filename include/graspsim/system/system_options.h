#pragma once
/// @file
/// Options for turning a model description into a Simbody system.

#include "graspsim/simbody.h"

namespace graspsim::system {

/// How the description is turned into a Simbody system.
struct SystemOptions {
    /// Gravity acceleration, in Ground (m/s^2). Ground's y axis is up.
    SimTK::Vec3 gravity{0, -9.81, 0};

    /// Stiffness k of the joint-limit stops (N m/rad for revolute joints, N/m for prismatic).
    /// Past a limit the stop pushes back with k times the violation.
    ///
    /// The default, 50 N m/rad, keeps a finger joint within about half a degree of its limit
    /// under the finger's own passive loads: a 0.25 N m/rad joint spring stretched over a
    /// 1.6 rad range plus gravity on a 60 g finger give at most about 0.45 N m -> 0.009 rad.
    /// Heavy proximal joints pressed on a limit by gravity sink further (a 5.45 kg arm at
    /// 0.3 m, about 16 N m, sinks 0.32 rad = 18 degrees); raise k if they must rest on a limit.
    /// A stiffer stop shortens the system's fastest oscillation: the anthropometric hand's
    /// distal phalanx (effective inertia about 1.3e-7 kg m^2) rings against a 50 N m/rad stop
    /// with a 0.3 ms period. That is not what limits explicit step sizes there: its
    /// 0.05 N m s/rad joint damper has a 3 microsecond time constant (I / c).
    double stopStiffness = 50;

    /// Dissipation coefficient d of the stops (s/rad, i.e. per rad/s; s/m for prismatic).
    /// Simbody's stop force is -k x (1 + d qdot) for a violation x of the upper limit (mirrored
    /// at the lower one), clamped so that it never pulls: Hunt-Crossley-like, with no damping
    /// force at first touch. Its coefficient of restitution depends on the impact speed only
    /// (not on k or inertia); with d = 1 s/rad it is 0.83 at 0.3 rad/s, 0.59 at 1 rad/s, 0.31 at
    /// 3 rad/s and 0.10 at 10 rad/s, so fast swings settle on their limits without bouncing.
    double stopDissipation = 1.0;

    /// Whether Revolute and Prismatic joints get limit stops.
    bool enforceLimits = true;
};

}  // namespace graspsim::system
