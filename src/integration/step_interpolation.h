#pragma once
// Dense output of the linearly implicit stepper: the state between the ends of a step, from the
// values and derivatives at both ends (cubic Hermite, third order, above the method's second), so
// that reports and scheduled events inside a step are served without cutting the step there.

#include "graspsim/simbody.h"

#include <utility>
#include <vector>

namespace graspsim::integration {

class StepInterpolation {
public:
    // The step's start: time, y = (q, u, z) and its derivative. `start` realized through Acceleration.
    void captureStart(const SimTK::State& start);
    // y at time t within [start, end]; `end` is the step's end, realized through Acceleration.
    void interpolate(const SimTK::State& end, double t, SimTK::Vector& y) const;

private:
    double t0_ = 0;
    SimTK::Vector y0_, yDot0_;
};

// The discrete variables whose change invalidates only Stage::Report: nothing an integrator
// computes depends on them, so a scheduled event that changes only these at an interpolated
// instant can hand them on to the integrator's state ahead of it without a restart.
using DiscreteVariableKeys = std::vector<std::pair<SimTK::SubsystemIndex, SimTK::DiscreteVariableIndex>>;
DiscreteVariableKeys findReportVariables(const SimTK::State& state);
// Whether any discrete variable is an auto-update one (updated after every step, so that a state
// copied earlier no longer has the integrator's values).
bool hasAutoUpdateVariables(const SimTK::State& state);
// Copies those variables from `source` to `target` (invalidating only Report in `target`).
void copyReportVariables(const DiscreteVariableKeys& keys, const SimTK::State& source, SimTK::State& target);

}  // namespace graspsim::integration
