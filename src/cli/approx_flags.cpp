#include "approx_flags.h"

#include "number_option.h"

#include "graspsim/error.h"

namespace graspsim::cli {

namespace {

// Each shared flag once: its name, where its value goes, and its help.
struct FlagDefinition {
    const char* name;
    std::string ApproxFlags::*value;
    const char* help;
};

const FlagDefinition kFlags[] = {
    {"--constraint", &ApproxFlags::constraint,
     "approx: the friction-limited palm-object constraint, bushing (compliant, default) or weld (rigid)"},
    {"--attach", &ApproxFlags::attach,
     "approx: merged (default: fingers locked to the palm, one palm-object element) or multi (one element spanning the "
     "object and every fingertip, fingers free)"},
    {"--q-minimum", &ApproxFlags::qMinimum, "approx: grasp quality Q_M (N) below which to release (default: 0.5 x Q_Th)"},
    {"--limits", &ApproxFlags::limits,
     "approx: the constraint's friction limits, thesis (default: one box, eq. 4.1-4.3), contact (per axis, from each "
     "contact's normal and position) or compliance (two-sided per axis, from the grasp's compliance model; bushing, merged)"},
    {"--release-give", &ApproxFlags::releaseGive,
     "approx: the compliance release trigger's onset: hand the object back once the grasp's compliance model says full "
     "contact would have let it give this far at the grasp goals, m (default 0.002, the model's slip onset)"},
    {"--bushing-give", &ApproxFlags::bushingGive,
     "approx: how the merged bushing gives under a load: auto (default: coupled on the merged bushing), coupled (the "
     "grasp's compliance model's whole 6 x 6 stiffness, rotations and translations coupled, preloaded with the "
     "contacts' wrench, the locked fingers following the object; docs/capacity.md), model (the model's rotational "
     "stiffness only, the translations stiff) or stiff (stiffened for the penetration bound)"},
    {"--hand-back", &ApproxFlags::handBack,
     "approx: the state full contact takes the object back in at a compliance-trigger release: engaged (default: as the "
     "constraint held it) or deflected (object and finger joints deflected as the grasp's compliance model says full "
     "contact would be under the carried load)"},
    {"--release-creep", &ApproxFlags::releaseCreep,
     "approx: with the compliance release trigger, also hand back once the grasp's compliance model, followed in time "
     "with full contact's creep under the carried load, has given the release give: on (default) or off"},
    {"--release-at", &ApproxFlags::releaseAt,
     "approx: an extra release rule: compliance (release once the constraint's reaction, or the load the grasp carries "
     "(gravity and the external loads), reaches the grasp's compliance-model limit on any axis side, or the model's "
     "onset along the load's own direction; bushing, merged), none (the thesis's rules only) or auto (default: "
     "compliance on the merged bushing, none otherwise)"},
};

}  // namespace

void addApproxFlags(CLI::App& command, ApproxFlags& flags) {
    for (const FlagDefinition& flag : kFlags) command.add_option(flag.name, flags.*flag.value, flag.help);
}

std::vector<std::string> getApproxFlagNames() {
    std::vector<std::string> names;
    for (const FlagDefinition& flag : kFlags) names.emplace_back(flag.name);
    return names;
}

void parseApproxFlags(const ApproxFlags& flags, simulation::ApproxOptions& options) {
    options.constraint = simulation::parseApproxConstraint(flags.constraint, "--constraint");
    options.attach = simulation::parseApproxAttach(flags.attach, "--attach");
    options.qMinimum = parsePositiveNumber(flags.qMinimum, "--q-minimum", "N").value_or(0);  // 0: automatic
    options.limitModel = grasp::parseFrictionLimitModel(flags.limits, "--limits");
    options.releaseTrigger = simulation::parseApproxReleaseTrigger(flags.releaseAt, "--release-at");
    options.releaseGive = parseReleaseGive(flags.releaseGive);
    options.handBack = simulation::parseApproxHandBack(flags.handBack, "--hand-back");
    options.bushingGive = simulation::parseApproxBushingGive(flags.bushingGive, "--bushing-give");
    if (!flags.releaseCreep.empty() && flags.releaseCreep != "on" && flags.releaseCreep != "off") {
        throw InputError("--release-creep: '" + flags.releaseCreep + "' is not accepted; use on or off");
    }
    if (!flags.releaseCreep.empty()) options.releaseCreep = flags.releaseCreep == "on";
}

void checkApproxOnlyOptions(const CLI::App& command, const std::string& mode, const std::vector<std::string>& names) {
    if (mode == "approx") return;
    for (const std::string& name : names) {
        const CLI::Option* option = command.get_option_no_throw(name);
        if (option == nullptr || option->count() == 0) continue;
        const std::string value = option->results().empty() ? "" : option->results().front();
        throw InputError(name + ": value '" + value + "' is not accepted with --mode " + mode +
                         "; it is an option of the grasp approximation: add --mode approx or leave " + name + " out");
    }
}

}  // namespace graspsim::cli
