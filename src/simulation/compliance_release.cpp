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

// A side the model never lets go of is capped at four times the thesis's box on its axis, so that
// the bushing, stiffened for its larger side, stays as stiff as the thesis's would be within a
// small factor.
ComplianceReleaseLimits calcComplianceLimits(const ApproximationContext& context, const SimTK::State& state,
                                             const std::vector<contact::ContactReport>& reports, double mu,
                                             const SimTK::Vec6& box, const SimTK::Rotation& R_GM, const SimTK::Vec3& p_GM,
                                             double slipDistance) {
    const FingerCompliance fingers = makeFingerCompliance(context);
    const std::vector<grasp::CompliantContact> contacts = fingers.findCompliantContacts(state, reports, {});
    grasp::ComplianceLimitOptions options;
    options.mu = mu;
    options.kineticMu = std::min(mu, context.contactParameters.dynamicFriction);  // broken loose, a contact slides at mu_d
    options.slipDistance = slipDistance;
    for (int k = 0; k < 6; ++k) options.maxLoads[k] = std::max(4 * box[k], 1e-9);
    const grasp::TwoSidedLimits limits =
        grasp::calcComplianceLimits(contacts, system::toEigenMatrix(R_GM), system::toEigenVector(p_GM), options);
    ComplianceReleaseLimits result;
    for (int k = 0; k < 6; ++k) {
        result.lower[k] = limits.lower[k];
        result.upper[k] = limits.upper[k];
    }
    setDirectionModel(result, contacts, R_GM, p_GM, options);
    for (const contact::ContactReport& r : reports) {
        if (findPressingContact(r, {})) result.contactBodies.push_back(r.bodyA);  // findCompliantContacts' filter
    }
    return result;
}

std::string findAxisAtLimit(const SimTK::Vec6& wrench, const ComplianceReleaseLimits& limits, const char* name) {
    for (int k = 0; k < 6; ++k) {
        const double limit = wrench[k] >= 0 ? limits.upper[k] : -limits.lower[k];
        if (std::abs(wrench[k]) < std::abs(limit)) continue;
        const bool atSlipOnset = wrench[k] >= 0 ? limits.upperAtSlipOnset[k] : limits.lowerAtSlipOnset[k];
        const char* unit = k < 3 ? "N m" : "N";
        char text[200];
        std::snprintf(text, sizeof text, "%s on %s %.6g %s reached the %s %.6g %s", name, kAxisNames[k], wrench[k],
                      unit, atSlipOnset ? "constraint's slip onset" : "compliance limit", limit, unit);
        return text;
    }
    return {};
}

void capAtSlipOnset(ComplianceReleaseLimits& limits, const SimTK::Vec6& lower, const SimTK::Vec6& upper,
                    const std::array<bool, 6>& locked, double onsetFraction) {
    for (int k = 3; k < 6; ++k) {
        if (locked[k]) continue;
        if (limits.lower[k] > onsetFraction * lower[k]) limits.lower[k] = onsetFraction * lower[k], limits.lowerAtSlipOnset[k] = true;
        if (limits.upper[k] > onsetFraction * upper[k]) limits.upper[k] = onsetFraction * upper[k], limits.upperAtSlipOnset[k] = true;
    }
}

std::string describeSlipOnsetSides(const ComplianceReleaseLimits& limits) {
    std::string text;
    for (int k = 0; k < 6; ++k) {
        for (const bool upper : {false, true}) {
            if (!(upper ? limits.upperAtSlipOnset[k] : limits.lowerAtSlipOnset[k])) continue;
            text += std::string(" (") + kAxisNames[k] + (upper ? " upper" : " lower") + " side at the constraint's slip onset)";
        }
    }
    return text;
}

