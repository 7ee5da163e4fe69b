#include "graspsim/integration/simbody_stepper.h"

namespace graspsim::integration {

SimbodyCpodesStepper::SimbodyCpodesStepper(const SimTK::System& system, double accuracy)
    : integrator_(system, SimTK::CPodes::BDF, SimTK::CPodes::Newton), stepper_(system, integrator_) {
    integrator_.setAccuracy(accuracy);
}

// Simbody's initialize() zeroes the integrator's counters: bank them first.
void SimbodyCpodesStepper::initialize(const SimTK::State& initial) {
    if (initialized_) addCurrentCountsTo(totals_);
    stepper_.initialize(initial);
    initialized_ = true;
}

void SimbodyCpodesStepper::stepTo(double time) { stepper_.stepTo(time); }

void SimbodyCpodesStepper::addCurrentCountsTo(IntegrationStatistics& s) const {
    s.steps += integrator_.getNumStepsTaken();
    s.rhsEvaluations += integrator_.getNumRealizations();
    s.errorTestFailures += integrator_.getNumErrorTestFailures();
    s.convergenceFailures += integrator_.getNumConvergenceTestFailures();
    s.projections += integrator_.getNumProjections();
}

IntegrationStatistics SimbodyCpodesStepper::getStatistics() const {
    IntegrationStatistics all = totals_;
    if (initialized_) addCurrentCountsTo(all);
    return all;
}

}  // namespace graspsim::integration
