#include "graspsim/capacity/overload.h"

#include "graspsim/error.h"

#include <cmath>

namespace graspsim::capacity {

CapacityTrace runOverload(const LoadedRunFactory& makeRun, const OverloadProtocol& p) {
    if (!(p.load > 0) || !std::isfinite(p.load) || !(p.hold > 0) || !std::isfinite(p.hold)) {
        throw InputError("overload: the load (" + std::to_string(p.load) + ") and the hold (" + std::to_string(p.hold) +
                         " s) must be finite numbers > 0");
    }
    const simulation::LoadRampSpec spec{p.direction, p.torque, p.start, p.load, 0.0};
    return runLoadedScene(makeRun, spec, p.start + p.hold, p.sampleInterval, p.criteria);
}

OverloadFigures findOverloadFigures(const CapacityFigures& figures, double start) {
    OverloadFigures f;
    f.slipped = figures.slipped;
    f.slipOnsetTime = figures.slipOnsetTime - start;
    f.dropped = figures.dropped;
    f.dropTime = figures.dropTime - start;
    f.released = figures.released;
    f.releaseTime = figures.releaseTime - start;
    return f;
}

}  // namespace graspsim::capacity
