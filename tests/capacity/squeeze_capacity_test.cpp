#include "graspsim/capacity/squeeze_capacity.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

namespace {

using graspsim::capacity::BisectionProtocol;
using graspsim::capacity::makeSqueezeRuns;
using graspsim::capacity::RampProtocol;
using graspsim::capacity::runBisection;
using graspsim::capacity::runRamp;
using graspsim::capacity::SqueezeCase;
using graspsim::capacity::SqueezeIntegrator;

// The grid: three mu and three N, mu = 0.5 and N = 10 (validation's case) not among them.
const double kMus[] = {0.3, 0.6, 0.9};
const double kPresses[] = {4, 12, 25};

constexpr double kRampTime = 1.0;  // s from zero to 2 mu N: each case's rate is 2 mu N / kRampTime

RampProtocol makeRamp(const SqueezeCase& c) {
    RampProtocol p;
    p.direction = SimTK::UnitVec3(0, 1, 0);
    p.start = 0.01;
    p.rate = c.findLimit() / kRampTime;
    p.maxDuration = 2 * kRampTime;
    p.sampleInterval = 0.002;
    return p;
}

// Coulomb's answer for a ramp F = R t: the box stays until F = 2 mu N (t = T), then x = R (t - T)^3 / (6 m),
// so the slip reaches d at F = 2 mu N + R (6 m d / R)^(1/3): the capacity plus what the ramp adds
// while the box accelerates through d. Compliant (regularized) friction adds its creep: below the
// limit the box creeps at v_t F / (2 mu N) (v_t T / 2 by the time F = 2 mu N) and passes the limit
// at about v_t; the slip is solved for d by bisection.
double findCoulombOnset(const SqueezeCase& c, double rate, double d, bool creep) {
    const double T = c.findLimit() / rate;
    const double vt = creep ? c.transitionVelocity : 0;
    const auto slip = [&](double tau) { return vt * T / 2 + vt * tau + rate * tau * tau * tau / (6 * c.boxMass); };
    double lo = 0, hi = 10;
    for (int k = 0; k < 100; ++k) (slip(0.5 * (lo + hi)) < d ? lo : hi) = 0.5 * (lo + hi);
    return c.findLimit() + rate * 0.5 * (lo + hi);
}

void expectRampOnset(bool rigid, SqueezeIntegrator integrator = SqueezeIntegrator::Reference) {
    for (double mu : kMus) {
        for (double press : kPresses) {
            SqueezeCase c;
            c.mu = mu;
            c.press = press;
            c.rigid = rigid;
            c.integrator = integrator;
            const RampProtocol p = makeRamp(c);
            const auto trace = runRamp(makeSqueezeRuns(c), p);
            ASSERT_TRUE(trace.figures.slipped) << mu << " " << press;
            const double expected = findCoulombOnset(c, p.rate, p.criteria.slip, !rigid);
            EXPECT_NEAR(trace.figures.slipOnsetLoad / expected, 1, 0.02)
                << "mu " << mu << ", N " << press << ": onset " << trace.figures.slipOnsetLoad << " N, expected " << expected
                << " N (2 mu N = " << c.findLimit() << " N)";
            EXPECT_GT(trace.figures.slipOnsetLoad, c.findLimit() * (rigid ? 1.0 : 0.98));
        }
    }
}

}  // namespace

TEST(SqueezeCapacity, RampFindsTheCoulombOnsetRigid) { expectRampOnset(true); }

TEST(SqueezeCapacity, RampFindsTheCoulombOnsetCompliant) { expectRampOnset(false); }

TEST(SqueezeCapacity, RampFindsTheCoulombOnsetOnTheLinearlyImplicitStepper) {
    expectRampOnset(false, SqueezeIntegrator::LinearlyImplicit);
}

// A constant load F above 2 mu N from rest: once the slip speed passes the transition velocity
// (about 0.2 ms here) friction is mu N on each side, so the box slides with Coulomb's
// a = (F - 2 mu N) / m, a parabola whose second difference over equal intervals is a dt^2. F is
// 1.2 x 2 mu N and the window 0.15 s, so the box travels at most 0.14 m of its 0.5 m half-length
// and stays between the spheres.
TEST(SqueezeCapacity, LinearlyImplicitStepperSlidesWithTheCoulombAcceleration) {
    for (double mu : kMus) {
        for (double press : {kPresses[0], kPresses[2]}) {
            SqueezeCase c;
            c.mu = mu;
            c.press = press;
            c.integrator = SqueezeIntegrator::LinearlyImplicit;
            graspsim::simulation::LoadRampSpec load;
            load.direction = SimTK::UnitVec3(0, 1, 0);
            load.start = 0.01;
            load.initial = 1.2 * c.findLimit();
            const auto run = makeSqueezeRuns(c)(load);
            run->advanceTo(load.start);
            run->captureReference();
            const double dt = 0.05;
            double x[3];
            for (int k = 0; k < 3; ++k) {
                run->advanceTo(load.start + (k + 1) * dt);
                x[k] = run->sampleNow().slip;
            }
            const double coulomb = (load.initial - c.findLimit()) / c.boxMass;
            EXPECT_NEAR((x[2] - 2 * x[1] + x[0]) / (dt * dt) / coulomb, 1, 0.02) << "mu " << mu << ", N " << press;
        }
    }
}

