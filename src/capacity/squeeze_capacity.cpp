#include "graspsim/capacity/squeeze_capacity.h"

#include "graspsim/contact/compliant_contact_force.h"
#include "graspsim/contact/compliant_contact_jacobian.h"
#include "graspsim/contact/rigid_contact.h"
#include "graspsim/contact/rigid_impulse_solver.h"
#include "graspsim/error.h"
#include "graspsim/integration/linearly_implicit_stepper.h"
#include "graspsim/system/silenced_stdout.h"

#include <cmath>

namespace graspsim::capacity {

namespace {

constexpr double kRadius = 0.01;     // m, spheres
constexpr double kHalfWidth = 0.02;  // m, box half-width along x
constexpr double kEStar = 1e6;       // Pa, effective Young's modulus (compliant)
constexpr double kRigidStep = 1e-3;  // s, the rigid stepper's fixed step
constexpr double kReferenceAccuracy = 1e-7;
// A scenario's defaults (scenario::SimulationSpec), so the case checks what a run uses.
constexpr double kImplicitAccuracy = 1e-3;

class SqueezeRun : public LoadedRun {
public:
    SqueezeRun(const SqueezeCase& c, const simulation::LoadRampSpec& load) : case_(c) {
        box_ = addSlider(SimTK::YAxis, c.boxMass, 0.05);
        left_ = addSlider(SimTK::XAxis, 0.05, kRadius);
        right_ = addSlider(SimTK::XAxis, 0.05, kRadius);
        SimTK::Force::MobilityConstantForce(forces_, left_, 0, c.press);
        SimTK::Force::MobilityConstantForce(forces_, right_, 0, -c.press);
        load_ = std::make_unique<simulation::RampLoad>(forces_, box_, load);
        if (c.rigid) {
            startRigid();
        } else {
            startCompliant(load.start);
        }
    }

    void advanceTo(double t) override {
        if (implicit_) {
            implicit_->stepTo(t);
            return;
        }
        if (!case_.rigid) {
            timeStepper_->stepTo(t);
            return;
        }
        // Fixed steps; the last one shortened to land on t.
        const system::SilencedStdout quiet;  // Debian's Simbody traces every rigid step on stdout
        while (rigid_->getState().getTime() < t - 1e-12) rigid_->stepTo(std::min(t, rigid_->getState().getTime() + kRigidStep));
    }
    void captureReference() override { reference_ = box_.getOneQ(getState(), 0); }
    CapacitySample sampleNow() override {
        CapacitySample s;
        s.slip = std::abs(box_.getOneQ(getState(), 0) - reference_);
        if (!case_.rigid) s.gripForce = calcGripForce();
        return s;
    }

private:
    const SimTK::State& getState() const {
        if (implicit_) return implicit_->getState();
        return case_.rigid ? rigid_->getState() : timeStepper_->getState();
    }

    double calcGripForce() const {
        const SimTK::State& s = getState();
        system_.realize(s, SimTK::Stage::Velocity);
        return contact::sumNormalForces(contacts_.findContactReports(s));
    }

    // A Slider translates along its frames' x axis: x is turned onto the wanted Ground axis.
    SimTK::MobilizedBody::Slider addSlider(SimTK::CoordinateAxis axis, double mass, double radius) {
        const SimTK::Rotation R_GF(SimTK::UnitVec3(axis), SimTK::XAxis);
        const SimTK::Body::Rigid body(SimTK::MassProperties(mass, SimTK::Vec3(0), SimTK::UnitInertia::sphere(radius)));
        return SimTK::MobilizedBody::Slider(matter_.updGround(), SimTK::Transform(R_GF), body, SimTK::Transform(R_GF));
    }

    std::vector<contact::ContactPair> makePairs() const {
        contact::ContactParameters p;
        p.effectiveStiffness = kEStar;
        p.dissipation = 5;
        p.staticFriction = p.dynamicFriction = case_.mu;
        p.viscousFriction = 0;
        p.transitionVelocity = case_.transitionVelocity;
        const contact::ContactShape ball = contact::ContactShape::sphere(kRadius);
        const contact::ContactSurface b{box_, "box", "box", contact::ContactShape::box(SimTK::Vec3(kHalfWidth, 0.5, 0.02)),
                                        SimTK::Transform()};
        return {{{left_, "left", "ball", ball, SimTK::Transform()}, b, p}, {{right_, "right", "ball", ball, SimTK::Transform()}, b, p}};
    }

