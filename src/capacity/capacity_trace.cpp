#include "graspsim/capacity/capacity_trace.h"

#include "graspsim/error.h"

#include <sstream>

namespace graspsim::capacity {

namespace {

// "0.02 m, the default" or "0.03 m".
std::string describeDistance(double metres, double defaultMetres) {
    std::ostringstream text;
    text << metres << " m" << (metres == defaultMetres ? ", the default" : "");
    return text.str();
}

}  // namespace

void checkSlipCriteria(const SlipCriteria& criteria, const std::string& source, const std::string& value) {
    if (criteria.slip < criteria.drop) return;
    const SlipCriteria defaults;
    throw InputError(source + ": value " + value + " is not accepted; the slip threshold (" + describeDistance(criteria.slip, defaults.slip) +
                     ") must be below the drop threshold (" + describeDistance(criteria.drop, defaults.drop) + ")");
}

bool isDropped(const CapacitySample& sample, const SlipCriteria& criteria) {
    return !sample.held || sample.slip > criteria.drop;
}

namespace {

// Time, load and grip force where the slip crosses `threshold` between samples a and b (a below,
// b above). A grip force not measured on either side (NaN) stays unmeasured.
struct Crossing {
    double time = 0, load = 0, gripForce = 0;
};

Crossing interpolateCrossing(const CapacitySample& a, const CapacitySample& b, double threshold) {
    const double f = b.slip > a.slip ? (threshold - a.slip) / (b.slip - a.slip) : 1.0;
    return {a.time + f * (b.time - a.time), a.load + f * (b.load - a.load), a.gripForce + f * (b.gripForce - a.gripForce)};
}

}  // namespace

CapacityFigures findCapacityFigures(const std::vector<CapacitySample>& samples, const SlipCriteria& criteria) {
    CapacityFigures figures;
    if (!samples.empty()) figures.gripForceAtStart = samples.front().gripForce;
    for (std::size_t k = 0; k < samples.size(); ++k) {
        const CapacitySample& s = samples[k];
        // A first sample already released: handed back at the load's start (the run was engaged up
        // to it, or it would not have been sampled).
        if (!figures.released && s.engaged == 0 && (k == 0 || samples[k - 1].engaged == 1)) {
            figures.released = true;
            figures.releaseLoad = s.load;
            figures.releaseTime = s.time;
        }
        if (!figures.slipped && s.slip > criteria.slip) {
            figures.slipped = true;
            const Crossing onset = k == 0 ? Crossing{s.time, s.load, s.gripForce} : interpolateCrossing(samples[k - 1], s, criteria.slip);
            figures.slipOnsetTime = onset.time;
            figures.slipOnsetLoad = onset.load;
            figures.gripForceAtOnset = onset.gripForce;
        }
        if (isDropped(s, criteria)) {
            const Crossing drop = s.held && k > 0 ? interpolateCrossing(samples[k - 1], s, criteria.drop) : Crossing{s.time, s.load, s.gripForce};
            figures.dropped = true;
            figures.dropTime = drop.time;
            figures.dropLoad = drop.load;
            // A grasp that lets go without sliding 2 mm first (a torque that unwraps it) slips there too.
            if (!figures.slipped) {
                figures.slipped = true;
                figures.slipOnsetTime = drop.time;
                figures.slipOnsetLoad = drop.load;
                figures.gripForceAtOnset = drop.gripForce;
            }
            break;
        }
    }
    return figures;
}

}  // namespace graspsim::capacity
