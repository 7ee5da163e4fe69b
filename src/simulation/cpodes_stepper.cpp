#include "cpodes_stepper.h"

namespace graspsim::simulation {

CpodesStepper::CpodesStepper(const SimTK::System& system, double accuracy) : system_(system), accuracy_(accuracy) {}

void CpodesStepper::initialize(const SimTK::State& state) {
    stepper_.reset();  // it refers to the old integrator
    integrator_ = std::make_unique<SimTK::CPodesIntegrator>(system_, SimTK::CPodes::BDF, SimTK::CPodes::Newton);
    integrator_->setAccuracy(accuracy_);
    stepper_ = std::make_unique<SimTK::TimeStepper>(system_, *integrator_);
    stepper_->initialize(state);
}

void CpodesStepper::stepTo(double t) { stepper_->stepTo(t); }

const SimTK::State& CpodesStepper::getState() const { return stepper_->getState(); }

long CpodesStepper::getNumStepsTaken() const { return integrator_->getNumStepsTaken(); }

}  // namespace graspsim::simulation