    // Spheres touching the box at `depth` (m) of overlap each.
    SimTK::State makeState(double depth) {
        SimTK::State s = system_.realizeTopology();
        left_.setOneQ(s, 0, -(kHalfWidth + kRadius - depth));
        right_.setOneQ(s, 0, kHalfWidth + kRadius - depth);
        system_.realize(s, SimTK::Stage::Position);
        return s;
    }

    // Starts at the static Hertz depth for N, so the squeeze is in equilibrium from the start.
    // The implicit stepper lands on the load's start, as a scene's does (scene_stepper.cpp): a
    // constant load jumps on there, and no step may straddle the jump.
    void startCompliant(double loadStart) {
        contacts_ = contact::CompliantContactForce(forces_, makePairs());
        const double depth = std::pow(3 * case_.press / (4 * kEStar * std::sqrt(kRadius)), 2.0 / 3.0);
        if (case_.integrator == SqueezeIntegrator::LinearlyImplicit) {
            jacobian_ = std::make_unique<contact::CompliantContactJacobian>(matter_, contacts_);
            integration::LinearlyImplicitOptions options;
            options.stepSize = case_.implicitStepCap;
            options.accuracy = kImplicitAccuracy;
            options.landingTimes = {loadStart};
            implicit_ = std::make_unique<integration::LinearlyImplicitStepper>(
                system_, std::vector<const integration::ForceJacobianContributor*>{jacobian_.get()}, options);
            implicit_->initialize(makeState(depth));
            return;
        }
        integrator_ = std::make_unique<SimTK::RungeKuttaMersonIntegrator>(system_);
        integrator_->setAccuracy(kReferenceAccuracy);
        timeStepper_ = std::make_unique<SimTK::TimeStepper>(system_, *integrator_);
        timeStepper_->initialize(makeState(depth));
    }

    void startRigid() {
        for (const contact::ContactPair& p : makePairs()) contact::RigidContact::add(matter_, p);
        rigid_ = std::make_unique<SimTK::SemiExplicitEulerTimeStepper>(system_);
        rigid_->setImpulseSolverType(SimTK::SemiExplicitEulerTimeStepper::PGS);
        rigid_->setImpulseSolver(new contact::RigidImpulseSolver());  // the same PGS, without Debian's debug work
        rigid_->initialize(makeState(0));
    }

    SqueezeCase case_;
    SimTK::MultibodySystem system_;
    SimTK::SimbodyMatterSubsystem matter_{system_};
    SimTK::GeneralForceSubsystem forces_{system_};
    SimTK::MobilizedBody::Slider box_, left_, right_;
    std::unique_ptr<simulation::RampLoad> load_;
    contact::CompliantContactForce contacts_;
    std::unique_ptr<SimTK::RungeKuttaMersonIntegrator> integrator_;
    std::unique_ptr<SimTK::TimeStepper> timeStepper_;
    std::unique_ptr<SimTK::SemiExplicitEulerTimeStepper> rigid_;
    std::unique_ptr<contact::CompliantContactJacobian> jacobian_;
    std::unique_ptr<integration::LinearlyImplicitStepper> implicit_;
    double reference_ = 0;
};

}  // namespace

LoadedRunFactory makeSqueezeRuns(const SqueezeCase& squeeze) {
    return [squeeze](const simulation::LoadRampSpec& load) -> std::unique_ptr<LoadedRun> {
        if (load.torque || std::abs(std::abs(load.direction[1]) - 1) > 1e-12) {
            throw InputError("squeeze capacity: the load must be a force along +y or -y (the box's slider)");
        }
        return std::make_unique<SqueezeRun>(squeeze, load);
    };
}

}  // namespace graspsim::capacity
