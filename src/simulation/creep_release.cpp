#include "graspsim/simulation/creep_release.h"

#include <cstdio>

namespace graspsim::simulation {

CreepWatch startCreepWatch(const ComplianceReleaseLimits& limits, const contact::ContactParameters& friction,
                           const Eigen::Matrix<double, 6, 1>& load, double t) {
    CreepWatch watch;
    watch.time = t;
    if (limits.contacts_O.empty()) return watch;
    // The model's contacts in O, O's origin as its origin, as the static rules take them.
    std::vector<grasp::CompliantContact> contacts = limits.contacts_O;
    for (grasp::CompliantContact& c : contacts) c.tangentialStiffness = grasp::kCreepTangentialStiffnessRatio * c.normalStiffness;
    contact::ContactParameters creep = friction;
    // The model's law has no viscous term (CompliantCreep refuses one); the scenarios' is 0 by default.
    creep.viscousFriction = 0;
    watch.model.emplace(contacts, Eigen::Vector3d::Zero(), creep, limits.slipPoints_O);
    watch.model->advance(load, 0);
    watch.load = load;
    return watch;
}

void updateCreepWatch(CreepWatch& watch, const std::optional<Eigen::Matrix<double, 6, 1>>& load, double t) {
    const double interval = t - watch.time;
    watch.time = t;
    if (!watch.model || !load || !(interval >= 0)) return;
    watch.model->advance(*load - watch.load, interval);
    watch.load = *load;
}

std::string describeCreepRelease(const CreepWatch& watch, double give) {
    if (!watch.model) return {};
    if (watch.model->hasGivenWay()) {
        return "the compliance model followed in time (full contact's creep) gave way under the load beyond engagement";
    }
    const double slip = watch.model->findSlip();
    if (!(slip >= give)) return {};
    char text[200];
    std::snprintf(text, sizeof text,
                  "the compliance model followed in time (full contact's creep) gave %.4g mm at the grasp goals under the load "
                  "beyond engagement (release give %.4g mm)", 1e3 * slip, 1e3 * give);
    return text;
}

}  // namespace graspsim::simulation
