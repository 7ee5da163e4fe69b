#pragma once
// The grasp simulations' time stepper: Simbody's TimeStepper on a CPodesIntegrator (BDF, Newton;
// the finger joints are stiff). initialize() may be called again after an Instance-stage change
// (the object's release) and then starts on a new integrator: Simbody 3.7's CPodes::init
// allocates the integrator's vectors anew on every call without freeing those of the previous
// one (CPodeInit -> cpAllocVectors), which leaked about 8 kB per restart in a parameter sweep
// (tests/simulation/grasp_simulation_sweep_test.cpp).

#include <SimTKmath.h>

#include <memory>

namespace graspsim::simulation {

class CpodesStepper {
public:
    /// `accuracy` is the integrator's relative accuracy.
    CpodesStepper(const SimTK::System& system, double accuracy);

    /// Starts (or restarts) integration from `state` on a new integrator.
    void initialize(const SimTK::State& state);
    /// Integrates to time t (s); event handlers run on the way.
    void stepTo(double t);
    const SimTK::State& getState() const;
    /// Integrator steps since the last initialize().
    long getNumStepsTaken() const;

private:
    const SimTK::System& system_;
    double accuracy_;
    std::unique_ptr<SimTK::CPodesIntegrator> integrator_;
    std::unique_ptr<SimTK::TimeStepper> stepper_;  // refers to *integrator_
};

}  // namespace graspsim::simulation
