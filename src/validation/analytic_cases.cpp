#include "graspsim/validation/analytic_cases.h"

#include "graspsim/contact/compliant_contact_force.h"
#include "graspsim/contact/rigid_contact.h"
#include "graspsim/contact/rigid_impulse_solver.h"
#include "graspsim/system/silenced_stdout.h"

#include <simbody/Simbody.h>

#include <cmath>

namespace graspsim::validation {

namespace {

constexpr double kRadius = 0.01;     // m, spheres
constexpr double kHalfWidth = 0.02;  // m, box half-width along x
constexpr double kEStar = 1e6;       // Pa, effective Young's modulus (compliant)

struct SqueezeScene {
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter{system};
    SimTK::GeneralForceSubsystem forces{system};
    SimTK::MobilizedBody::Slider box, left, right;

    explicit SqueezeScene(double pull) {
        box = addSlider(SimTK::YAxis, kSqueezeBoxMass, 0.05);
        left = addSlider(SimTK::XAxis, 0.05, kRadius);
        right = addSlider(SimTK::XAxis, 0.05, kRadius);
        SimTK::Force::MobilityConstantForce(forces, left, 0, kSqueezePress);
        SimTK::Force::MobilityConstantForce(forces, right, 0, -kSqueezePress);
        SimTK::Force::MobilityConstantForce(forces, box, 0, pull);
    }

    // A Slider translates along its frames' x axis: x is turned onto the wanted Ground axis.
    SimTK::MobilizedBody::Slider addSlider(SimTK::CoordinateAxis axis, double mass, double radius) {
        const SimTK::Rotation R_GF(SimTK::UnitVec3(axis), SimTK::XAxis);
        const SimTK::Body::Rigid body(SimTK::MassProperties(mass, SimTK::Vec3(0), SimTK::UnitInertia::sphere(radius)));
        return SimTK::MobilizedBody::Slider(matter.updGround(), SimTK::Transform(R_GF), body, SimTK::Transform(R_GF));
    }

    std::vector<contact::ContactPair> makePairs(const contact::ContactParameters& p) const {
        const contact::ContactShape ball = contact::ContactShape::sphere(kRadius);
        const contact::ContactSurface b{box, "box", "box", contact::ContactShape::box(SimTK::Vec3(kHalfWidth, 0.5, 0.02)),
                                        SimTK::Transform()};
        return {{{left, "left", "ball", ball, SimTK::Transform()}, b, p}, {{right, "right", "ball", ball, SimTK::Transform()}, b, p}};
    }

