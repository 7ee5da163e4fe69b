#pragma once
// The matrix of a linearly implicit step, A = M - g D - g^2 K (g = the step's implicit factor
// times h), built from the mass matrix and the force Jacobians at one state and LU-factored once,
// so that each stage of a step solves with it (linearly_implicit_stepper.h).

#include "graspsim/integration/force_jacobian.h"

#include "graspsim/simbody.h"

#include <vector>

namespace graspsim::integration {

class StepMatrix {
public:
    // Builds and factors A at `state` (realized through Acceleration). A locked mobilizer's rows
    // and columns become the identity (its speeds do not change; see holdLocked()).
    // @throws graspsim::NumericalError if A is singular.
    // `massMatrix`: M (column-major) computed earlier, to use instead of calcM at `state`; empty:
    // calcM here.
    StepMatrix(const SimTK::SimbodyMatterSubsystem& matter, const std::vector<const ForceJacobianContributor*>& contributors,
               const SimTK::State& state, double g, const std::vector<double>& massMatrix = {});
    // The M in use (column-major).
    const std::vector<double>& getMassMatrix() const { return M_; }

    // M v, with the M of the state A was built at.
    std::vector<double> multiplyByM(const std::vector<double>& v) const;
    // g K_g v, with K_g = (g_/g)^2 K: the stiffness this matrix stands for when a step's factor
    // is g rather than the g_ it was built with. A = M - g_ D - g_^2 K = M - g D_g - g^2 K_g with
    // D_g = (g_/g) D: a W-method may take A as the matrix of any step, its approximate Jacobian
    // being D_g, K_g, as long as the stages use K_g with it.
    std::vector<double> multiplyByGK(const std::vector<double>& v, double g) const;
    // x = A^-1 b in place; b's entries for locked speeds are zeroed first.
    void solve(std::vector<double>& b) const;
    int size() const { return n_; }
    // g, the factor A was built with (s).
    double getFactor() const { return g_; }

private:
    void findLocked(const SimTK::SimbodyMatterSubsystem& matter, const SimTK::State& state);
    void holdLocked(std::vector<double>& A) const;
    void factor(std::vector<double> A);

    int n_ = 0;
    double g_ = 0;
    std::vector<double> M_, K_;  // column-major n x n
    std::vector<double> lu_;     // A's LU factors, column-major, rows swapped as pivots_ says
    std::vector<int> pivots_;
    std::vector<int> locked_;    // speed indices of locked mobilizers
};

}  // namespace graspsim::integration
