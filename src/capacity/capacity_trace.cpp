#include "graspsim/capacity/capacity_trace.h"

namespace graspsim::capacity {

bool isDropped(const CapacitySample& sample, const SlipCriteria& criteria) {
    return !sample.held || sample.slip > criteria.drop;
}

namespace {

// Time and load where the slip crosses `threshold` between samples a and b (a below, b above).
void interpolateCrossing(const CapacitySample& a, const CapacitySample& b, double threshold, double& time, double& load) {
    const double f = b.slip > a.slip ? (threshold - a.slip) / (b.slip - a.slip) : 1.0;
    time = a.time + f * (b.time - a.time);
    load = a.load + f * (b.load - a.load);
}

}  // namespace

CapacityFigures findCapacityFigures(const std::vector<CapacitySample>& samples, const SlipCriteria& criteria) {
    CapacityFigures figures;
    for (std::size_t k = 0; k < samples.size(); ++k) {
        const CapacitySample& s = samples[k];
        if (!figures.released && k > 0 && samples[k - 1].engaged == 1 && s.engaged == 0) {
            figures.released = true;
            figures.releaseLoad = s.load;
            figures.releaseTime = s.time;
        }
        if (!figures.slipped && s.slip > criteria.slip) {
            figures.slipped = true;
            if (k == 0) {
                figures.slipOnsetTime = s.time;
                figures.slipOnsetLoad = s.load;
            } else {
                interpolateCrossing(samples[k - 1], s, criteria.slip, figures.slipOnsetTime, figures.slipOnsetLoad);
            }
        }
        if (isDropped(s, criteria)) {
            figures.dropped = true;
            figures.dropTime = s.time;
            figures.dropLoad = s.load;
            if (s.held && k > 0) interpolateCrossing(samples[k - 1], s, criteria.drop, figures.dropTime, figures.dropLoad);
            // A grasp that lets go without sliding 2 mm first (a torque that unwraps it) slips there too.
            if (!figures.slipped) {
                figures.slipped = true;
                figures.slipOnsetTime = figures.dropTime;
                figures.slipOnsetLoad = figures.dropLoad;
            }
            break;
        }
    }
    return figures;
}

}  // namespace graspsim::capacity