void setDirectionModel(ComplianceReleaseLimits& limits, const std::vector<grasp::CompliantContact>& contacts_G,
                       const SimTK::Rotation& R_GO, const SimTK::Vec3& p_GO, const grasp::ComplianceLimitOptions& options) {
    const Eigen::Matrix3d R_OG = system::toEigenMatrix(R_GO).transpose();
    const Eigen::Vector3d p = system::toEigenVector(p_GO);
    limits.contacts_O.clear();
    for (grasp::CompliantContact c : contacts_G) {
        c.p_GC = R_OG * (c.p_GC - p);
        c.n_G = R_OG * c.n_G;
        c.force_G = R_OG * c.force_G;
        c.fingerCompliance_G = R_OG * c.fingerCompliance_G * R_OG.transpose();
        limits.contacts_O.push_back(c);
    }
    const Eigen::Matrix<double, 6, 1> w0 = grasp::calcContactWrenchInM(contacts_G, R_OG.transpose(), p);
    for (int k = 0; k < 6; ++k) limits.w0[k] = w0[k];
    limits.slipPoints_O.clear();
    for (const Eigen::Vector3d& p_GS : options.slipPoints_G) limits.slipPoints_O.push_back(R_OG * (p_GS - p));
    limits.mu = options.mu;
    limits.kineticMu = options.kineticMu;
    limits.slipDistance = options.slipDistance;
}

Eigen::Matrix<double, 6, 1> findLoadBeyondEngagement(const SimTK::Vec6& wrench, const ComplianceReleaseLimits& limits) {
    Eigen::Matrix<double, 6, 1> load;
    for (int k = 0; k < 6; ++k) load[k] = limits.w0[k] - wrench[k];
    return load;
}

namespace {

// The model's onset along `load` in multiples of it, followed up to `maxLoad` (infinite beyond).
double findOnsetAlong(const Eigen::Matrix<double, 6, 1>& load, const ComplianceReleaseLimits& limits, double maxLoad) {
    return followDirectionModel(limits, load, maxLoad).onset;
}

}  // namespace

grasp::CompliantCapacity followDirectionModel(const ComplianceReleaseLimits& limits, const Eigen::Matrix<double, 6, 1>& load,
                                              double maxLoad) {
    grasp::CompliantCapacityOptions options;
    options.mu = limits.mu;
    options.kineticMu = limits.kineticMu;
    options.slipPoints_G = limits.slipPoints_O;  // O's origin as the model's origin: O is its G here
    options.maxLoad = maxLoad;
    options.slipDistance = limits.slipDistance;
    return grasp::calcCompliantCapacityAlong(limits.contacts_O, Eigen::Vector3d::Zero(), load, options);
}

std::string findDirectionAtLimit(const SimTK::Vec6& wrench, const ComplianceReleaseLimits& limits) {
    if (limits.contacts_O.empty()) return {};
    const Eigen::Matrix<double, 6, 1> load = findLoadBeyondEngagement(wrench, limits);
    if (load.isZero(0)) return {};
    const double onset = findOnsetAlong(load, limits, 1);
    if (!(onset <= 1)) return {};
    char text[240];
    std::snprintf(text, sizeof text,
                  "load beyond engagement [%.4g %.4g %.4g] N m, [%.4g %.4g %.4g] N reached the compliance model's onset "
                  "along it (%.4g times it)",
                  load[0], load[1], load[2], load[3], load[4], load[5], onset);
    return text;
}

// Followed to twice the load, so that the margin reaches its cap, |load|, continuously: onset 2
// gives (2 - 1) |load| either way, and the witness sees no jump.
double findDirectionMargin(const SimTK::Vec6& wrench, const ComplianceReleaseLimits& limits) {
    if (limits.contacts_O.empty()) return SimTK::Infinity;
    const Eigen::Matrix<double, 6, 1> load = findLoadBeyondEngagement(wrench, limits);
    if (load.isZero(0)) return SimTK::Infinity;
    const double onset = findOnsetAlong(load, limits, 2);
    return (std::min(onset, 2.0) - 1) * load.norm();
}

