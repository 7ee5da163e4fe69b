#pragma once
/// @file
/// The rigid model's impulse solver: projected Gauss-Seidel (PGS) for the contact, impact and
/// position-projection subproblems of Simbody's SemiExplicitEulerTimeStepper, the same method
/// as Simbody 3.7's SimTK::PGSImpulseSolver, step for step.
///
/// Why not Simbody's own: Debian's Simbody 3.7 is built without NDEBUG, and its PGS solver
/// factors A (QTZ) and prints A, the right-hand side and the iterate at every solve and every
/// iteration, with assertion checks that build matrix views in every row update. That debug
/// work, not the iteration, was over a third of a rigid step (docs/performance.md). This class
/// performs the same floating-point operations in the same order (SOR factor 1.2, relaxed by
/// 0.8 down to 0.1 whenever the enforced error grows, convergence tolerance 1e-6 RMS over the
/// participating rows, at most 100 sweeps, the same defaults), so its impulses are bitwise
/// Simbody's; rigid_impulse_solver_test.cpp checks that on random problems.
///
/// What it solves, per sweep: every participating unilateral normal row (Gauss-Seidel, clamped
/// to push only: sign * pi <= 0), then each contact's two friction rows as a block (both rows'
/// residuals from the same iterate), scaled back into the cone |pi_t| <= mu |pi_n + piExpand_n|.
/// Units are the stepper's: impulses (N s) and constraint-space velocities (m/s).
///
/// Scope: Simbody 3.7's stepper only ever passes unilateral contacts (its unconditional,
/// unilateral-speed, bounded and friction-limit lists are always empty); given any of those,
/// solve() throws rather than ignore them.
#include "graspsim/simbody.h"

namespace graspsim::contact {

/// PGS impulse solver for SimTK::SemiExplicitEulerTimeStepper::setImpulseSolver() (which takes
/// ownership). A must be a packed, column-ordered m x m matrix (the stepper's G M^-1 G^T is).
class RigidImpulseSolver : public SimTK::ImpulseSolver {
public:
    /// @param rollToSlipSpeed friction transition speed (m/s); the stepper resets it in
    ///        SemiExplicitEulerTimeStepper::initialize(). PGS does not use it.
    explicit RigidImpulseSolver(double rollToSlipSpeed = 0);

    /// Unilateral contacts with friction: see the file comment. Returns whether the RMS error
    /// of the enforced rows fell below the convergence tolerance.
    /// @throws graspsim::NumericalError if A is not packed in column order or any constraint
    ///         list other than uniContact is non-empty.
    bool solve(int phase, const SimTK::Array_<SimTK::MultiplierIndex>& participating,
               const SimTK::Matrix& A, const SimTK::Vector& D,
               const SimTK::Array_<SimTK::MultiplierIndex>& expanding, SimTK::Vector& piExpand,
               SimTK::Vector& verrStart, SimTK::Vector& verrApplied, SimTK::Vector& pi,
               SimTK::Array_<UncondRT>& unconditional, SimTK::Array_<UniContactRT>& uniContact,
               SimTK::Array_<UniSpeedRT>& uniSpeed, SimTK::Array_<BoundedRT>& bounded,
               SimTK::Array_<ConstraintLtdFrictionRT>& consLtdFriction,
               SimTK::Array_<StateLtdFrictionRT>& stateLtdFriction) const override;

    /// Equality constraints only (the stepper's bilateral position projection): plain PGS
    /// sweeps over the participating rows of [A+D] pi = rhs; pi is zero elsewhere.
    bool solveBilateral(const SimTK::Array_<SimTK::MultiplierIndex>& participating,
                        const SimTK::Matrix& A, const SimTK::Vector& D, const SimTK::Vector& rhs,
                        SimTK::Vector& pi) const override;

private:
    double sor_ = 1.2;  // successive over-relaxation factor at the start of each solve
};

}  // namespace graspsim::contact
