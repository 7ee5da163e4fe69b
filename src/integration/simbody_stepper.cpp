#include "graspsim/integration/simbody_stepper.h"

namespace graspsim::integration {

SimbodyCpodesStepper::SimbodyCpodesStepper(const SimTK::System& system, double accuracy)
    : system_(system), accuracy_(accuracy) {
    makeIntegrator();
}

void SimbodyCpodesStepper::makeIntegrator() {
    stepper_.reset();  // it refers to the old integrator
    integrator_ = std::make_unique<SimTK::CPodesIntegrator>(system_, SimTK::CPodes::BDF, SimTK::CPodes::Newton);
    integrator_->setAccuracy(accuracy_);
    stepper_ = std::make_unique<SimTK::TimeStepper>(system_, *integrator_);
}

// A restart begins on a new integrator (see the header): bank the old one's counters first.
void SimbodyCpodesStepper::initialize(const SimTK::State& initial) {
    if (initialized_) {
        addCurrentCountsTo(totals_);
        makeIntegrator();
    }
    stepper_->initialize(initial);
    initialized_ = true;
}

void SimbodyCpodesStepper::stepTo(double time) {
    if (!quiet_) quiet_ = std::make_unique<io::FilteredStderr>(std::vector<std::string>{"[CPODES ERROR]", "[CPODES WARNING]"});
    try {
        stepper_->stepTo(time);
    } catch (...) {
        quiet_.reset();  // stderr back before the caller reports the failure
        throw;
    }
    quiet_->forward();
}

void SimbodyCpodesStepper::addCurrentCountsTo(IntegrationStatistics& s) const {
    s.steps += integrator_->getNumStepsTaken();
    s.rhsEvaluations += integrator_->getNumRealizations();
    s.errorTestFailures += integrator_->getNumErrorTestFailures();
    s.convergenceFailures += integrator_->getNumConvergenceTestFailures();
    s.projections += integrator_->getNumProjections();
}

IntegrationStatistics SimbodyCpodesStepper::getStatistics() const {
    IntegrationStatistics all = totals_;
    if (initialized_) addCurrentCountsTo(all);
    return all;
}

}  // namespace graspsim::integration