std::string findComplianceLimitReached(const SimTK::Vec6& wrench, const ComplianceReleaseLimits& limits, const char* name) {
    const std::string axis = name ? findAxisAtLimit(wrench, limits, name) : findAxisAtLimit(wrench, limits);
    if (!axis.empty()) return axis;
    const std::string direction = findDirectionAtLimit(wrench, limits);
    return name && !direction.empty() ? std::string(name) + ": " + direction : direction;
}

double findAxisMargin(const SimTK::Vec6& wrench, const ComplianceReleaseLimits& limits) {
    double margin = SimTK::Infinity;
    for (int k = 0; k < 6; ++k) margin = std::min(margin, wrench[k] >= 0 ? limits.upper[k] - wrench[k] : limits.lower[k] + wrench[k]);
    return margin;
}

double findLimitMargin(const SimTK::Vec6& wrench, const ComplianceReleaseLimits& limits) {
    return std::min(findAxisMargin(wrench, limits), findDirectionMargin(wrench, limits));
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

SimTK::Vec6 calcHeldWrenchInO(const ApproximationContext& context, const SimTK::State& state,
                              const std::vector<contact::ContactReport>& reports) {
    const SimTK::MobilizedBody& object = context.object;
    const SimTK::MobilizedBody& palm = context.palm;
    const SimTK::Transform& X_GO = object.getBodyTransform(state);
    const SimTK::Vec3 p_HO = palm.findStationAtGroundPoint(state, X_GO.p());
    const SimTK::Vec3 a_rel_G = object.getBodyOriginAcceleration(state) - palm.findStationAccelerationInGround(state, p_HO);
    const SimTK::Vec3 alpha_rel_G = object.getBodyAngularAcceleration(state) - palm.getBodyAngularAcceleration(state);
    const SimTK::MassProperties& mp = object.getBodyMassProperties(state);  // about O's origin, in O
    const SimTK::Vec3 force_O = mp.getMass() * (~X_GO.R() * a_rel_G);
    const SimTK::Vec3 moment_O = mp.getUnitInertia().asSymMat33() * mp.getMass() * (~X_GO.R() * alpha_rel_G);
    SimTK::Vec6 held = calcContactWrenchInO(context, state, reports);
    for (int k = 0; k < 3; ++k) held[k] -= moment_O[k], held[k + 3] -= force_O[k];
    return held;
}

double findGoalSpeedInPalm(const ApproximationContext& context, const SimTK::State& state) {
    double fastest = 0;
    for (const SimTK::Vec3& p_OT : context.goals.getSurfacePoints()) {
        const SimTK::Vec3 p_GT = context.object.findStationLocationInGround(state, p_OT);
        const SimTK::Vec3 p_HT = context.palm.findStationAtGroundPoint(state, p_GT);
        const SimTK::Vec3 v = context.object.findStationVelocityInGround(state, p_OT) - context.palm.findStationVelocityInGround(state, p_HT);
        fastest = std::max(fastest, v.norm());
    }
    return fastest;
}

std::string findReengageObstacle(const ApproximationContext& context, const SimTK::State& state,
                                 const std::vector<contact::ContactReport>& reports, const ComplianceReleaseLimits& limits) {
    context.model.getSystem().realize(state, SimTK::Stage::Velocity);
    const double speed = findGoalSpeedInPalm(context, state), sticking = context.contactParameters.transitionVelocity;
    if (speed >= sticking) {
        char text[120];
        std::snprintf(text, sizeof text, "object moving in the palm at %.6g m/s (transition velocity %.6g m/s)", speed, sticking);
        return text;
    }
    context.model.getSystem().realize(state, SimTK::Stage::Acceleration);
    // Engaging takes the held wrench off the contacts at once and the bushing picks it up from
    // zero force, critically damped: its reaction k x + c v peaks at (1 + e^-2) times the wrench
    // (at omega t = 2), so a grasp engaged within that of a limit would be released by its own
    // pick-up.
    const double pickUpPeak = 1 + std::exp(-2.0);
    return findComplianceLimitReached(pickUpPeak * calcHeldWrenchInO(context, state, reports), limits);
}

}  // namespace graspsim::simulation
