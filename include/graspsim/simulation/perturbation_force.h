#pragma once
/// @file
/// A constant external force on a body's centre of mass during a time window: the thesis's
/// perturbations f1 and f2.

#include "graspsim/simbody.h"

namespace graspsim::simulation {

/// Applies F_B_G (N, ground frame) at body B's centre of mass for start <= t < start + duration.
/// The force is a step in time: step the integrator to `start` and to `start + duration` exactly
/// (the simulation's output times include both) so no step straddles a jump.
class PerturbationForce {
public:
    PerturbationForce(SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& body,
                      const SimTK::Vec3& F_B_G, double start, double duration);
    // The Simbody force element refers back to this object.
    PerturbationForce(const PerturbationForce&) = delete;
    PerturbationForce& operator=(const PerturbationForce&) = delete;

    /// The force applied at time t (N, ground): F_B_G inside the window, zero outside.
    SimTK::Vec3 findForceAt(double t) const;
    double getStartTime() const { return start_; }
    double getEndTime() const { return start_ + duration_; }

private:
    SimTK::Vec3 F_B_G_;
    double start_;
    double duration_;
};

}  // namespace graspsim::simulation