    // Spheres touching the box at `depth` (m) of overlap each.
    SimTK::State makeState(double depth) {
        SimTK::State s = system.realizeTopology();
        left.setOneQ(s, 0, -(kHalfWidth + kRadius - depth));
        right.setOneQ(s, 0, kHalfWidth + kRadius - depth);
        system.realize(s, SimTK::Stage::Position);
        return s;
    }
};

contact::ContactParameters makeParameters() {
    contact::ContactParameters p;
    p.effectiveStiffness = kEStar;
    p.dissipation = 5;
    p.staticFriction = p.dynamicFriction = kSqueezeMu;
    p.viscousFriction = 0;
    p.transitionVelocity = kSqueezeTransition;
    return p;
}

SqueezeOutcome runCompliantSqueeze(double pull, double duration) {
    SqueezeScene scene(pull);
    const contact::CompliantContactForce force(scene.forces, scene.makePairs(makeParameters()));
    // Start at the static Hertz depth for N so the squeeze is in equilibrium from the start.
    const double depth = std::pow(3 * kSqueezePress / (4 * kEStar * std::sqrt(kRadius)), 2.0 / 3.0);
    SimTK::RungeKuttaMersonIntegrator integrator(scene.system);
    integrator.setAccuracy(1e-7);
    SimTK::TimeStepper stepper(scene.system, integrator);
    stepper.initialize(scene.makeState(depth));
    const double window = 0.2 * duration;
    stepper.stepTo(duration - window);
    const double v0 = scene.box.getOneU(stepper.getState(), 0);
    stepper.stepTo(duration);
    return {(scene.box.getOneU(stepper.getState(), 0) - v0) / window, scene.box.getOneQ(stepper.getState(), 0)};
}

SqueezeOutcome runRigidSqueeze(double pull, double duration) {
    SqueezeScene scene(pull);
    for (const contact::ContactPair& p : scene.makePairs(makeParameters())) contact::RigidContact::add(scene.matter, p);
    SimTK::SemiExplicitEulerTimeStepper stepper(scene.system);
    stepper.setImpulseSolverType(SimTK::SemiExplicitEulerTimeStepper::PGS);
    stepper.setImpulseSolver(new contact::RigidImpulseSolver());  // the same PGS, without Debian's debug work
    stepper.initialize(scene.makeState(0));
    const system::SilencedStdout quiet;  // Debian's Simbody traces every rigid step on stdout
    constexpr double h = 1e-3;
    const int steps = static_cast<int>(std::lround(duration / h)), windowSteps = steps / 5;
    double v0 = 0;
    for (int k = 1; k <= steps; ++k) {
        stepper.stepTo(k * h);
        if (k == steps - windowSteps) v0 = scene.box.getOneU(stepper.getState(), 0);
    }
    return {(scene.box.getOneU(stepper.getState(), 0) - v0) / (windowSteps * h), scene.box.getOneQ(stepper.getState(), 0)};
}

}  // namespace

SqueezeOutcome runSqueeze(bool rigid, double pull, double duration) {
    return rigid ? runRigidSqueeze(pull, duration) : runCompliantSqueeze(pull, duration);
}

PendulumOutcome runPendulum(double amplitude, double accuracy) {
    constexpr double L = 1.0, g = 9.81, mass = 1.0;
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter(system);
    SimTK::GeneralForceSubsystem forces(system);
    SimTK::Force::UniformGravity(forces, matter, SimTK::Vec3(0, -g, 0));
    // Pin about z; the point mass hangs L below the joint.
    const SimTK::Body::Rigid bob(SimTK::MassProperties(mass, SimTK::Vec3(0), SimTK::Inertia(0)));
    SimTK::MobilizedBody::Pin rod(matter.updGround(), SimTK::Transform(), bob, SimTK::Transform(SimTK::Vec3(0, L, 0)));
    SimTK::State s = system.realizeTopology();
    rod.setOneQ(s, 0, amplitude);
    SimTK::RungeKuttaMersonIntegrator integrator(system);
    integrator.setAccuracy(accuracy);
    SimTK::TimeStepper stepper(system, integrator);
    stepper.initialize(s);
    // Upward zero crossings of the angle, by linear interpolation between 1 ms samples: at the
    // crossing the angular acceleration -g/L sin(q) vanishes, so the interpolation error is
    // third order in the sample interval (~1e-10 s here).
    std::vector<double> crossings;
    double tPrev = 0, qPrev = amplitude;
    for (int k = 1; k <= 20000 && crossings.size() < 2; ++k) {
        const double t = k * 1e-3;
        stepper.stepTo(t);
        const double q = rod.getOneQ(stepper.getState(), 0);
        if (qPrev < 0 && q >= 0) crossings.push_back(tPrev + (t - tPrev) * (-qPrev) / (q - qPrev));
        tPrev = t;
        qPrev = q;
    }
    PendulumOutcome out;
    out.exact = 4 * std::sqrt(L / g) * std::comp_ellint_1(std::sin(amplitude / 2));
    out.measured = crossings.size() >= 2 ? crossings.back() - crossings[crossings.size() - 2] : 0;
    return out;
}

std::vector<ValidationCheck> runAnalyticCases() {
    std::vector<ValidationCheck> checks;
    const double limit = 2 * kSqueezeMu * kSqueezePress;  // N
    const auto add = [&](const std::string& name, double value, const std::string& relation, double bound, const std::string& unit,
                         const std::string& source) {
        const bool pass = relation == "<=" ? value <= bound : value >= bound;
        checks.push_back({"analytic", name, value, bound, unit, relation, pass, source});
    };
    for (bool rigid : {false, true}) {
        const std::string model = rigid ? "rigid" : "compliant";
        const double duration = 0.3;
        const SqueezeOutcome held = runSqueeze(rigid, 0.8 * limit, duration);
        // Compliant: regularized friction creeps, at most at v_t F / (2 mu N) (the steady creep speed,
        // approached from rest; 0.1 % for the integrator's error); rigid: PGS's own creep, 1e-5 m.
        const double creep = rigid ? 1e-5 : kSqueezeTransition * 0.8 * duration * 1.001;
        add("two-finger friction, " + model + ": displacement at F = 0.8 x 2 mu N", std::abs(held.displacement) * 1e3, "<=",
            creep * 1e3, "mm", "Coulomb friction of two contacts: sticks below 2 mu N (thesis eq. 4.1)");
        const SqueezeOutcome slid = runSqueeze(rigid, 1.5 * limit, duration);
        const double expected = 0.5 * limit / kSqueezeBoxMass;
        add("two-finger friction, " + model + ": acceleration's relative error vs (F - 2 mu N) / m at F = 1.5 x 2 mu N",
            std::abs(slid.acceleration / expected - 1) * 100, "<=", 5, "%", "closed form a = (F - 2 mu N) / m; 5 % for the regularized friction's transition");
    }
    const PendulumOutcome p = runPendulum(SimTK::Pi / 3, 1e-8);
    add("pendulum (60 deg) period vs 4 sqrt(L/g) K(sin(theta0/2)), relative error", std::abs(p.measured / p.exact - 1) * 100, "<=",
        1e-3, "%", "closed form (elliptic integral); at accuracy 1e-8 the integrator stays far below 1e-3 %");
    return checks;
}

}  // namespace graspsim::validation
