#include "graspsim/simulation/simulation_options.h"

#include "graspsim/error.h"
#include "graspsim/model/body_model.h"
#include "graspsim/scenario/scenario.h"

#include <cmath>
#include <cstdio>

namespace graspsim::simulation {

ContactModel parseContactModel(const std::string& text, const std::string& source) {
    if (text == "compliant") return ContactModel::Compliant;
    if (text == "rigid") return ContactModel::Rigid;
    throw InputError(source + ": contact model '" + text + "' is not accepted; use compliant or rigid");
}

SimulationMode parseSimulationMode(const std::string& text, const std::string& source) {
    if (text == "full") return SimulationMode::Full;
    if (text == "approx") return SimulationMode::Approx;
    throw InputError(source + ": mode '" + text + "' is not accepted; use full or approx");
}

IntegratorChoice parseIntegratorChoice(const std::string& text, const std::string& source) {
    if (text == "auto") return IntegratorChoice::Automatic;
    if (text == "simbody") return IntegratorChoice::SimbodyCpodes;
    if (text == "cvode") return IntegratorChoice::Cvode;
    if (text == "implicit") return IntegratorChoice::LinearlyImplicit;
    if (text == "implicit-fixed") return IntegratorChoice::LinearlyImplicitFixed;
    throw InputError(source + ": integrator '" + text + "' is not accepted; use auto, simbody, cvode, implicit or implicit-fixed");
}

std::string toString(IntegratorChoice integrator) {
    if (integrator == IntegratorChoice::Automatic) return "auto";
    if (integrator == IntegratorChoice::Cvode) return "cvode";
    if (integrator == IntegratorChoice::LinearlyImplicit) return "implicit";
    return integrator == IntegratorChoice::LinearlyImplicitFixed ? "implicit-fixed" : "simbody";
}

ApproxConstraint parseApproxConstraint(const std::string& text, const std::string& source) {
    if (text == "bushing") return ApproxConstraint::Bushing;
    if (text == "weld") return ApproxConstraint::Weld;
    throw InputError(source + ": constraint '" + text + "' is not accepted; use bushing or weld");
}

std::string toString(ContactModel model) { return model == ContactModel::Compliant ? "compliant" : "rigid"; }
std::string toString(ApproxConstraint constraint) {
    return constraint == ApproxConstraint::Bushing ? "bushing" : "weld";
}
ApproxAttach parseApproxAttach(const std::string& text, const std::string& source) {
    if (text == "merged") return ApproxAttach::Merged;
    if (text == "multi") return ApproxAttach::Multi;
    throw InputError(source + ": attachment '" + text + "' is not accepted; use merged or multi");
}

std::string toString(ApproxAttach attach) { return attach == ApproxAttach::Merged ? "merged" : "multi"; }

ApproxReleaseTrigger parseApproxReleaseTrigger(const std::string& text, const std::string& source) {
    if (text == "auto") return ApproxReleaseTrigger::Automatic;
    if (text == "none") return ApproxReleaseTrigger::None;
    if (text == "compliance") return ApproxReleaseTrigger::Compliance;
    throw InputError(source + ": release trigger '" + text + "' is not accepted; use auto, none or compliance");
}

std::string toString(ApproxReleaseTrigger trigger) {
    switch (trigger) {
    case ApproxReleaseTrigger::Automatic: return "auto";
    case ApproxReleaseTrigger::None: return "none";
    case ApproxReleaseTrigger::Compliance: return "compliance";
    }
    return "compliance";
}
ApproxHandBack parseApproxHandBack(const std::string& text, const std::string& source) {
    if (text == "engaged") return ApproxHandBack::Engaged;
    if (text == "deflected") return ApproxHandBack::Deflected;
    throw InputError(source + ": hand-back '" + text + "' is not accepted; use engaged or deflected");
}

std::string toString(ApproxHandBack handBack) { return handBack == ApproxHandBack::Engaged ? "engaged" : "deflected"; }

ApproxBushingGive parseApproxBushingGive(const std::string& text, const std::string& source) {
    if (text == "auto") return ApproxBushingGive::Automatic;
    if (text == "stiff") return ApproxBushingGive::Stiff;
    if (text == "model") return ApproxBushingGive::Model;
    if (text == "coupled") return ApproxBushingGive::Coupled;
    throw InputError(source + ": bushing give '" + text + "' is not accepted; use auto, stiff, model or coupled");
}

std::string toString(ApproxBushingGive give) {
    switch (give) {
    case ApproxBushingGive::Automatic: return "auto";
    case ApproxBushingGive::Stiff: return "stiff";
    case ApproxBushingGive::Model: return "model";
    case ApproxBushingGive::Coupled: return "coupled";
    }
    return "?";
}

std::string toString(SimulationMode mode) { return mode == SimulationMode::Full ? "full" : "approx"; }

void checkApproxAttach(const scenario::Scenario& scenario, const SimulationOptions& options) {
    if (options.mode != SimulationMode::Approx) return;
    if (options.approx.limitModel == grasp::FrictionLimitModel::Compliance &&
        (options.approx.constraint != ApproxConstraint::Bushing || options.approx.attach != ApproxAttach::Merged)) {
        throw InputError("--limits: 'compliance' is not available with --constraint " + toString(options.approx.constraint) +
                         " --attach " + toString(options.approx.attach) +
                         " (its limits are two-sided, which only the merged bushing takes); use --constraint bushing "
                         "--attach merged or another --limits");
    }
    if (options.approx.releaseTrigger == ApproxReleaseTrigger::Compliance &&
        (options.approx.constraint != ApproxConstraint::Bushing || options.approx.attach != ApproxAttach::Merged)) {
        throw InputError("--release-at: 'compliance' is not available with --constraint " + toString(options.approx.constraint) +
                         " --attach " + toString(options.approx.attach) +
                         " (it watches the one palm-object bushing's reaction); use --constraint bushing --attach merged "
                         "or --release-at none");
    }
    if (options.approx.attach != ApproxAttach::Multi) return;
    if (options.approx.constraint != ApproxConstraint::Bushing) {
        throw InputError("--attach: 'multi' is not available with --constraint " + toString(options.approx.constraint) +
                         " (its parts are friction-limited bushings); use --constraint bushing or --attach merged");
    }
    const model::ModelDescription d = model::buildBodyModel(scenario.bodyOptions);
    for (const auto& [endEffector, goal] : scenario.goals) {
        const model::EndEffector* e = d.findEndEffector(endEffector);
        const model::Body* body = e ? d.findBody(e->body) : nullptr;
        if (body && !body->geometry.empty()) continue;
        throw InputError("--attach: 'multi' is not accepted for scenario '" + scenario.name + "': goal end-effector '" +
                         endEffector + "' is on a body without contact geometry; use --attach merged");
    }
}

IntegratorChoice resolveIntegrator(const scenario::Scenario& scenario, const SimulationOptions& options) {
    if (options.integrator != IntegratorChoice::Automatic) return options.integrator;
    if (options.contact == ContactModel::Rigid || scenario.friction.model == contact::FrictionModel::Anchor) {
        return IntegratorChoice::SimbodyCpodes;
    }
    if (options.mode == SimulationMode::Approx &&
        (options.approx.constraint != ApproxConstraint::Bushing || options.approx.attach != ApproxAttach::Merged)) {
        return IntegratorChoice::SimbodyCpodes;
    }
    return IntegratorChoice::LinearlyImplicit;
}

StepSizeChoice findStepSize(const scenario::Scenario& scenario, const SimulationOptions& options) {
    if (options.stepSize > 0) return {options.stepSize, "--step-size"};
    if (scenario.simulation.stepSize > 0) return {scenario.simulation.stepSize, scenario.source + ": simulation.step_size"};
    if (options.integrator == IntegratorChoice::LinearlyImplicitFixed) {
        return {kDefaultFixedStepSize, "the default fixed step (no --step-size, no simulation.step_size)"};
    }
    return {scenario.controller.ikInterval, "the default longest step, controller.ik_interval (no --step-size, no simulation.step_size)"};
}

void checkIntegratorChoice(const scenario::Scenario& scenario, const SimulationOptions& options) {
    if (options.contact == ContactModel::Rigid && options.integrator != IntegratorChoice::Automatic &&
        options.integrator != IntegratorChoice::SimbodyCpodes) {
        throw InputError("--integrator: '" + toString(options.integrator) +
                         "' is not accepted with --contact rigid (rigid contact has its own time stepper, Simbody's "
                         "semi-explicit Euler with impulses, rigid_stepping.h); leave --integrator out");
    }
    if (options.contact != ContactModel::Compliant || options.integrator != IntegratorChoice::LinearlyImplicitFixed ||
        scenario.friction.model != contact::FrictionModel::Anchor) {
        return;
    }
    const StepSizeChoice choice = findStepSize(scenario, options);
    const double step = choice.step;
    const double tau = scenario.friction.anchor.relaxationTime;
    // The linearly implicit stepper leaves the anchors' rates out of its Jacobian: they are
    // integrated explicitly, and ROS2's explicit part (a two-stage Runge-Kutta method) is stable for
    // a decay rate 1 / tau only while step / tau <= 2.
    if (step <= kAnchorStabilityLimit * tau) return;
    const std::string& field = choice.source;
    char text[500];
    std::snprintf(text, sizeof text,
                  "%s: %g s is not accepted with --integrator implicit-fixed and friction_model anchor: the anchors' "
                  "relaxation (contact.anchor_relaxation_time %g s) is integrated explicitly and is unstable for steps "
                  "above %g x that, %g s; use a step <= %g s, a longer anchor_relaxation_time, or --integrator implicit",
                  field.c_str(), step, tau, kAnchorStabilityLimit, kAnchorStabilityLimit * tau, kAnchorStabilityLimit * tau);
    throw InputError(text);
}

ApproxOptions resolveApproxOptions(const ApproxOptions& given, const scenario::ApproximationSpec& scenario) {
    ApproxOptions options = given;
    if (options.qThreshold == 0) options.qThreshold = scenario.qThreshold;
    if (options.qMinimum == 0) options.qMinimum = scenario.qMinimum;
    if (!options.relaxedAxes) options.relaxedAxes = scenario.relaxedAxes;
    if (options.releaseTrigger == ApproxReleaseTrigger::Automatic) {
        const bool mergedBushing = options.constraint == ApproxConstraint::Bushing && options.attach == ApproxAttach::Merged;
        options.releaseTrigger = mergedBushing ? ApproxReleaseTrigger::Compliance : ApproxReleaseTrigger::None;
    }
    if (!(options.qThreshold >= 0) || !(options.qMinimum >= 0)) {
        throw InputError("approx: the quality thresholds Q_Th and Q_M must be >= 0 (0 = automatic)");
    }
    if (!(options.releaseSlideDistance > 0)) throw InputError("approx: the release slide distance must be > 0 m");
    if (!(options.releasePenetration > 0)) throw InputError("approx: the release penetration must be > 0 m");
    if (!(options.maxEngagedPenetration > 0)) throw InputError("approx: the engaged penetration bound must be > 0 m");
    if (options.releaseGive && !(*options.releaseGive > 0 && std::isfinite(*options.releaseGive))) {
        throw InputError("approx: the release give must be a finite number > 0 m");
    }
    if (options.releaseGive && options.releaseTrigger != ApproxReleaseTrigger::Compliance) {
        throw InputError("--release-give: only the compliance release trigger uses it (--release-at compliance, or auto "
                         "on the merged bushing); this run's is " + toString(options.releaseTrigger));
    }
    if (options.releaseCreep && options.releaseTrigger != ApproxReleaseTrigger::Compliance) {
        throw InputError("--release-creep: only the compliance release trigger has the creep watch (--release-at compliance, "
                         "or auto on the merged bushing); this run's is " + toString(options.releaseTrigger));
    }
    if (options.handBack == ApproxHandBack::Deflected && options.releaseTrigger != ApproxReleaseTrigger::Compliance) {
        throw InputError("--hand-back: 'deflected' needs the compliance release trigger (--release-at compliance, or auto "
                         "on the merged bushing); this run's is " + toString(options.releaseTrigger));
    }
    const bool mergedBushing = options.constraint == ApproxConstraint::Bushing && options.attach == ApproxAttach::Merged;
    if (options.bushingGive == ApproxBushingGive::Automatic) {
        options.bushingGive = mergedBushing ? ApproxBushingGive::Coupled : ApproxBushingGive::Stiff;
    }
    if (options.bushingGive != ApproxBushingGive::Stiff && !mergedBushing) {
        throw InputError("--bushing-give: '" + toString(options.bushingGive) +
                         "' needs the merged bushing (--constraint bushing --attach merged); this run's is " +
                         toString(options.constraint) + " " + toString(options.attach));
    }
    if (options.qThreshold > 0 && options.qMinimum >= options.qThreshold) {
        char text[160];
        std::snprintf(text, sizeof text, "approx: Q_M (%g N) must be below Q_Th (%g N)", options.qMinimum, options.qThreshold);
        throw InputError(text);
    }
    return options;
}

}  // namespace graspsim::simulation
