#pragma once
/// @file
/// What `graspsim validate` runs: the thesis experiments x perturbations x contact models x
/// modes, each approximation run paired with the full-contact run it is measured against.

#include "graspsim/simulation/simulation_options.h"

#include <string>
#include <vector>

namespace graspsim::validation {

/// One simulation of the suite.
struct ValidationRun {
    std::string id;            ///< unique, also its folder under DIR/runs: `<experiment>_<perturbation>_<variant>`, e.g. "ball-clutch_f1_approx-bushing-merged"
    std::string scenario;      ///< built-in scenario name
    std::string variant;       ///< "full" or an approximation variant, e.g. "approx-bushing-merged"
    simulation::SimulationOptions options;
    std::string reference;     ///< id of the full-contact run it is compared with; empty for a full-contact run
    /// The long hold: an approximation run of several minutes checked
    /// for finite states and drift, not compared with full contact.
    bool longHold = false;
};

/// The suite's selection (the command line of `graspsim validate`).
struct PlanOptions {
    bool quick = false;                    ///< the reduced set run by ctest (label validation)
    std::vector<std::string> experiments;  ///< scenario names; empty = both thesis experiments
    std::vector<std::string> variants;     ///< "full" and approximation variants; empty = all available
    double longHoldDuration = 600;         ///< simulated s of the long hold (full suite only; 0 = none)
};

/// Relative accuracy of the CVODE reference runs ("full-cvode"): a thousand times tighter than
/// the scenarios' 1e-3, so that its own error is negligible next to the difference it measures.
constexpr double kReferenceAccuracy = 1e-6;

/// The run options of a variant ("full", "full-cvode", "full-rigid", "approx-<constraint>-<attach>"
/// with the default release trigger, "approx-bushing-merged-thesis" for the thesis's switch (its box
/// without the compliance release), "approx-bushing-merged-contact" / "-compliance" for the other
/// friction-limit models, on the thesis's switch too) with the given perturbation ("none" or the
/// scenario's) and duration (s; 0 = the scenario's).
simulation::SimulationOptions makeVariantOptions(const std::string& variant, const std::string& perturbation, double duration);

/// The experiments of the thesis (chapter 5): "ball-clutch", "phone-pinch".
const std::vector<std::string>& getThesisExperiments();
/// The built-in scenarios that are not the thesis's: the grasps `graspsim grasp plan` set up
/// ("ball-tripod", "can-power", "key-lateral"), in the built-in list's order.
const std::vector<std::string>& getPlannedExperiments();
/// Every variant this build can run: "full" first (compliant contact, Simbody's CPodes: the
/// reference of the others), "full-cvode" (the CVODE reference integrator; run without
/// perturbation only), "full-rigid" (rigid contact), then the approximation variants
/// "approx-bushing-merged", "approx-weld-merged", "approx-bushing-multi" (compliant contact
/// before engaging; multi is built on bushings only).
const std::vector<std::string>& getAvailableVariants();

/// The runs for `options`, references before the runs that compare against them.
/// Quick: ball-clutch without perturbation, full vs every other variant except full-rigid (unless
/// asked for), 2 s after settling.
/// Full suite: every experiment x {none, its perturbations} x every variant,
/// the scenario's whole duration, plus the long hold (ball-clutch, first approximation variant).
/// @throws graspsim::InputError naming the option, the unknown value and the accepted ones.
std::vector<ValidationRun> makeValidationPlan(const PlanOptions& options);

}  // namespace graspsim::validation
