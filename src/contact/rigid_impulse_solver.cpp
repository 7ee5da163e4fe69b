#include "graspsim/contact/rigid_impulse_solver.h"

#include "graspsim/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace graspsim::contact {

namespace {

using SimTK::Array_;
using SimTK::MultiplierIndex;

// The solver's operands as raw arrays. SimTK's element access goes through Debian's debug
// MatrixHelper (a call and assertions per element); the sweeps touch each element many times.
struct Operands {
    const double* A = nullptr;  // A(r, c) = A[r + c * m]
    const double* D = nullptr;  // null if D is empty
    int m = 0;
};

const double* contiguousData(const SimTK::Vector& v, const char* name) {
    if (v.size() == 0) return nullptr;
    if (!v.hasContiguousData()) throw Error(std::string("RigidImpulseSolver: ") + name + " is not contiguous");
    return &v[0];
}

double* contiguousData(SimTK::Vector& v, const char* name) {
    return const_cast<double*>(contiguousData(static_cast<const SimTK::Vector&>(v), name));
}

Operands viewOperands(const SimTK::Matrix& A, const SimTK::Vector& D) {
    Operands op;
    op.m = A.nrow();
    if (A.ncol() != op.m || (D.size() != 0 && D.size() != op.m))
        throw Error("RigidImpulseSolver: A is " + std::to_string(A.nrow()) + " x " + std::to_string(A.ncol()) +
                    " and D has " + std::to_string(D.size()) + " elements; A must be square and D empty or as long");
    if (op.m == 0) return op;
    op.A = &A(0, 0);
    const int last = op.m - 1;
    if (&A(last, 0) != op.A + last || &A(0, last) != op.A + last * op.m || &A(last, last) != op.A + last * (op.m + 1))
        throw Error("RigidImpulseSolver: A is not packed in column order");
    op.D = contiguousData(D, "D");
    return op;
}

// Row `row` of [A+D] times pi, over the given columns only (the participating rows: the others'
// pi are zero), summed in column order, the diagonal D term last.
double rowTimesPi(const Operands& op, int row, const Array_<MultiplierIndex>& columns, const double* pi) {
    double sum = 0;
    for (const MultiplierIndex c : columns) sum += op.A[row + c * op.m] * pi[c];
    if (op.D) sum += op.D[row] * pi[row];
    return sum;
}

// Relaxed Gauss-Seidel update of pi[row] from the row's residual rhs - rowSum; a row whose
// diagonal is not positive is left alone. Returns the squared residual.
double relaxRow(const Operands& op, int row, double rhs, double rowSum, double sor, double* pi) {
    double diagonal = op.A[row + row * op.m];
    if (op.D) diagonal += op.D[row];
    const double residual = rhs - rowSum;
    if (diagonal > 0) pi[row] += sor * residual / diagonal;
    return residual * residual;
}

// Scales the friction impulses pi[rows] back onto the circle of radius maxLength if outside.
SimTK::ImpulseSolver::FricCond limitFriction(double maxLength, const Array_<MultiplierIndex>& rows, double* pi) {
    const double max2 = maxLength * maxLength;
    double length2 = 0;
    for (const MultiplierIndex r : rows) length2 += pi[r] * pi[r];
    if (length2 <= max2) return SimTK::ImpulseSolver::Rolling;
    const double scale = std::sqrt(max2 / length2);
    for (const MultiplierIndex r : rows) pi[r] *= scale;
    return SimTK::ImpulseSolver::Sliding;
}

// rhs -= [A+D] * piExpand, for the expanding (known) normal impulses.
void moveExpansionToRhs(const Operands& op, const Array_<MultiplierIndex>& expanding, const double* piExpand,
                        double* rhs) {
    for (int r = 0; r < op.m; ++r) {
        double sum = 0;
        for (const MultiplierIndex c : expanding) sum += op.A[r + c * op.m] * piExpand[c];
        rhs[r] -= sum + op.D[r] * piExpand[r];
    }
}

// rhs -= [A+D] * pi over all of A: what is left of the constraint-space velocity error.
void subtractImpulseResponse(const Operands& op, const double* pi, double* rhs) {
    for (int r = 0; r < op.m; ++r) {
        double sum = 0;
        for (int c = 0; c < op.m; ++c) sum += op.A[r + c * op.m] * pi[c];
        rhs[r] -= sum;
    }
    if (op.D)
        for (int r = 0; r < op.m; ++r) rhs[r] -= op.D[r] * pi[r];
}

// The relaxation factor after a sweep whose enforced error grew by `rate`.
double relaxedSor(double sor, double rate) { return (rate > 1 && sor > 0.1) ? std::max(0.8 * sor, 0.1) : sor; }

struct SweepError {
    double all2 = 0;       // sum of squared residuals of every participating row
    double enforced2 = 0;  // of the rows whose condition is active (pushing normal, rolling friction)
};

// One sweep over the unilateral contacts: every participating normal first, then the friction
// pairs, each pair's residuals from the same iterate.
SweepError sweepContacts(const Operands& op, const Array_<MultiplierIndex>& participating, const double* rhs,
                         const double* piExpand, double sor, Array_<SimTK::ImpulseSolver::UniContactRT>& contacts,
                         double* pi) {
    using IS = SimTK::ImpulseSolver;
    SweepError e;
    for (IS::UniContactRT& rt : contacts) {
        if (rt.m_type != IS::Participating) continue;
        const int n = rt.m_Nk;
        const double er2 = relaxRow(op, n, rhs[n], rowTimesPi(op, n, participating, pi), sor, pi);
        e.all2 += er2;
        rt.m_contactCond = IS::UniActive;
        if (rt.m_sign * pi[n] > 0) {  // would pull: release
            pi[n] = 0;
            rt.m_contactCond = IS::UniOff;
        }
        if (rt.m_contactCond == IS::UniActive) e.enforced2 += er2;
    }
    for (IS::UniContactRT& rt : contacts) {
        if (rt.m_type == IS::Observing || !rt.hasFriction()) continue;
        if (rt.m_Fk.size() > 3) throw Error("RigidImpulseSolver: a contact with more than 3 friction rows");
        const unsigned k = rt.m_Fk.size();
        double sums[3];
        for (unsigned i = 0; i < k; ++i) sums[i] = rowTimesPi(op, rt.m_Fk[i], participating, pi);
        double er2 = 0;
        for (unsigned i = 0; i < k; ++i) er2 += relaxRow(op, rt.m_Fk[i], rhs[rt.m_Fk[i]], sums[i], sor, pi);
        e.all2 += er2;
        const double normal = std::abs(pi[rt.m_Nk] + (piExpand ? piExpand[rt.m_Nk] : 0.0));
        rt.m_frictionCond = limitFriction(rt.m_effMu * normal, rt.m_Fk, pi);
        if (rt.m_frictionCond == IS::Rolling) e.enforced2 += er2;
    }
    return e;
}

}  // namespace

