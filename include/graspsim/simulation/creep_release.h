#pragma once
/// @file
/// The creep watch of the compliance release trigger (ApproxOptions::releaseCreep): while the merged
/// bushing is engaged and an external load acts on the object, the first engagement's compliance
/// model (ComplianceReleaseLimits::contacts_O) is followed in time with full contact's regularized
/// friction (grasp::CompliantCreep) under the load the grasp carries beyond engagement, and the
/// switch hands the object back once the model says full contact's object would have given the
/// release give at the grasp goals.
///
/// Why: the other compliance rules read the static model, whose onset does not depend on how fast
/// the load grows. Full contact's contacts creep under any tangential load, so under a slow ramp it
/// slips at a smaller load than under a fast one, and a hand-back at the static onset comes after
/// full contact's own, which the approximation cannot undo (docs/capacity.md, "The creep watch").
///
/// The watch advances at the switch's checks (every IK interval and at the release witness's),
/// from the last check, the load change spread evenly over the interval. While no external load
/// acts it waits with its state kept: a held grasp is not handed back for its creep under its own
/// weight, which the model overestimates (docs/capacity.md, "Creep in the bushing").

#include "graspsim/grasp/compliant_grasp_creep.h"
#include "graspsim/simulation/compliance_release.h"

#include "graspsim/simbody.h"

#include <limits>
#include <optional>
#include <string>

namespace graspsim::simulation {

/// The model followed so far, kept in the State (a discrete variable of the switch).
struct CreepWatch {
    /// The model since the engagement; unset: no watch (not engaged, or the rule off).
    std::optional<grasp::CompliantCreep> model;
    /// The load beyond engagement at the last update (moment about O's origin then force, along
    /// O's axes; N m, N): findLoadBeyondEngagement of the carried load, zero without external load.
    Eigen::Matrix<double, 6, 1> load = Eigen::Matrix<double, 6, 1>::Zero();
    /// When the watch was last brought up to date (s).
    double time = std::numeric_limits<double>::quiet_NaN();
};

/// A watch that starts at time `t` from the first engagement's model `limits` (its contacts_O and
/// slip points; none: an empty watch) with the contacts' friction `friction`, the load beyond
/// engagement `load` (as CreepWatch::load) taken up at once.
/// @throws graspsim::InputError for invalid friction.
CreepWatch startCreepWatch(const ComplianceReleaseLimits& limits, const contact::ContactParameters& friction,
                           const Eigen::Matrix<double, 6, 1>& load, double t);

/// Brings `watch` to time `t` under the load beyond engagement `load`, or leaves its model as it is
/// (only the time moves) when `load` is unset: no external load acts.
void updateCreepWatch(CreepWatch& watch, const std::optional<Eigen::Matrix<double, 6, 1>>& load, double t);

/// The release reason once the watch's model has given `give` (m) at the slip points, or given way;
/// empty otherwise, and for an empty watch.
std::string describeCreepRelease(const CreepWatch& watch, double give);

}  // namespace graspsim::simulation