// Constant loads held h = 0.5 s: above 2 mu N by e the box slides e h^2 / (2 m), which passes 2 mm
// for e > 0.016 N (0.2 % of the smallest 2 mu N here); below it, it stays (rigid) or creeps less
// than v_t h = 0.5 mm (compliant). So the bisection brackets 2 mu N itself, to its 1 % tolerance.
TEST(SqueezeCapacity, BisectionFindsTwoMuN) {
    const std::pair<bool, SqueezeIntegrator> kinds[] = {{true, SqueezeIntegrator::Reference},
                                                        {false, SqueezeIntegrator::Reference},
                                                        {false, SqueezeIntegrator::LinearlyImplicit}};
    for (const auto& [rigid, integrator] : kinds) {
        for (double mu : {0.3, 0.9}) {
            SqueezeCase c;
            c.mu = mu;
            c.press = 12;
            c.rigid = rigid;
            c.integrator = integrator;
            BisectionProtocol p;
            p.direction = SimTK::UnitVec3(0, 1, 0);
            p.start = 0.01;
            p.hold = 0.5;
            p.high = 1.5 * c.findLimit();
            p.sampleInterval = 0.005;
            const auto b = runBisection(makeSqueezeRuns(c), p);
            EXPECT_NEAR(b.findEstimate() / c.findLimit(), 1, 0.02)
                << (rigid ? "rigid" : "compliant") << " integrator " << static_cast<int>(integrator) << " mu " << mu;
            const double slideMargin = 2 * c.boxMass * p.criteria.slip / (p.hold * p.hold);  // e above, N
            EXPECT_LE(b.held, c.findLimit() + slideMargin * 1.01);
            EXPECT_GE(b.slipped, c.findLimit() * 0.99);
        }
    }
}

// The ramp's onset, taken back by what Coulomb says the ramp adds (R (6 m d / R)^(1/3)), agrees
// with the bisection's bracket: the two methods measure the same capacity.
TEST(SqueezeCapacity, RampAndBisectionAgree) {
    SqueezeCase c;
    c.mu = 0.6;
    c.press = 4;
    c.rigid = true;
    const RampProtocol ramp = makeRamp(c);
    const double onset = runRamp(makeSqueezeRuns(c), ramp).figures.slipOnsetLoad;
    const double added = ramp.rate * std::cbrt(6 * c.boxMass * ramp.criteria.slip / ramp.rate);
    BisectionProtocol p;
    p.direction = ramp.direction;
    p.start = ramp.start;
    p.high = onset;
    const auto b = runBisection(makeSqueezeRuns(c), p);
    EXPECT_NEAR((onset - added) / b.findEstimate(), 1, 0.02) << onset << " " << added << " " << b.held << " " << b.slipped;
}

// The thresholds are the user's (capacity --slip-threshold, --drop-threshold): at each, the ramp's
// onset and drop are Coulomb's load at which the accelerating box has slid that far.
TEST(SqueezeCapacity, OnsetAndDropFollowTheThresholdsAsCoulombSays) {
    SqueezeCase c;
    c.mu = 0.3;  // a small capacity (2.4 N), to which the ramp's slide through d adds 11-25 %
    c.press = 4;
    c.rigid = true;
    for (const auto& [slip, drop] : {std::pair{0.0005, 0.004}, std::pair{0.006, 0.015}}) {
        RampProtocol p = makeRamp(c);
        p.criteria.slip = slip;
        p.criteria.drop = drop;
        const auto trace = runRamp(makeSqueezeRuns(c), p);
        ASSERT_TRUE(trace.figures.slipped && trace.figures.dropped) << slip << " " << drop;
        EXPECT_NEAR(trace.figures.slipOnsetLoad / findCoulombOnset(c, p.rate, slip, false), 1, 0.02) << slip;
        EXPECT_NEAR(trace.figures.dropLoad / findCoulombOnset(c, p.rate, drop, false), 1, 0.02) << drop;
    }
}

// The grip force is the sum of the contacts' normal forces: each slider is pressed by a constant
// N along x and slides only along x, so at equilibrium, and while the box slides along y (which
// moves no slider), the two contacts push back with N each: 2 N, at the start and at the onset.
TEST(SqueezeCapacity, GripForceIsTwiceThePress) {
    for (double press : {7.0, 18.0}) {
        SqueezeCase c;
        c.mu = 0.45;
        c.press = press;
        const auto trace = runRamp(makeSqueezeRuns(c), makeRamp(c));
        ASSERT_TRUE(trace.figures.slipped) << press;
        EXPECT_NEAR(trace.figures.gripForceAtStart / (2 * press), 1, 1e-3) << press;
        EXPECT_NEAR(trace.figures.gripForceAtOnset / (2 * press), 1, 1e-3) << press;
        // Coulomb: at the onset the load exceeds mu times the grip by what the ramp adds while the
        // box slides 2 mm (findCoulombOnset), so the grip accounts for the capacity.
        EXPECT_NEAR(trace.figures.slipOnsetLoad / findCoulombOnset(c, makeRamp(c).rate, 0.002, true), 1, 0.02);
        EXPECT_GT(trace.figures.slipOnsetLoad, 0.98 * c.mu * trace.figures.gripForceAtOnset);
    }
    SqueezeCase rigid;
    rigid.rigid = true;
    EXPECT_TRUE(std::isnan(runRamp(makeSqueezeRuns(rigid), makeRamp(rigid)).figures.gripForceAtStart));
}
