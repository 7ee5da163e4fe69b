#pragma once
/// @file
/// Simbody's own implicit integrator behind the Stepper interface: CPodes (variable-order BDF,
/// Newton iteration) driven by SimTK::TimeStepper. The default of grasp simulations, whose
/// finger joints are stiff (µs time constants).

#include "graspsim/integration/stepper.h"
#include "graspsim/io/filtered_stderr.h"

#include <simbody/Simbody.h>

#include <memory>

namespace graspsim::integration {

/// SimTK::TimeStepper with SimTK::CPodesIntegrator(BDF, Newton). The System must outlive it.
/// initialize() (again after an Instance-stage change, e.g. the object's release) starts on a
/// NEW integrator: Simbody 3.7's CPodes::init allocates the integrator's vectors anew on every
/// call without freeing those of the previous one (CPodeInit -> cpAllocVectors), which leaked
/// about 8 kB per restart in parameter sweeps (tests/integration/simbody_stepper_test.cpp).
///
/// CPodes prints its own "[CPODES ERROR]" block to stderr when it gives up, before the exception
/// that graspsim turns into one line; stepTo() keeps it off the terminal with an io::FilteredStderr
/// that lives from the first stepTo() until the stepper is destroyed or a step throws (setting one
/// up per step cost 1-2 % of an engaged run). Anything else written to stderr meanwhile is passed on
/// at the end of the next stepTo().
class SimbodyCpodesStepper : public Stepper {
public:
    /// `accuracy`: Simbody's integrator accuracy (relative, also the constraint tolerance).
    SimbodyCpodesStepper(const SimTK::System& system, double accuracy);

    void initialize(const SimTK::State& initial) override;
    void stepTo(double time) override;
    const SimTK::State& getState() const override { return stepper_->getState(); }
    long getNumStepsTaken() const override { return integrator_->getNumStepsTaken(); }
    IntegrationStatistics getStatistics() const override;
    std::string getMethodName() const override { return "simbody-cpodes-bdf"; }

private:
    void addCurrentCountsTo(IntegrationStatistics& statistics) const;

    void makeIntegrator();

    const SimTK::System& system_;
    double accuracy_;
    std::unique_ptr<SimTK::CPodesIntegrator> integrator_;
    std::unique_ptr<SimTK::TimeStepper> stepper_;  // refers to *integrator_
    IntegrationStatistics totals_;  // of the runs before the last initialize()
    bool initialized_ = false;
    std::unique_ptr<io::FilteredStderr> quiet_;  // see the class comment
};

}  // namespace graspsim::integration
