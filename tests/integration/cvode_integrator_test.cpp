#include "graspsim/integration/cvode_integrator.h"

#include <gtest/gtest.h>

#include "graspsim/error.h"
#include "graspsim/integration/simbody_stepper.h"

#include <cfloat>
#include <cmath>
#include <memory>
#include <sstream>
#include <vector>

namespace graspsim::integration {
namespace {

constexpr double g = 9.81;  // m/s^2

std::string toText(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

// A simple pendulum: point mass m on a massless rod of length L, pinned to ground about z.
// q = angle from the downward vertical (rad).
struct Pendulum {
    static constexpr double m = 1.5, L = 0.7;
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter{system};
    SimTK::GeneralForceSubsystem forces{system};
    SimTK::Force::Gravity gravity{forces, matter, SimTK::Vec3(0, -g, 0)};
    SimTK::MobilizedBody::Pin pin{matter.updGround(), SimTK::Transform(),
                                  SimTK::Body::Rigid(SimTK::MassProperties(m, SimTK::Vec3(0), SimTK::Inertia(0))),
                                  SimTK::Transform(SimTK::Vec3(0, L, 0))};

    SimTK::State makeState(double theta0) {
        SimTK::State s = system.realizeTopology();
        pin.setQ(s, theta0);
        return s;
    }
    double calcEnergy(const SimTK::State& s) const {
        system.realize(s, SimTK::Stage::Dynamics);
        return system.calcEnergy(s);
    }
};

// Exact period of the simple pendulum at amplitude theta0: T = 4 sqrt(L/g) K(sin(theta0/2)).
double calcExactPeriod(double theta0) { return 4 * std::sqrt(Pendulum::L / g) * std::comp_ellint_1(std::sin(theta0 / 2)); }

struct PendulumRun {
    double periodError = 0;     // s, after `periods` exact periods
    double maxEnergyError = 0;  // relative to m g L
    IntegrationStatistics statistics;
};

// Integrates `periods` exact periods from rest at theta0. At t = n T the exact solution is back
// at rest at theta0; the numerical phase error there is -u/udot (one Newton step on u(t) = 0).
PendulumRun runPendulum(double rtol, double theta0, int periods) {
    Pendulum p;
    CvodeOptions options;
    options.relativeTolerance = rtol;
    CvodeIntegrator cvode(p.system, options);
    cvode.initialize(p.makeState(theta0));
    const double E0 = p.calcEnergy(cvode.getState()), T = calcExactPeriod(theta0);
    PendulumRun run;
    const int samplesPerPeriod = 40;
    for (int k = 1; k <= periods * samplesPerPeriod; ++k) {
        cvode.stepTo(k * T / samplesPerPeriod);
        const double E = p.calcEnergy(cvode.getState());
        run.maxEnergyError = std::max(run.maxEnergyError, std::abs(E - E0) / (Pendulum::m * g * Pendulum::L));
    }
    const SimTK::State& s = cvode.getState();
    p.system.realize(s, SimTK::Stage::Acceleration);
    run.periodError = std::abs(p.pin.getOneU(s, 0) / p.pin.getOneUDot(s, 0)) / periods;
    run.statistics = cvode.getStatistics();
    return run;
}

// Bounds from what the tolerance promises: CVODE keeps each step's local error e_i below
// rtol |y_i| + atol (atol = rtol here), so the global error after N steps is at most the sum,
// N rtol (1 + max|y|), when the errors do not grow (a pendulum is not exponentially unstable).
// And the global error of a variable-step method of order p >= 1 scales as tol^(p/(p+1)), so a
// 1000 x tighter tolerance must cut the error by at least sqrt(1000).
TEST(CvodeIntegratorTest, PendulumMatchesEllipticPeriodAndConservesEnergy) {
    const double theta0 = 2.5;  // rad (143 degrees): far from the small-angle period
    const int periods = 3;
    const double T = calcExactPeriod(theta0);
    ASSERT_GT(T, 1.5 * 2 * SimTK::Pi * std::sqrt(Pendulum::L / g));  // the amplitude matters
    const double maxSpeed = std::sqrt(2 * g / Pendulum::L * (1 - std::cos(theta0)));  // rad/s, at the bottom
    const double yScale = 1 + std::max(theta0, maxSpeed);
    std::vector<PendulumRun> runs;
    for (double rtol : {1e-5, 1e-8}) {
        runs.push_back(runPendulum(rtol, theta0, periods));
        const PendulumRun& r = runs.back();
        const double bound = static_cast<double>(r.statistics.steps) * rtol * yScale;
        EXPECT_LT(r.periodError / T, bound) << "rtol " << rtol;
        EXPECT_LT(r.maxEnergyError, bound) << "rtol " << rtol;
        EXPECT_GT(r.statistics.rhsEvaluations, r.statistics.steps);
        EXPECT_GT(r.statistics.jacobianEvaluations, 0);
        RecordProperty("period_error_rel_rtol_" + toText(rtol), toText(r.periodError / T));
        RecordProperty("energy_error_rel_rtol_" + toText(rtol), toText(r.maxEnergyError));
        RecordProperty("bound_rtol_" + toText(rtol), toText(bound));
        RecordProperty("steps_rtol_" + toText(rtol), toText(static_cast<double>(r.statistics.steps)));
    }
    EXPECT_GT(runs[0].periodError / runs[1].periodError, std::sqrt(1000.0));
    EXPECT_GT(runs[0].maxEnergyError / runs[1].maxEnergyError, std::sqrt(1000.0));
    EXPECT_GT(runs[1].statistics.steps, runs[0].statistics.steps);
}

// A second, independent integrator: Simbody's CPodes at the same accuracy must agree with CVODE
// on the pendulum angle within the sum of their global error bounds (N rtol (1 + max|y|) each,
// as above).
TEST(CvodeIntegratorTest, AgreesWithSimbodyCpodesOnPendulum) {
    const double rtol = 1e-6, theta0 = 2.0, tEnd = 2.0;
    Pendulum p;
    CvodeOptions options;
    options.relativeTolerance = rtol;
    CvodeIntegrator cvode(p.system, options);
    SimbodyCpodesStepper cpodes(p.system, rtol);
    cvode.initialize(p.makeState(theta0));
    cpodes.initialize(p.makeState(theta0));
    double maxDifference = 0;
    for (int k = 1; k <= 20; ++k) {
        cvode.stepTo(k * tEnd / 20);
        cpodes.stepTo(k * tEnd / 20);
        maxDifference = std::max(maxDifference, std::abs(p.pin.getOneQ(cvode.getState(), 0) - p.pin.getOneQ(cpodes.getState(), 0)));
    }
    const double maxSpeed = std::sqrt(2 * g / Pendulum::L * (1 - std::cos(theta0)));
    const long steps = cvode.getStatistics().steps + cpodes.getStatistics().steps;
    const double bound = static_cast<double>(steps) * rtol * (1 + std::max(theta0, maxSpeed));
    RecordProperty("max_angle_difference", toText(maxDifference));
    RecordProperty("bound", toText(bound));
    EXPECT_LT(maxDifference, bound);
    EXPECT_EQ(cvode.getMethodName(), "cvode-bdf");
    EXPECT_GT(cpodes.getStatistics().steps, 0);
}

// A spherical pendulum built as a Free body (6 dof) held by a Ball constraint to ground: the
// constraint manifold is |p_G(point)| = 0 for the body point at the rod's end.
struct BallPendulum {
    static constexpr double m = 1.0, L = 0.5;
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter{system};
    SimTK::GeneralForceSubsystem forces{system};
    SimTK::Force::Gravity gravity{forces, matter, SimTK::Vec3(0, -g, 0)};
    SimTK::MobilizedBody::Free body{matter.updGround(), SimTK::Transform(),
                                    SimTK::Body::Rigid(SimTK::MassProperties(m, SimTK::Vec3(0), SimTK::UnitInertia(0.01))),
                                    SimTK::Transform()};
    SimTK::Vec3 p_BP{0, L, 0};  // the pivot point on the body
    SimTK::Constraint::Ball ball{matter.updGround(), SimTK::Vec3(0), body, p_BP};

    // Tilted by theta0 about z with a sideways spin, so that it swings in 3D.
    SimTK::State makeState(double theta0) {
        SimTK::State s = system.realizeTopology();
        const SimTK::Rotation R_GB(theta0, SimTK::ZAxis);
        body.setQToFitTransform(s, SimTK::Transform(R_GB, -(R_GB * p_BP)));
        system.realize(s, SimTK::Stage::Position);
        body.setUToFitAngularVelocity(s, SimTK::Vec3(0, 2.0, 0));
        body.setUToFitLinearVelocity(s, -(SimTK::Vec3(0, 2.0, 0) % (R_GB * p_BP)));
        return s;
    }
    double findPositionError(const SimTK::State& s) const {
        system.realize(s, SimTK::Stage::Position);
        return body.findStationLocationInGround(s, p_BP).norm();
    }
    double findVelocityError(const SimTK::State& s) const {
        system.realize(s, SimTK::Stage::Velocity);
        return body.findStationVelocityInGround(s, p_BP).norm();
    }
};

struct ManifoldRun {
    double maxPositionError = 0, maxVelocityError = 0;  // m, m/s
    long projections = 0;
};

ManifoldRun runBallPendulum(bool projection, double rtol, double duration) {
    BallPendulum p;
    CvodeOptions options;
    options.relativeTolerance = rtol;
    options.projection = projection;
    CvodeIntegrator cvode(p.system, options);
    cvode.initialize(p.makeState(1.2));
    ManifoldRun run;
    for (int k = 1; k <= 200; ++k) {
        cvode.stepTo(k * duration / 200);
        run.maxPositionError = std::max(run.maxPositionError, p.findPositionError(cvode.getState()));
        run.maxVelocityError = std::max(run.maxVelocityError, p.findVelocityError(cvode.getState()));
    }
    run.projections = cvode.getStatistics().projections;
    return run;
}

// With projection, every step ends on the manifold to the constraint tolerance (Simbody's RMS
// norm of the 3 weighted position errors is at most their Euclidean norm / sqrt(3) <= tol, so
// the Euclidean error is at most sqrt(3) tol, with unit length and time scales).
TEST(CvodeIntegratorTest, ProjectionKeepsConstrainedSystemOnManifold) {
    const double rtol = 1e-6, duration = 10;
    const ManifoldRun on = runBallPendulum(true, rtol, duration);
    RecordProperty("max_position_error_projected", toText(on.maxPositionError));
    RecordProperty("max_velocity_error_projected", toText(on.maxVelocityError));
    EXPECT_GT(on.projections, 0);
    EXPECT_LE(on.maxPositionError, std::sqrt(3.0) * rtol);
    EXPECT_LE(on.maxVelocityError, std::sqrt(3.0) * rtol);
    // Without projection the acceleration-level constraint lets position errors drift.
    const ManifoldRun off = runBallPendulum(false, rtol, duration);
    RecordProperty("max_position_error_unprojected", toText(off.maxPositionError));
    EXPECT_EQ(off.projections, 0);
    EXPECT_GT(off.maxPositionError, on.maxPositionError);
}

// A body falling along a Slider (y up), with a witness h(q) = y - floor that triggers on the
// falling transition; the handler bounces it (u -> -e u), which changes the state and makes
// CVODE restart.
class FloorHandler : public SimTK::TriggeredEventHandler {
public:
    FloorHandler(const SimTK::MobilizedBody::Slider& body, double floor, double restitution)
        : SimTK::TriggeredEventHandler(SimTK::Stage::Position), body_(body), floor_(floor), restitution_(restitution) {
        getTriggerInfo().setTriggerOnRisingSignTransition(false);
    }
    SimTK::Real getValue(const SimTK::State& s) const override { return body_.getOneQ(s, 0) - floor_; }
    void handleEvent(SimTK::State& s, SimTK::Real, bool&) const override {
        times.push_back(s.getTime());
        witnessAtEvent.push_back(getValue(s));
        body_.setOneU(s, 0, -restitution_ * body_.getOneU(s, 0));
    }
    mutable std::vector<double> times, witnessAtEvent;

private:
    const SimTK::MobilizedBody::Slider& body_;
    double floor_, restitution_;
};

class PeriodicRecorder : public SimTK::PeriodicEventHandler {
public:
    explicit PeriodicRecorder(double interval) : SimTK::PeriodicEventHandler(interval) {}
    void handleEvent(SimTK::State& s, SimTK::Real, bool&) const override { times.push_back(s.getTime()); }
    mutable std::vector<double> times;
};

struct FallingBody {
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter{system};
    SimTK::GeneralForceSubsystem forces{system};
    SimTK::Force::Gravity gravity{forces, matter, SimTK::Vec3(0, -g, 0)};
    // The Slider translates along its frames' x axis: turn x to point up (y).
    SimTK::MobilizedBody::Slider body{matter.updGround(), SimTK::Transform(SimTK::Rotation(SimTK::Pi / 2, SimTK::ZAxis)),
                                      SimTK::Body::Rigid(SimTK::MassProperties(0.3, SimTK::Vec3(0), SimTK::UnitInertia(1))),
                                      SimTK::Transform(SimTK::Rotation(SimTK::Pi / 2, SimTK::ZAxis))};
    FloorHandler* floor = nullptr;        // owned by the system
    PeriodicRecorder* periodic = nullptr;  // owned by the system

    FallingBody(double floorHeight, double restitution, double interval) {
        floor = new FloorHandler(body, floorHeight, restitution);
        periodic = new PeriodicRecorder(interval);
        system.addEventHandler(floor);
        system.addEventHandler(periodic);
    }
};

// Oracle: free fall from h0 at rest reaches the floor hf at t1 = sqrt(2 (h0 - hf) / g) with
// speed v1 = g t1; after the bounce (speed e v1 up) it is back at t2 = t1 + 2 e v1 / g.
// The time error is the height error over the speed; the height error is bounded by the
// integration tolerance (100 x (rtol |y| + atol), as in the pendulum test).
TEST(CvodeIntegratorTest, TriggeredEventLandsAtAnalyticRoot) {
    const double h0 = 2.0, hf = 0.5, e = 0.6, rtol = 1e-8, interval = 0.1;
    FallingBody fall(hf, e, interval);
    SimTK::State s = fall.system.realizeTopology();
    fall.body.setOneQ(s, 0, h0);
    CvodeOptions options;
    options.relativeTolerance = rtol;
    CvodeIntegrator cvode(fall.system, options);
    cvode.initialize(s);
    const double t1 = std::sqrt(2 * (h0 - hf) / g), v1 = g * t1, t2 = t1 + 2 * e * v1 / g;
    cvode.stepTo(t2 + 0.05);
    ASSERT_EQ(fall.floor->times.size(), 2u);
    const double heightTolerance = 100 * (rtol * h0 + rtol);
    EXPECT_NEAR(fall.floor->times[0], t1, heightTolerance / v1);
    EXPECT_NEAR(fall.floor->times[1], t2, heightTolerance / (e * v1));
    RecordProperty("first_impact_time_error", toText(fall.floor->times[0] - t1));
    RecordProperty("second_impact_time_error", toText(fall.floor->times[1] - t2));
    // CVODE's own root localization: the witness at the reported time is within its time
    // tolerance (100 x machine epsilon x max(t, h), with t and h below 10 s here) times the
    // witness rate (at most v1).
    for (std::size_t k = 0; k < 2; ++k) {
        EXPECT_LE(std::abs(fall.floor->witnessAtEvent[k]), v1 * 100 * DBL_EPSILON * 10) << "impact " << k;
    }
    EXPECT_EQ(cvode.getStatistics().triggeredEvents, 2);
}

TEST(CvodeIntegratorTest, ScheduledEventsFireAtTheirExactTimes) {
    const double interval = 0.1;
    FallingBody fall(-1e9, 1, interval);  // a floor it never reaches
    CvodeIntegrator cvode(fall.system);
    cvode.initialize(fall.system.realizeTopology());
    cvode.stepTo(0.55);
    cvode.stepTo(1.0);
    cvode.stepTo(1.05);  // the event due at 1.0 fires at the start of this call
    // Events at 0, 0.1, ..., 1.0: the periodic handler's own times k * interval, exactly.
    ASSERT_EQ(fall.periodic->times.size(), 11u);
    for (std::size_t k = 0; k < fall.periodic->times.size(); ++k) {
        EXPECT_EQ(fall.periodic->times[k], static_cast<double>(k) * interval) << "event " << k;
    }
    EXPECT_EQ(cvode.getState().getTime(), 1.05);
}

// A change the caller makes between stepTo() calls is noticed: CVODE restarts from it.
TEST(CvodeIntegratorTest, RestartsAfterCallerChangesTheState) {
    FallingBody fall(-1e9, 1, 1e9);
    CvodeOptions options;
    options.relativeTolerance = 1e-9;
    CvodeIntegrator cvode(fall.system, options);
    cvode.initialize(fall.system.realizeTopology());
    cvode.stepTo(0.5);
    const long restarts = cvode.getStatistics().restarts;
    fall.body.setOneU(cvode.updState(), 0, 3.0);  // kick upwards at t = 0.5
    cvode.stepTo(1.0);
    EXPECT_EQ(cvode.getStatistics().restarts, restarts + 1);
    const double y = -0.5 * g * 0.25 + 3.0 * 0.5 - 0.5 * g * 0.25;  // y(0.5) + 3 t - g t^2 / 2, t = 0.5
    EXPECT_NEAR(fall.body.getOneQ(cvode.getState(), 0), y, 1e-6);
}

// A force that fails after t = 0.2 s: CVODE cannot step on, and says when and why.
class FailingForce : public SimTK::Force::Custom::Implementation {
public:
    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                   SimTK::Vector&) const override {
        if (s.getTime() > 0.2) throw std::runtime_error("force model failed");
    }
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
};

TEST(CvodeIntegratorTest, FailureThrowsNumericalErrorWithTimeAndFlag) {
    Pendulum p;
    SimTK::Force::Custom failing(p.forces, new FailingForce);
    // CVODE retries a failed evaluation with a smaller step, creeping towards 0.2 s; a step
    // budget ends the creep.
    CvodeOptions options;
    options.maxStepsPerInterval = 2000;
    CvodeIntegrator cvode(p.system, options);
    cvode.initialize(p.makeState(1.0));
    try {
        cvode.stepTo(1.0);
        FAIL() << "no exception";
    } catch (const NumericalError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("t = 0.2"), std::string::npos) << what;  // to_string: 6 decimals
        EXPECT_NE(what.find("CV_"), std::string::npos) << what;
        EXPECT_NE(what.find("force model failed"), std::string::npos) << what;
    }
}

TEST(CvodeIntegratorTest, RejectsBadOptions) {
    Pendulum p;
    CvodeOptions options;
    options.relativeTolerance = 0;
    EXPECT_THROW(CvodeIntegrator(p.system, options), InputError);
    options = CvodeOptions{};
    options.maxOrder = 6;
    EXPECT_THROW(CvodeIntegrator(p.system, options), InputError);
}

}  // namespace
}  // namespace graspsim::integration
