#pragma once
// How `graspsim bench` times things (cost_table.cpp): dynamics evaluations one by one, and runs per
// simulated second in wall time and in evaluations counted. Wall times on a shared machine drift by
// tens of per cent over a minute, so what is compared is timed back to back where it can be.

#include <simbody/Simbody.h>

#include <utility>
#include <vector>

namespace graspsim::validation {

// Wall-clock seconds of a steady clock (differences only).
double readWallClock();

// µs per dynamics evaluation (realize to Acceleration from Time) of `state`: best of five batches
// of `realizations`, so that another process taking the core for a moment does not count.
double timeRealization(const SimTK::System& system, const SimTK::State& state, int realizations);

// The same for two states of one System, timed in alternating batches (best of ten each): a machine
// slowed for a while slows both alike, so their ratio holds where separate timings drift apart.
std::pair<double, double> timeRealizationPair(const SimTK::System& system, const SimTK::State& a, const SimTK::State& b,
                                              int realizations);

// Dynamics evaluations: System realizations of Stage::Acceleration, one ODE right-hand side each
// (integrator steps, Newton iterations, Jacobian columns, trigger checks, output samples). A count,
// the same on any machine, unlike the wall time.
long countEvaluations(const SimTK::System& system);

// Simulated time, wall time and evaluations at one point of a run.
struct Mark {
    double time = -1, wall = 0;
    long evaluations = 0;
    bool isSet() const { return time >= 0; }
};

// Wall time and evaluations of a run with what the sample observer spends (the per-evaluation
// timings, the floor run beside the hold: hundreds of milliseconds and thousands of realizations)
// taken out, so that it does not count as simulation cost.
class RunClock {
public:
    Mark mark(double time, const SimTK::System& system) const;
    void beginObserving(const SimTK::System& system);
    void endObserving(const SimTK::System& system);
    double getObservingSeconds() const { return observing_; }

private:
    double observing_ = 0, observeStart_ = 0;
    long observedEvaluations_ = 0, evaluationsAtStart_ = 0;
};

double wallPerSimSecond(const Mark& a, const Mark& b);

// A stretch of a run per simulated second: the median wall time of the windows between successive
// marks (one window slowed by another process does not move it) and the evaluations, first to last.
struct HoldCost {
    double wallPerSimSecond = 0, evaluationsPerSimSecond = 0;
};
HoldCost findHoldCost(const std::vector<Mark>& marks);
// The same from one-second stretches, each counted from zero (FloorRun::advanceOneSecond()).
HoldCost findHoldCostOfSeconds(const std::vector<Mark>& seconds);

// The median over the pairs (hold window k, floorSeconds[k - 1]) of hold / floor wall time, for a
// floor integrated one simulated second right after each window of the hold.
double findMedianPairedRatio(const std::vector<Mark>& hold, const std::vector<Mark>& floorSeconds);

// A floor state integrated by CPodes at `accuracy`, driven as integration::SimbodyCpodesStepper
// drives it (returning after every internal step, so that triggers are checked at steps only) and
// reporting every `reportInterval` s (interpolated, as an engaged run's reports and switch checks
// are), with no event handler: a floor has no grasp to check and no goals to track. The System
// must outlive it.
class FloorRun {
public:
    FloorRun(const SimTK::System& system, const SimTK::State& floorState, double accuracy, double reportInterval);
    // One more simulated second: its wall time and evaluations (time 1, counted from zero).
    Mark advanceOneSecond();

private:
    const SimTK::System& system_;
    SimTK::CPodesIntegrator integrator_;
    double interval_, next_;
};

// A FloorRun for `seconds` whole simulated seconds on its own.
HoldCost timeFloorHold(const SimTK::System& system, const SimTK::State& floorState, double accuracy, double reportInterval,
                       int seconds);

}  // namespace graspsim::validation
