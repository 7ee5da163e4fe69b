#pragma once
/// @file
/// The derivatives of a System's applied generalized forces with respect to the generalized
/// speeds and coordinates, supplied by the force elements that know them analytically: what a
/// linearly implicit stepper (linearly_implicit_stepper.h) needs, without the integration layer
/// knowing any force law.

#include "graspsim/simbody.h"

#include <vector>

namespace graspsim::integration {

/// One force element's share of the force Jacobians, added in place.
///
/// With f the generalized forces (N m or N, one per mobility, nu of them):
///  - D = df/du (N m s/rad ...), the damping Jacobian;
///  - K = df/dq expressed per mobility: the change of f when the coordinates move by
///    q + N(q) dx for a small mobility-space displacement dx (for hinges and sliders dx = dq),
///    so K is nu x nu even where nq != nu (quaternions).
/// Dissipative and restoring forces make D and K negative semi-definite.
class ForceJacobianContributor {
public:
    virtual ~ForceJacobianContributor() = default;
    /// Adds this element's D and K (both nu x nu, already sized, with contiguous column-major
    /// storage, so an element may write through updContiguousScalarData()) at `state`, realized through
    /// Stage::Velocity (Acceleration where the stepper calls it).
    virtual void addForceJacobians(const SimTK::State& state, SimTK::Matrix& D, SimTK::Matrix& K) const = 0;
    /// Appends identifiers of the stiff terms active at `state` (contact points pushing, sticking
    /// friction, limit stops engaged; same realization as addForceJacobians): between two states
    /// with equal lists this element's D and K change smoothly, so a stepper may keep them for a
    /// while; a change in the list is a jump in structure and calls for new ones. A term that is
    /// gone at a step's end (a contact starts sliding or lets go) is a switch the stepper localizes
    /// (its matrix carried the term's stiffness past it); one that appears is not. Identifiers need
    /// only be distinct within this element: a stepper tells elements apart. The default: no such
    /// terms.
    virtual void appendActiveSet(const SimTK::State& state, std::vector<int>& active) const {
        static_cast<void>(state);
        static_cast<void>(active);
    }
    /// How far term `id` (as appendActiveSet() lists it) is from being gone at `state` (same
    /// realization): positive while it is active, at most zero once it is gone, and continuous
    /// along a step, in any unit the element likes (a sticking contact: the transition velocity
    /// less the slip speed, m/s; a stop: its violation, rad or m). A stepper interpolates it
    /// between a step's two ends to estimate where the term was lost. NaN where the element cannot
    /// say (the default): the stepper then bisects.
    virtual double findTermMargin(const SimTK::State& state, int id) const {
        static_cast<void>(state);
        static_cast<void>(id);
        return SimTK::NaN;
    }
};

}  // namespace graspsim::integration
