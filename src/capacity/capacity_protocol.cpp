#include "graspsim/capacity/capacity_protocol.h"

#include "graspsim/error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace graspsim::capacity {

namespace {

// The number of samples after `start`: every `dt`, the last one exactly at `end`. Counted, not
// listed: a long ramp's samples end at the drop, and its times are made as they come.
double countSampleTimes(double start, double end, double dt) { return std::max(1.0, std::ceil((end - start) / dt - 1e-9)); }

// Advances `run` to the load's start, then samples it until it drops or `end`.
void sampleRun(LoadedRun& run, const simulation::LoadRampSpec& load, double end, double dt, const SlipCriteria& criteria,
               std::vector<CapacitySample>& samples) {
    run.advanceTo(load.start);
    run.captureReference();
    CapacitySample first = run.sampleNow();
    first.time = load.start;
    first.load = load.initial;
    samples.push_back(first);
    const double n = countSampleTimes(load.start, end, dt);
    for (double k = 1; k <= n; ++k) {
        const double t = k < n ? load.start + k * dt : end;
        run.advanceTo(t);
        CapacitySample s = run.sampleNow();
        s.time = t;
        s.load = load.initial + load.rate * (t - load.start);
        samples.push_back(s);
        if (isDropped(s, criteria)) break;
    }
}

// Whether a constant `load` slips within the hold.
bool slipsUnder(const LoadedRunFactory& makeRun, const BisectionProtocol& p, double load) {
    const simulation::LoadRampSpec spec{p.direction, p.torque, p.start, load, 0.0};
    const std::unique_ptr<LoadedRun> run = makeRun(spec);
    std::vector<CapacitySample> samples;
    sampleRun(*run, spec, p.start + p.hold, p.sampleInterval, p.criteria, samples);
    return findCapacityFigures(samples, p.criteria).slipped;
}

}  // namespace

CapacityTrace runLoadedScene(const LoadedRunFactory& makeRun, const simulation::LoadRampSpec& load, double end,
                             double sampleInterval, const SlipCriteria& criteria) {
    const std::unique_ptr<LoadedRun> run = makeRun(load);
    CapacityTrace trace;
    try {
        sampleRun(*run, load, end, sampleInterval, criteria, trace.samples);
    } catch (const NumericalError& e) {
        trace.failure = foldToOneLine(e.what());
    } catch (const SimTK::Exception::Base& e) {  // an integrator that cannot step
        trace.failure = "Simbody: " + foldToOneLine(e.getMessageText());
    }
    trace.figures = findCapacityFigures(trace.samples, criteria);
    trace.releaseReason = run->findReleaseReason();
    return trace;
}

CapacityTrace runRamp(const LoadedRunFactory& makeRun, const RampProtocol& p) {
    const simulation::LoadRampSpec spec{p.direction, p.torque, p.start, p.initial, p.rate};
    return runLoadedScene(makeRun, spec, p.start + p.maxDuration, p.sampleInterval, p.criteria);
}

BisectionResult runBisection(const LoadedRunFactory& makeRun, const BisectionProtocol& p) {
    BisectionResult result;
    result.held = p.low;
    result.slipped = p.high;
    for (int k = 0;; ++k) {
        ++result.runs;
        if (slipsUnder(makeRun, p, result.slipped)) break;
        if (k == 6) {
            throw NumericalError("capacity bisection: no load up to " + std::to_string(result.slipped) + " slips within " +
                                 std::to_string(p.hold) + " s");
        }
        result.held = result.slipped;
        result.slipped *= 2;
    }
    while (result.slipped - result.held > p.tolerance * result.slipped) {
        const double middle = 0.5 * (result.held + result.slipped);
        ++result.runs;
        (slipsUnder(makeRun, p, middle) ? result.slipped : result.held) = middle;
    }
    return result;
}

}  // namespace graspsim::capacity
