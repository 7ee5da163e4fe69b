#pragma once
/// @file
/// The holding-capacity figures read off a loaded run's time series: the load at slip onset and
/// at the drop.
///
/// Slip is measured where the fingers hold the object: the largest displacement, relative to the
/// palm, of the object's material points at the grasp goals since the load began (m). Onset is
/// the first time it exceeds SlipCriteria::slip, by linear interpolation between samples.

#include <limits>
#include <string>
#include <vector>

namespace graspsim::capacity {

/// One sample of a loaded run.
struct CapacitySample {
    double time = 0;    ///< s
    double load = 0;    ///< magnitude of the applied load (N, or N m for a torque)
    double slip = 0;    ///< slip distance since the load began (m)
    /// Rotation of the object relative to the palm since the load began (rad): a pinch lets the
    /// object pivot about the pinch axis with little slip at the pads; reported, not a criterion.
    double rotation = 0;
    bool held = true;   ///< the grasp still holds the object (the scenario's held criterion)
    /// Whether the grasp approximation is engaged: 1 or 0 in approx mode, -1 where there is none.
    int engaged = -1;
    /// Grip force (N): the sum of the normal forces of the finger-object contacts, the F_perp of
    /// the thesis's limits (eq. 4.1). NaN where it is not measured: while the approximation is
    /// engaged (its constraint replaces the contacts), or in a scene that does not report it.
    double gripForce = std::numeric_limits<double>::quiet_NaN();
};

/// When a run counts as slipping and as dropped.
struct SlipCriteria {
    /// Slip onset (m). 2 mm: above the elastic give of the grasp without sliding (skin
    /// compression, finger joints yielding to the load: below 1 mm in the thesis scenarios at
    /// loads they hold) and below a fingertip pad's radius (about 5 mm, the approximation's release
    /// distance), so the pad still covers the spot it pressed.
    double slip = 0.002;
    /// Drop (m): the slip exceeds this, or the grasp no longer holds the object (held = false).
    /// 20 mm is the thesis scenarios' held tolerance: a pad that far from its spot has lost it.
    double drop = 0.020;
};

/// Checks that the slip onset comes before the drop (each already a finite number > 0): with the
/// onset at or beyond the drop, every run would drop before it slips. Both the capacity command and
/// a capacity study check their distances here; a distance equal to SlipCriteria's default is
/// named as such, since that is the one the user did not change.
/// @param source where the refused value came from ("--slip-threshold", "run option 'slip_threshold'")
/// @param value that value as the user wrote it
/// @throws graspsim::InputError "<source>: value <value> is not accepted; the slip threshold
///         (0.03 m) must be below the drop threshold (0.02 m, the default)"
void checkSlipCriteria(const SlipCriteria& criteria, const std::string& source, const std::string& value);

/// The capacity figures of one run.
struct CapacityFigures {
    bool slipped = false;
    double slipOnsetLoad = 0;  ///< N or N m (valid if slipped)
    double slipOnsetTime = 0;  ///< s
    bool dropped = false;
    double dropLoad = 0;       ///< N or N m (valid if dropped)
    double dropTime = 0;       ///< s
    /// the approximation released during the load (engaged 1 -> 0, or 0 at the load's start: a
    /// step it handed back at once)
    bool released = false;
    double releaseLoad = 0;    ///< N or N m, at the first sample after the release
    double releaseTime = 0;    ///< s, that sample's time
    /// Grip force (N) at the first sample (the load's start), NaN where not measured there.
    double gripForceAtStart = std::numeric_limits<double>::quiet_NaN();
    /// Grip force (N) at the slip onset, interpolated as the onset's load is; NaN where it is not
    /// measured on both sides of the crossing, or without slip.
    double gripForceAtOnset = std::numeric_limits<double>::quiet_NaN();
};

/// Reads slip onset and drop off `samples` (time order).
CapacityFigures findCapacityFigures(const std::vector<CapacitySample>& samples, const SlipCriteria& criteria);

/// Whether `sample` counts as dropped.
bool isDropped(const CapacitySample& sample, const SlipCriteria& criteria);

}  // namespace graspsim::capacity
