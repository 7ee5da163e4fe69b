#pragma once
/// @file
/// The bounds `graspsim validate` holds each run to, each with its reason (the thesis section it
/// comes from, the closed form, or the physical meaning of the tolerance), and what one run
/// measured against its full-contact reference.

#include "graspsim/simulation/grasp_simulation.h"
#include "graspsim/validation/trajectory_comparison.h"
#include "graspsim/validation/validation_plan.h"

#include <string>
#include <vector>

namespace graspsim::validation {

/// Bound of the full-contact hold: drift of the object after settling, no perturbation (m).
constexpr double kFullHoldDrift = 0.005;
/// Bounds of the approximation against full contact, no perturbation, 2 s after engaging.
constexpr double kApproxPositionError = 0.002;  ///< m
constexpr double kApproxAngleError = 2.0 * 3.14159265358979323846 / 180.0;  ///< rad (2 degrees)
constexpr double kApproxWindow = 2.0;           ///< s after engagement
/// Bound of Simbody's integrator at the scenario accuracy against the CVODE reference: a quarter
/// of the approximation's 2 mm / 2 degree bounds, so that integration error cannot decide an
/// approximation check.
constexpr double kIntegratorPositionError = 0.0005;  ///< m
constexpr double kIntegratorAngleError = 0.5 * 3.14159265358979323846 / 180.0;  ///< rad (0.5 degree)
/// Bound of the fingertips' penetration growth beyond their depth at engagement, while engaged,
/// over full contact's own growth of the same pairs in the same spans (m): "no visible
/// interpenetration" beyond what the skin's compression under the load gives anyway (the
/// engagement depth itself is the compliant skin's).
constexpr double kEngagedPenetrationGrowth = 0.0001;
/// Bound of the long hold: drift after settling (m).
constexpr double kLongHoldDrift = 0.001;
/// Distance from the settled position that counts as the object slipping (m).
constexpr double kSlipDistance = 0.002;

/// What one run measured (and, for an approximation run, how it compares with its reference).
struct RunRecord {
    ValidationRun run;
    simulation::SimulationSummary summary;
    double slipOnset = -1;           ///< findSlipOnset() with kSlipDistance (s); -1 if none
    bool hasReference = false;
    PoseErrors errors;               ///< against the reference, from engagement (or settling) to the end
    PoseErrors windowErrors;         ///< the same over the kApproxWindow after engagement
    double referenceSlipOnset = -1;  ///< the reference's slip onset (s)
    bool referenceHeld = false;
    double referenceDisplacement = 0;  ///< the reference's object displacement after settling (m)
    /// The reference's counterpart of summary.maxEngagedPenetrationGrowth: calcDepthGrowth of the
    /// pairs the candidate replaced, over the candidate's engaged spans (m).
    double referenceEngagedGrowth = 0;
};

/// One bound checked on one run.
struct ValidationCheck {
    std::string run;     ///< run id
    std::string name;    ///< what is checked, e.g. "position error vs full contact (max)"
    double value = 0;    ///< measured, in `unit`
    double bound = 0;    ///< limit, in `unit`
    std::string unit;    ///< "mm", "deg", "s", "" (booleans: 1 = true)
    std::string relation;  ///< "<=", ">=" or "=="
    bool pass = false;
    std::string source;  ///< why the bound holds: thesis section, closed form, or physical meaning
};

/// The largest growth of one contact pair's depth over the samples of `contacts` in
/// (from, to], beyond its depth in the last sample at or before `from` (0 for a pair not in
/// contact there), over `pairs` (ascending) only (m, >= 0). A pair with several contact points counts its
/// deepest. 0 if no sample falls in the span.
double calcDepthGrowth(const std::vector<simulation::ContactSample>& contacts, const std::vector<int>& pairs, double from,
                       double to);

/// Fills the comparison fields of `record` from its own and its reference's results.
void compareWithReference(const simulation::SimulationResult& reference, const simulation::SimulationResult& candidate,
                          RunRecord& record);

/// The bounds that apply to `record` (see the constants above); empty if none applies.
std::vector<ValidationCheck> checkRun(const RunRecord& record);

}  // namespace graspsim::validation
