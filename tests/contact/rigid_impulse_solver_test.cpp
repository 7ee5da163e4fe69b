// RigidImpulseSolver: closed-form single contacts (pushing, sliding, rolling, separating) and,
// as the second independent method, Simbody's own PGSImpulseSolver, which it must reproduce
// bit for bit on random coupled problems.

#include "graspsim/contact/rigid_impulse_solver.h"

#include <gtest/gtest.h>

#include <random>

#include "graspsim/error.h"
#include "graspsim/system/silenced_stdout.h"

namespace graspsim::contact {
namespace {

using SimTK::Array_;
using SimTK::ImpulseSolver;
using SimTK::Matrix;
using SimTK::MultiplierIndex;
using SimTK::Vector;

// One solver call's inputs and outputs, run through either solver.
struct Problem {
    Matrix A;
    Vector D, piExpand, verrStart, verrApplied, pi;
    Array_<MultiplierIndex> participating, expanding;
    Array_<ImpulseSolver::UniContactRT> contacts;

    bool solveWith(const ImpulseSolver& solver) {
        Array_<ImpulseSolver::UncondRT> uncond;
        Array_<ImpulseSolver::UniSpeedRT> speed;
        Array_<ImpulseSolver::BoundedRT> bounded;
        Array_<ImpulseSolver::ConstraintLtdFrictionRT> consLtd;
        Array_<ImpulseSolver::StateLtdFrictionRT> stateLtd;
        return solver.solve(0, participating, A, D, expanding, piExpand, verrStart, verrApplied, pi, uncond,
                            contacts, speed, bounded, consLtd, stateLtd);
    }
};

// k contacts, each a normal row 3i and friction rows 3i+1, 3i+2.
Problem makeContacts(int k, const Vector& rhs, double mu) {
    Problem p;
    const int m = 3 * k;
    p.A.resize(m, m);
    p.A = 1.0;  // identity
    p.D.resize(m);
    p.D = 0;
    p.piExpand.resize(m);
    p.piExpand = 0;
    p.verrStart = rhs;
    for (int i = 0; i < k; ++i) {
        ImpulseSolver::UniContactRT rt;
        rt.m_type = ImpulseSolver::Participating;
        rt.m_Nk = MultiplierIndex(3 * i);
        rt.m_Fk = {MultiplierIndex(3 * i + 1), MultiplierIndex(3 * i + 2)};
        rt.m_effMu = mu;
        rt.m_slipVel = SimTK::Vec2(0);  // unused by the solvers; set so copies read no garbage
        rt.m_slipMag = 0;
        p.contacts.push_back(rt);
        for (int j = 0; j < 3; ++j) p.participating.push_back(MultiplierIndex(3 * i + j));
    }
    return p;
}

TEST(RigidImpulseSolver, SingleContactMatchesClosedForm) {
    const RigidImpulseSolver solver;
    // A = 2 I: approaching at 1 m/s with tangential error 0.5 m/s -> pi = rhs / 2 inside the cone
    {
        Problem p = makeContacts(1, Vector(SimTK::Vec3(-1, 0.5, 0)), 1.0);
        p.A *= 2;
        EXPECT_TRUE(p.solveWith(solver));
        EXPECT_NEAR(p.pi[0], -0.5, 1e-6);
        EXPECT_NEAR(p.pi[1], 0.25, 1e-6);
        EXPECT_NEAR(p.pi[2], 0, 1e-6);
        EXPECT_EQ(p.contacts[0].m_frictionCond, ImpulseSolver::Rolling);
        EXPECT_NEAR(p.verrStart.normInf(), 0, 1e-6);  // the error is gone
    }
    // mu = 0.3: friction on the cone, |pi_t| = mu |pi_n|, pointing along the tangential error
    {
        Problem p = makeContacts(1, Vector(SimTK::Vec3(-1, 0.3, 0.4)), 0.3);
        EXPECT_TRUE(p.solveWith(solver));
        EXPECT_NEAR(p.pi[0], -1, 1e-6);
        EXPECT_NEAR(p.pi[1], 0.3 * 0.6, 1e-6);
        EXPECT_NEAR(p.pi[2], 0.3 * 0.8, 1e-6);
        EXPECT_EQ(p.contacts[0].m_frictionCond, ImpulseSolver::Sliding);
    }
    // separating: no push, hence no friction
    {
        Problem p = makeContacts(1, Vector(SimTK::Vec3(1, 0.3, 0.4)), 0.8);
        EXPECT_TRUE(p.solveWith(solver));
        EXPECT_EQ(p.pi[0], 0);
        EXPECT_EQ(p.pi[1], 0);
        EXPECT_EQ(p.pi[2], 0);
        EXPECT_EQ(p.contacts[0].m_contactCond, ImpulseSolver::UniOff);
    }
}

// A random coupled problem: A = J J^T + small diagonal (symmetric positive definite like
// G M^-1 G^T), contacts in every role the stepper gives them.
Problem makeRandomProblem(std::mt19937& rng, bool withExpansion) {
    std::uniform_real_distribution<double> u(-1, 1);
    const int k = 2 + static_cast<int>(rng() % 5);
    Problem p = makeContacts(k, Vector(3 * k, 0.0), 0.5);
    const int m = 3 * k;
    Matrix J(m, m + 3);
    for (int r = 0; r < m; ++r)
        for (int c = 0; c < m + 3; ++c) J(r, c) = u(rng);
    p.A = J * ~J;
    for (int r = 0; r < m; ++r) p.verrStart[r] = u(rng), p.D[r] = r % 4 == 0 ? 0.01 : 0;
    p.verrApplied.resize(m);
    for (int r = 0; r < m; ++r) p.verrApplied[r] = 0.3 * u(rng);
    for (int i = 0; i < k; ++i) p.contacts[i].m_effMu = 0.2 + 0.5 * (u(rng) + 1);
    if (withExpansion) {  // first contact expands with a known impulse, its normal not participating
        p.contacts[0].m_type = ImpulseSolver::Known;
        p.expanding.push_back(MultiplierIndex(0));
        p.piExpand[0] = -0.2;
        p.participating.erase(p.participating.begin());
        p.verrApplied.clear();
    }
    if (k > 2) {  // last contact observing: nothing of it participates
        p.contacts.back().m_type = ImpulseSolver::Observing;
        p.participating.resize(p.participating.size() - 3);
    }
    return p;
}

TEST(RigidImpulseSolver, ReproducesSimbodysPgsBitForBit) {
    system::SilencedStdout quiet;  // Simbody's PGS prints its debug trace
    std::mt19937 rng(7);
    const RigidImpulseSolver ours;
    const SimTK::PGSImpulseSolver simbodys(0);
    int sliding = 0, rolling = 0, released = 0;  // the problems must reach every condition
    for (int trial = 0; trial < 40; ++trial) {
        const Problem problem = makeRandomProblem(rng, trial % 2 == 1);
        Problem a = problem, b = problem;
        EXPECT_EQ(a.solveWith(ours), b.solveWith(simbodys)) << trial;
        for (int r = 0; r < problem.A.nrow(); ++r) {
            EXPECT_EQ(a.pi[r], b.pi[r]) << trial << " row " << r;
            EXPECT_EQ(a.verrStart[r], b.verrStart[r]) << trial << " row " << r;
        }
        for (unsigned i = 0; i < problem.contacts.size(); ++i) {
            EXPECT_EQ(a.contacts[i].m_contactCond, b.contacts[i].m_contactCond) << trial;
            EXPECT_EQ(a.contacts[i].m_frictionCond, b.contacts[i].m_frictionCond) << trial;
            sliding += a.contacts[i].m_frictionCond == ImpulseSolver::Sliding;
            rolling += a.contacts[i].m_frictionCond == ImpulseSolver::Rolling;
            released += a.contacts[i].m_contactCond == ImpulseSolver::UniOff;
        }
        // the bilateral solve (position projection) over the normals
        Array_<MultiplierIndex> normals;
        for (int r = 0; r < problem.A.nrow(); r += 3) normals.push_back(MultiplierIndex(r));
        Vector piA, piB;
        EXPECT_EQ(ours.solveBilateral(normals, problem.A, problem.D, problem.verrStart, piA),
                  simbodys.solveBilateral(normals, problem.A, problem.D, problem.verrStart, piB));
        for (int r = 0; r < problem.A.nrow(); ++r) EXPECT_EQ(piA[r], piB[r]) << trial << " row " << r;
    }
    EXPECT_GT(sliding, 0);
    EXPECT_GT(rolling, 0);
    EXPECT_GT(released, 0);
}

TEST(RigidImpulseSolver, RejectsConstraintKindsItDoesNotSolve) {
    Problem p = makeContacts(1, Vector(SimTK::Vec3(-1, 0, 0)), 0.5);
    Array_<ImpulseSolver::UncondRT> uncond(1);
    Array_<ImpulseSolver::UniSpeedRT> speed;
    Array_<ImpulseSolver::BoundedRT> bounded;
    Array_<ImpulseSolver::ConstraintLtdFrictionRT> consLtd;
    Array_<ImpulseSolver::StateLtdFrictionRT> stateLtd;
    EXPECT_THROW(RigidImpulseSolver().solve(0, p.participating, p.A, p.D, p.expanding, p.piExpand, p.verrStart,
                                            p.verrApplied, p.pi, uncond, p.contacts, speed, bounded, consLtd,
                                            stateLtd),
                 Error);
}

}  // namespace
}  // namespace graspsim::contact
