#pragma once
// Dense output of the linearly implicit stepper: the State it shows at a report or scheduled event
// inside its last step, interpolated there (StepInterpolation, cubic Hermite from both ends), and
// the Report-stage variables a scheduled event handled on that State may hand on to the
// integrator's own.

#include "step_interpolation.h"

#include "graspsim/simbody.h"

namespace graspsim::integration {

class DenseOutput {
public:
    // Which discrete variables are Report-stage ones and whether any is an auto-update one, at
    // `state` (the integrator's, after its initialization).
    void initialize(const SimTK::State& state);
    // The step about to be taken starts at `start` (realized through Acceleration).
    void captureStart(const SimTK::State& start) { start_.captureStart(start); }
    // The State at t inside the step from the captured start to `end` (realized through
    // Acceleration), with `end`'s discrete variables: time and y set, neither projected nor realized.
    SimTK::State& interpolate(const SimTK::State& end, double t);
    // The integrator's State changed otherwise than in time, q, u and z (a handler worked on it).
    void markChanged() { inSync_ = false; }
    const SimTK::State& getState() const { return state_; }
    SimTK::State& updState() { return state_; }
    // After handlers ran on the interpolated State: true if their change (none above Stage::Report
    // or of Report-stage variables only) leaves everything the integrator computed valid, the
    // variables then handed on to `integrator`, its State ahead; false if the integrator must go on
    // from the interpolated State.
    bool handOn(const SimTK::HandleEventsResults& results, SimTK::State& integrator) const;

private:
    StepInterpolation start_;
    SimTK::State state_;
    // Whether state_ differs from the integrator's State only in time, q, u and z (then
    // interpolate() need not copy the whole State again), and whether auto-update variables rule
    // that out.
    bool inSync_ = false, hasAutoUpdate_ = false;
    DiscreteVariableKeys reportVariables_;
};

}  // namespace graspsim::integration
