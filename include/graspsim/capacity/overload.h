#pragma once
/// @file
/// The constant-load ("overload") measurement: a load of fixed magnitude along a direction, applied
/// at once at `start` and held, and how long the grasp takes to let the object slip and drop under
/// it. Above the holding capacity the object slides; the slip-onset time is what issue 17 compares
/// between full contact and the approximation (a ramp folds onset time and load into one figure).
///
/// Slip and drop are the ramp's (capacity_trace.h: slip at the grasp goals relative to the palm,
/// onset at SlipCriteria::slip by linear interpolation between samples, drop at SlipCriteria::drop
/// or when the held criterion fails); the run stops at the drop.

#include "graspsim/capacity/capacity_protocol.h"

namespace graspsim::capacity {

/// Default sample interval of a constant load (s): above capacity the thesis objects slip 2 mm
/// within 15-150 ms of the load (docs/capacity.md), so the ramp's 5 ms would leave 3-4 samples
/// before the onset.
constexpr double kOverloadSampleInterval = 0.001;

/// A constant load from `start` for `hold` s, sampled every `sampleInterval`.
struct OverloadProtocol {
    SimTK::UnitVec3 direction{0, -1, 0};  ///< in G
    bool torque = false;                  ///< a torque about the object's centre of mass instead of a force
    double start = 0;                     ///< s, when the load is applied
    double load = 1;                      ///< N or N m, > 0
    double hold = 1;                      ///< s, > 0
    double sampleInterval = kOverloadSampleInterval;  ///< s
    SlipCriteria criteria;
};

/// The figures of a constant-load run, as times after the load's start (s).
struct OverloadFigures {
    bool slipped = false;
    double slipOnsetTime = 0;  ///< s after the start at which the slip passed criteria.slip (valid if slipped)
    bool dropped = false;
    double dropTime = 0;       ///< s after the start (valid if dropped)
    bool released = false;     ///< the approximation handed the object back to full contact
    double releaseTime = 0;    ///< s after the start, the first sample after the release (valid if released)
};

/// Runs the constant load on a scene made by `makeRun`: the trace's samples and figures are on the
/// scene's clock (the load's start is the first sample), its sample loads all `protocol.load`.
CapacityTrace runOverload(const LoadedRunFactory& makeRun, const OverloadProtocol& protocol);

/// Reads `figures` (on the scene's clock) as times after `start` (s).
OverloadFigures findOverloadFigures(const CapacityFigures& figures, double start);

}  // namespace graspsim::capacity
