#pragma once
// What the limited-bushing and limited-weld dynamics tests share: the integrators they run on, a
// run driven by a TimeStepper (it runs the elements' event handlers; a bare Integrator::stepTo()
// returns early at the start of each continuous interval), and the angle of a planar rotation.

#include <simbody/Simbody.h>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace graspsim::grasp::test {

enum class IntegratorKind { RungeKuttaMerson, CPodes };

/// A TimeStepper over an integrator of `kind` at `accuracy`; with allowInterpolation false every
/// step ends where the stepper asks (at load switches, say).
class SteppedRun {
public:
    SteppedRun(IntegratorKind kind, const SimTK::MultibodySystem& system, const SimTK::State& initial, double accuracy = 1e-6,
               bool allowInterpolation = true) {
        if (kind == IntegratorKind::CPodes) {
            integrator_ = std::make_unique<SimTK::CPodesIntegrator>(system, SimTK::CPodes::BDF, SimTK::CPodes::Newton);
        } else {
            integrator_ = std::make_unique<SimTK::RungeKuttaMersonIntegrator>(system);
        }
        integrator_->setAccuracy(accuracy);
        integrator_->setAllowInterpolation(allowInterpolation);
        stepper_ = std::make_unique<SimTK::TimeStepper>(system, *integrator_);
        stepper_->initialize(initial);
    }
    /// Steps to t (s), checking that it got there exactly.
    const SimTK::State& stepTo(double t) {
        stepper_->stepTo(t);
        EXPECT_DOUBLE_EQ(stepper_->getTime(), t);
        return stepper_->getState();
    }

private:
    std::unique_ptr<SimTK::Integrator> integrator_;
    std::unique_ptr<SimTK::TimeStepper> stepper_;
};

/// Angle (rad) of a rotation about Ground's z axis.
inline double calcAngleAboutZ(const SimTK::Rotation& R_GB) {
    return std::atan2(R_GB.asMat33()(1, 0), R_GB.asMat33()(0, 0));
}

}  // namespace graspsim::grasp::test
