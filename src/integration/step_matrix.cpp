#include "step_matrix.h"

#include "graspsim/error.h"

#include <cmath>
#include <string>
#include <utility>

namespace graspsim::integration {

StepMatrix::StepMatrix(const SimTK::SimbodyMatterSubsystem& matter,
                       const std::vector<const ForceJacobianContributor*>& contributors, const SimTK::State& state, double g,
                       const std::vector<double>& massMatrix)
    : n_(state.getNU()), g_(g) {
    const std::size_t size = static_cast<std::size_t>(n_) * static_cast<std::size_t>(n_);
    if (massMatrix.size() == size) {
        M_ = massMatrix;
    } else {
        SimTK::Matrix M;
        matter.calcM(state, M);
        M_.assign(M.getContiguousScalarData(), M.getContiguousScalarData() + size);
    }
    SimTK::Matrix D(n_, n_, 0.0), K(n_, n_, 0.0);
    for (const ForceJacobianContributor* c : contributors) c->addForceJacobians(state, D, K);
    const double* m = M_.data();
    const double* d = D.getContiguousScalarData();
    const double* k = K.getContiguousScalarData();
    K_.assign(k, k + size);
    std::vector<double> A(size);
    for (std::size_t i = 0; i < size; ++i) A[i] = m[i] - g * d[i] - g * g * k[i];
    findLocked(matter, state);
    holdLocked(A);
    factor(std::move(A));
}

// A locked mobilizer's speeds (SimTK::MobilizedBody::lock) do not change: du = 0 there, and the
// other rows see no coupling to them (the lock's force is in the state's accelerations).
void StepMatrix::findLocked(const SimTK::SimbodyMatterSubsystem& matter, const SimTK::State& state) {
    for (SimTK::MobilizedBodyIndex b(1); b < matter.getNumBodies(); ++b) {
        const SimTK::MobilizedBody& mobod = matter.getMobilizedBody(b);
        if (!mobod.isLocked(state)) continue;
        const int first = mobod.getFirstUIndex(state);
        for (int i = first; i < first + mobod.getNumU(state); ++i) locked_.push_back(i);
    }
}

void StepMatrix::holdLocked(std::vector<double>& A) const {
    for (int i : locked_) {
        for (int k = 0; k < n_; ++k) A[i + n_ * k] = A[k + n_ * i] = 0;
        A[i + n_ * i] = 1;
    }
}

// Gaussian elimination with partial pivoting, by hand: at the sizes of a hand (a few dozen
// mobilities) SimTK::Matrix's element access and FactorLU's copies cost more than the arithmetic.
void StepMatrix::factor(std::vector<double> A) {
    const int n = n_;
    pivots_.resize(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
        int pivot = k;
        for (int r = k + 1; r < n; ++r)
            if (std::abs(A[r + n * k]) > std::abs(A[pivot + n * k])) pivot = r;
        pivots_[k] = pivot;
        if (A[pivot + n * k] == 0 || !std::isfinite(A[pivot + n * k])) {
            throw NumericalError("linearly implicit step: the step's matrix M - hD - h^2 K is singular or not finite");
        }
        if (pivot != k)
            for (int c = 0; c < n; ++c) std::swap(A[k + n * c], A[pivot + n * c]);
        const double inverse = 1 / A[k + n * k];
        for (int r = k + 1; r < n; ++r) {
            const double factor = A[r + n * k] *= inverse;
            if (factor == 0) continue;
            for (int c = k + 1; c < n; ++c) A[r + n * c] -= factor * A[k + n * c];
        }
    }
    lu_ = std::move(A);
}

void StepMatrix::solve(std::vector<double>& b) const {
    const int n = n_;
    for (int i : locked_) b[i] = 0;
    // Whole rows (L's part included) were swapped during the factorization: P A = L U with P the
    // swaps in order, so b takes every swap before the substitutions.
    for (int k = 0; k < n; ++k)
        if (pivots_[k] != k) std::swap(b[k], b[pivots_[k]]);
    for (int k = 0; k < n; ++k)
        for (int r = k + 1; r < n; ++r) b[r] -= lu_[r + n * k] * b[k];
    for (int k = n - 1; k >= 0; --k) {
        double sum = b[k];
        for (int c = k + 1; c < n; ++c) sum -= lu_[k + n * c] * b[c];
        b[k] = sum / lu_[k + n * k];
    }
}

namespace {

std::vector<double> multiply(const std::vector<double>& A, int n, const std::vector<double>& v) {
    std::vector<double> out(static_cast<std::size_t>(n), 0.0);
    for (int c = 0; c < n; ++c) {
        if (v[c] == 0) continue;
        for (int r = 0; r < n; ++r) out[r] += A[r + n * c] * v[c];
    }
    return out;
}

}  // namespace

std::vector<double> StepMatrix::multiplyByM(const std::vector<double>& v) const { return multiply(M_, n_, v); }
std::vector<double> StepMatrix::multiplyByGK(const std::vector<double>& v, double g) const {
    std::vector<double> out = multiply(K_, n_, v);
    const double scale = g_ * g_ / g;
    for (double& x : out) x *= scale;
    return out;
}

}  // namespace graspsim::integration
