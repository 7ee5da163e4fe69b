#pragma once
/// @file
/// The holding-capacity protocol on any loaded scene: a ramp (the load grows from zero at a fixed
/// rate until the object drops) and, as a second method, a bisection over constant loads.
///
/// Both run a scene built with a simulation::LoadRampSpec on its object through a LoadedRun,
/// which knows how to advance that scene and how far the object has slipped in it: the grasp
/// scenarios (grasp_capacity.h) and the analytic two-finger squeeze (squeeze_capacity.h).

#include "graspsim/capacity/capacity_trace.h"
#include "graspsim/simulation/ramp_load.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace graspsim::capacity {

/// A scene with a load on its object, advanced forward in time.
class LoadedRun {
public:
    virtual ~LoadedRun() = default;
    /// Advances to time t (s, not earlier than the last call).
    virtual void advanceTo(double t) = 0;
    /// Takes the present pose as the one slip is measured from (the load's start).
    virtual void captureReference() = 0;
    /// Slip since the reference (m) and whether the object is still held, now. The load is filled
    /// in by the protocol.
    virtual CapacitySample sampleNow() = 0;
    /// Why the grasp approximation let go during the run, with its numbers ("" if it did not or
    /// there is none).
    virtual std::string findReleaseReason() const { return {}; }
};

/// Builds a fresh scene with the given load on its object.
using LoadedRunFactory = std::function<std::unique_ptr<LoadedRun>(const simulation::LoadRampSpec& load)>;

/// The ramp: from `start` (the settled grasp) the load grows at `rate`; sampled every
/// `sampleInterval` until the object drops or `maxDuration` after the start.
struct RampProtocol {
    SimTK::UnitVec3 direction{0, -1, 0};  ///< in G
    bool torque = false;
    double start = 0;           ///< s
    double rate = 1;            ///< N/s or N m/s, > 0
    /// N or N m applied at once at `start`, from which the ramp grows (a step load followed by the
    /// ramp: how the grasp approximation's hand-back gives the contacts the load it carried)
    double initial = 0;
    double maxDuration = 4;     ///< s of ramp at most
    double sampleInterval = 0.005;  ///< s
    SlipCriteria criteria;
};

/// A run's time series (from the load's start) and its figures.
struct CapacityTrace {
    std::vector<CapacitySample> samples;
    CapacityFigures figures;
    std::string releaseReason;  ///< LoadedRun::findReleaseReason at the end of the ramp
    /// Why the run stopped early ("" if it did not): a numerical failure of the scene's integrator.
    /// The samples before it are kept and the figures read from them.
    std::string failure;
};

/// Runs one scene made by `makeRun` with `load`: advances it to load.start, takes the reference
/// there, then samples it every `sampleInterval` until the object drops or `end` (s). A numerical
/// failure of the scene's integrator ends the run early (CapacityTrace::failure); the figures are
/// read from the samples before it. The ramp and the constant load (overload.h) are this with their
/// loads.
CapacityTrace runLoadedScene(const LoadedRunFactory& makeRun, const simulation::LoadRampSpec& load, double end,
                             double sampleInterval, const SlipCriteria& criteria);

/// Runs the ramp on a scene made by `makeRun`.
CapacityTrace runRamp(const LoadedRunFactory& makeRun, const RampProtocol& protocol);

/// Bisection over constant loads applied at `start` and held for `hold` s: a load "slips" when
/// the slip exceeds criteria.slip within the hold. Starts from [low, high] (high is doubled until
/// it slips, at most 6 times) and halves the bracket until it is narrower than `tolerance` times
/// its upper end.
struct BisectionProtocol {
    SimTK::UnitVec3 direction{0, -1, 0};
    bool torque = false;
    double start = 0;     ///< s
    double hold = 1;      ///< s
    double low = 0;       ///< N or N m, a load held (0 always is)
    double high = 1;      ///< N or N m, a first guess at one that slips
    double tolerance = 0.01;
    double sampleInterval = 0.005;  ///< s
    SlipCriteria criteria;
};

/// The bracket found: the largest load held and the smallest that slipped, and the runs it took.
struct BisectionResult {
    double held = 0;
    double slipped = 0;
    int runs = 0;
    /// The estimate of the slip-onset load: the bracket's middle.
    double findEstimate() const { return 0.5 * (held + slipped); }
};

/// Runs the bisection. @throws graspsim::NumericalError if no load up to 64 x high slips.
BisectionResult runBisection(const LoadedRunFactory& makeRun, const BisectionProtocol& protocol);

}  // namespace graspsim::capacity
