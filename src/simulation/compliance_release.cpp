#include "graspsim/simulation/compliance_release.h"

#include "graspsim/grasp/compliance_limits.h"
#include "graspsim/simulation/finger_compliance.h"
#include "graspsim/system/simtk_conversion.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace graspsim::simulation {

namespace {

const char* const kAxisNames[6] = {"rotation x", "rotation y", "rotation z", "translation x", "translation y", "translation z"};

}  // namespace

std::string findAxisAtLimit(const SimTK::Vec6& wrench, const ComplianceReleaseLimits& limits) {
    for (int k = 0; k < 6; ++k) {
        const double limit = wrench[k] >= 0 ? limits.upper[k] : -limits.lower[k];
        if (std::abs(wrench[k]) < std::abs(limit)) continue;
        const char* unit = k < 3 ? "N m" : "N";
        char text[160];
        std::snprintf(text, sizeof text, "constraint reaction on %s %.6g %s reached the compliance limit %.6g %s",
                      kAxisNames[k], wrench[k], unit, limit, unit);
        return text;
    }
    return {};
}

double findLimitMargin(const SimTK::Vec6& wrench, const ComplianceReleaseLimits& limits) {
    double margin = SimTK::Infinity;
    for (int k = 0; k < 6; ++k) margin = std::min(margin, wrench[k] >= 0 ? limits.upper[k] - wrench[k] : limits.lower[k] + wrench[k]);
    return margin;
}

// The wrench needs the contacts' points and forces only, not the fingers' compliance (a Jacobian
// and a solve per contact, at every check after a release).
SimTK::Vec6 calcContactWrenchInO(const ApproximationContext& context, const SimTK::State& state,
                                 const std::vector<contact::ContactReport>& reports) {
    std::vector<grasp::CompliantContact> contacts;
    for (const contact::ContactReport& r : reports) {
        if (const std::optional<grasp::CompliantContact> c = findPressingContact(r, {})) contacts.push_back(*c);
    }
    const SimTK::Transform& X_GO = context.object.getBodyTransform(state);
    const Eigen::Matrix<double, 6, 1> w =
        grasp::calcContactWrenchInM(contacts, system::toEigenMatrix(X_GO.R()), system::toEigenVector(X_GO.p()));
    SimTK::Vec6 result;
    for (int k = 0; k < 6; ++k) result[k] = w[k];
    return result;
}

}  // namespace graspsim::simulation
