#include "run_timing.h"

#include <algorithm>
#include <chrono>

namespace graspsim::validation {

double readWallClock() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

namespace {

// One batch of `realizations` evaluations of `state`, µs each.
double timeBatch(const SimTK::System& system, SimTK::State& state, int realizations) {
    const double start = readWallClock();
    for (int k = 0; k < realizations; ++k) {
        state.invalidateAllCacheAtOrAbove(SimTK::Stage::Time);
        system.realize(state, SimTK::Stage::Acceleration);
    }
    return 1e6 * (readWallClock() - start) / realizations;
}

double findMedian(std::vector<double> values) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace

double timeRealization(const SimTK::System& system, const SimTK::State& source, int realizations) {
    SimTK::State state = source;
    system.realize(state, SimTK::Stage::Acceleration);
    double best = 1e300;
    for (int batch = 0; batch < 5; ++batch) best = std::min(best, timeBatch(system, state, realizations));
    return best;
}

std::pair<double, double> timeRealizationPair(const SimTK::System& system, const SimTK::State& sourceA,
                                              const SimTK::State& sourceB, int realizations) {
    SimTK::State a = sourceA, b = sourceB;
    system.realize(a, SimTK::Stage::Acceleration);
    system.realize(b, SimTK::Stage::Acceleration);
    double bestA = 1e300, bestB = 1e300;
    for (int batch = 0; batch < 10; ++batch) {
        bestA = std::min(bestA, timeBatch(system, a, realizations));
        bestB = std::min(bestB, timeBatch(system, b, realizations));
    }
    return {bestA, bestB};
}

long countEvaluations(const SimTK::System& system) { return system.getNumRealizationsOfThisStage(SimTK::Stage::Acceleration); }

Mark RunClock::mark(double time, const SimTK::System& system) const {
    return {time, readWallClock() - observing_, countEvaluations(system) - observedEvaluations_};
}

void RunClock::beginObserving(const SimTK::System& system) {
    observeStart_ = readWallClock();
    evaluationsAtStart_ = countEvaluations(system);
}

void RunClock::endObserving(const SimTK::System& system) {
    observing_ += readWallClock() - observeStart_;
    observedEvaluations_ += countEvaluations(system) - evaluationsAtStart_;
}

double wallPerSimSecond(const Mark& a, const Mark& b) { return b.time > a.time ? (b.wall - a.wall) / (b.time - a.time) : 0; }

HoldCost findHoldCost(const std::vector<Mark>& marks) {
    std::vector<double> rates;
    for (std::size_t k = 1; k < marks.size(); ++k) rates.push_back(wallPerSimSecond(marks[k - 1], marks[k]));
    HoldCost cost;
    cost.wallPerSimSecond = findMedian(rates);
    if (marks.size() >= 2 && marks.back().time > marks.front().time) {
        cost.evaluationsPerSimSecond =
            double(marks.back().evaluations - marks.front().evaluations) / (marks.back().time - marks.front().time);
    }
    return cost;
}

HoldCost findHoldCostOfSeconds(const std::vector<Mark>& seconds) {
    std::vector<Mark> marks{{0, 0, 0}};
    for (const Mark& one : seconds) {
        const Mark& last = marks.back();
        marks.push_back({last.time + one.time, last.wall + one.wall, last.evaluations + one.evaluations});
    }
    return findHoldCost(marks);
}

double findMedianPairedRatio(const std::vector<Mark>& hold, const std::vector<Mark>& floorSeconds) {
    std::vector<double> ratios;
    for (std::size_t k = 1; k < hold.size() && k - 1 < floorSeconds.size(); ++k) {
        const double floorWall = floorSeconds[k - 1].wall;
        if (floorWall > 0) ratios.push_back(wallPerSimSecond(hold[k - 1], hold[k]) / floorWall);
    }
    return findMedian(ratios);
}

FloorRun::FloorRun(const SimTK::System& system, const SimTK::State& floorState, double accuracy, double reportInterval)
    : system_(system), integrator_(system, SimTK::CPodes::BDF, SimTK::CPodes::Newton), interval_(reportInterval) {
    integrator_.setAccuracy(accuracy);
    integrator_.setReturnEveryInternalStep(true);
    integrator_.initialize(floorState);
    next_ = floorState.getTime() + interval_;
}

Mark FloorRun::advanceOneSecond() {
    const double wallStart = readWallClock();
    const long evaluationsStart = countEvaluations(system_);
    const double end = integrator_.getTime() + 1.0;
    while (integrator_.getTime() < end - 1e-12) {
        const SimTK::Integrator::SuccessfulStepStatus status = integrator_.stepTo(std::min(end, next_));
        if (status == SimTK::Integrator::ReachedEventTrigger) integrator_.reinitialize(SimTK::Stage::Report, false);
        if (status == SimTK::Integrator::ReachedReportTime && integrator_.getTime() >= next_ - 1e-12) next_ += interval_;
        if (status == SimTK::Integrator::EndOfSimulation) break;
    }
    return {1.0, readWallClock() - wallStart, countEvaluations(system_) - evaluationsStart};
}

HoldCost timeFloorHold(const SimTK::System& system, const SimTK::State& floorState, double accuracy, double reportInterval,
                       int seconds) {
    FloorRun floor(system, floorState, accuracy, reportInterval);
    std::vector<Mark> ones;
    for (int k = 0; k < seconds; ++k) ones.push_back(floor.advanceOneSecond());
    return findHoldCostOfSeconds(ones);
}

}  // namespace graspsim::validation