RigidImpulseSolver::RigidImpulseSolver(double rollToSlipSpeed)
    : SimTK::ImpulseSolver(rollToSlipSpeed, 1e-6, 100) {}

bool RigidImpulseSolver::solve(int phase, const Array_<MultiplierIndex>& participating, const SimTK::Matrix& A,
                               const SimTK::Vector& D, const Array_<MultiplierIndex>& expanding,
                               SimTK::Vector& piExpand, SimTK::Vector& verrStart, SimTK::Vector& verrApplied,
                               SimTK::Vector& pi, Array_<UncondRT>& unconditional,
                               Array_<UniContactRT>& uniContact, Array_<UniSpeedRT>& uniSpeed,
                               Array_<BoundedRT>& bounded, Array_<ConstraintLtdFrictionRT>& consLtdFriction,
                               Array_<StateLtdFrictionRT>& stateLtdFriction) const {
    if (!unconditional.empty() || !uniSpeed.empty() || !bounded.empty() || !consLtdFriction.empty() ||
        !stateLtdFriction.empty())
        throw Error("RigidImpulseSolver: only unilateral contacts are supported");
    const Operands op = viewOperands(A, D);
    if (verrStart.size() != op.m || piExpand.size() != op.m || (verrApplied.size() != 0 && verrApplied.size() != op.m))
        throw Error("RigidImpulseSolver: verrStart, piExpand or verrApplied does not match A");
    ++m_nSolves[phase];
    pi.resize(op.m);
    pi.setToZero();
    if (verrApplied.size()) verrStart += verrApplied;
    double* rhs = contiguousData(verrStart, "verrStart");
    double* x = contiguousData(pi, "pi");
    const double* xExpand = contiguousData(piExpand, "piExpand");
    if (!expanding.empty()) moveExpansionToRhs(op, expanding, xExpand, rhs);
    const int p = static_cast<int>(participating.size());
    if (p == 0) return true;

    bool converged = false;
    double rms = std::numeric_limits<double>::infinity(), sor = sor_;
    for (int sweep = 1; sweep <= m_maxIters; ++sweep) {
        ++m_nIters[phase];
        const double previous = rms;
        const SweepError e = sweepContacts(op, participating, rhs, xExpand, sor, uniContact, x);
        rms = std::sqrt(e.enforced2 / p);
        sor = relaxedSor(sor, rms / previous);
        if (rms < m_convergenceTol) {
            converged = true;
            break;
        }
    }
    if (!converged) ++m_nFail[phase];
    subtractImpulseResponse(op, x, rhs);
    return converged;
}

bool RigidImpulseSolver::solveBilateral(const Array_<MultiplierIndex>& participating, const SimTK::Matrix& A,
                                        const SimTK::Vector& D, const SimTK::Vector& rhs, SimTK::Vector& pi) const {
    const Operands op = viewOperands(A, D);
    if (rhs.size() != op.m) throw Error("RigidImpulseSolver: rhs does not match A");
    ++m_nBilateralSolves;
    pi.resize(op.m);
    pi.setToZero();
    const int p = static_cast<int>(participating.size());
    if (p == 0) return true;
    const double* b = contiguousData(rhs, "rhs");
    double* x = contiguousData(pi, "pi");

    bool converged = false;
    double rms = std::numeric_limits<double>::infinity(), sor = sor_;
    for (int sweep = 1; sweep <= m_maxIters; ++sweep) {
        ++m_nBilateralIters;
        const double previous = rms;
        double enforced2 = 0;
        for (const MultiplierIndex r : participating)
            enforced2 += relaxRow(op, r, b[r], rowTimesPi(op, r, participating, x), sor, x);
        rms = std::sqrt(enforced2 / p);
        sor = relaxedSor(sor, rms / previous);
        if (rms < m_convergenceTol) {
            converged = true;
            break;
        }
    }
    if (!converged) ++m_nBilateralFail;
    return converged;
}

}  // namespace graspsim::contact
