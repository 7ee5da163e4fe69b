// GraspSwitch's engaging side: the check that decides to engage, the reasons it does not, and the
// engagement itself (grasp_switch.h, steps (a)-(e)); the release side is grasp_switch.cpp.

#include "graspsim/simulation/grasp_switch.h"

#include "graspsim/error.h"
#include "graspsim/simulation/bushing_give.h"
#include "graspsim/simulation/compliance_release.h"
#include "graspsim/simulation/multi_attachment_switch.h"
#include "graspsim/system/simtk_conversion.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace graspsim::simulation {

namespace {

// Eq. 4.1-4.3: F_perp = sum f_i . n_i; r = mean distance of the contact points to their centroid.
// Returns the constraint's limits, rotation first: mu r F_perp (N m), then mu F_perp (N).
SimTK::Vec6 calcFrictionLimits(const std::vector<contact::ContactReport>& reports, double mu) {
    double fPerp = 0;
    SimTK::Vec3 centroid(0);
    for (const contact::ContactReport& c : reports) {
        const SimTK::Vec3 f = c.normalForce * SimTK::Vec3(c.n_G) + c.frictionForce_G;
        fPerp += ~f * SimTK::Vec3(c.n_G);
        centroid += c.p_G;
    }
    centroid /= static_cast<double>(reports.size());
    double r = 0;
    for (const contact::ContactReport& c : reports) r += (c.p_G - centroid).norm();
    r /= static_cast<double>(reports.size());
    const double linear = mu * fPerp, angular = mu * r * fPerp;
    return SimTK::Vec6(angular, angular, angular, linear, linear, linear);
}

// The per-axis limits of the constraint frame M (orientation R_GM, origin p_GM) from each contact's
// normal and position (grasp/friction_limits.h), rotation first as calcFrictionLimits.
SimTK::Vec6 calcContactGeometryLimits(const std::vector<contact::ContactReport>& reports, double mu,
                                      const SimTK::Rotation& R_GM, const SimTK::Vec3& p_GM) {
    std::vector<grasp::GraspContact> contacts;
    for (const contact::ContactReport& c : reports) {
        grasp::GraspContact g;
        g.p_GC = system::toEigenVector(c.p_G);
        g.n_G = system::toEigenVector(SimTK::Vec3(c.n_G));
        g.normalForce = c.normalForce;
        contacts.push_back(g);
    }
    const Eigen::Matrix<double, 6, 1> limits =
        grasp::calcContactGeometryLimits(contacts, mu, system::toEigenMatrix(R_GM), system::toEigenVector(p_GM));
    SimTK::Vec6 result;
    for (int k = 0; k < 6; ++k) result[k] = limits[k];
    return result;
}

// " [-L-, L+] N, ..." for the six axes, translation first (the engage event's text).
std::string describeTwoSided(const SimTK::Vec6& lower, const SimTK::Vec6& upper) {
    std::string text;
    for (int k : {3, 4, 5, 0, 1, 2}) {
        char side[64];
        std::snprintf(side, sizeof side, " [-%.6g, %.6g]", lower[k], upper[k]);
        text += side + std::string(k == 5 ? " N," : k == 2 ? " N m" : "");
    }
    return text;
}

// The friction coefficient of limits computed from the contacts: static or dynamic as the options
// ask (--limits-friction), else static where `staticByDefault`.
double findLimitFriction(const contact::ContactParameters& pair, const ApproxOptions& options, bool staticByDefault) {
    return options.staticFrictionLimits.value_or(staticByDefault) ? pair.staticFriction : pair.dynamicFriction;
}

// Centroid of the contact points (Ground, m): where the friction acts, so where the constraint does.
SimTK::Vec3 findContactCentroid(const std::vector<contact::ContactReport>& reports) {
    SimTK::Vec3 centroid(0);
    for (const contact::ContactReport& c : reports) centroid += c.p_G;
    return centroid / static_cast<double>(reports.size());
}

// The farthest contact point from the constraint frame's origin p_GC (m): the lever arm through
// which a rotation of the object in the hand moves a fingertip into it.
double findLeverArm(const std::vector<contact::ContactReport>& reports, const SimTK::Vec3& p_GC) {
    double arm = 0;
    for (const contact::ContactReport& c : reports) arm = std::max(arm, (c.p_G - p_GC).norm());
    return arm;
}

}  // namespace

// The first goal body without a contact, or empty when every goal has one.
std::string GraspSwitch::findGoalWithoutContact(const std::vector<contact::ContactReport>& reports) const {
    for (const std::string& body : goalBodies_) {
        if (std::none_of(reports.begin(), reports.end(), [&](const contact::ContactReport& c) { return c.bodyA == body; })) return body;
    }
    return {};
}

// A constraint that starts out sticking is only right for an object that is not sliding: with
// regularized friction a contact inside its cone creeps slower than the transition velocity, one
// at its limit slides faster. Without this, an object already slipping out (phone-pinch f1 after a
// release) was re-engaged and dragged through the locked fingertips.
const contact::ContactReport* GraspSwitch::findSlidingContact(const std::vector<contact::ContactReport>& reports) const {
    if (multi_) return multi_->findSlidingContact(reports);
    const double limit = context_.contactParameters.transitionVelocity;
    const auto sliding = std::find_if(reports.begin(), reports.end(),
                                      [&](const contact::ContactReport& c) { return !(c.slipVelocity_G.norm() < limit); });
    return sliding == reports.end() ? nullptr : &*sliding;
}

// One set of contact reports serves every test of the check and the engagement itself.
void GraspSwitch::checkEngage(SimTK::State& state) const {
    context_.model.getSystem().realize(state, SimTK::Stage::Velocity);
    const std::vector<contact::ContactReport> reports = context_.contacts.findContactReports(state);
    if (!findGoalWithoutContact(reports).empty()) return;
    const double q = calcQualityOf(state, reports);
    if (getRecord(state).qThreshold == 0) {
        // Automatic Q_Th from the first full-contact check once the grasp has settled.
        if (state.getTime() < context_.settleTime - 1e-12) return;
        GraspSwitchRecord& record = updRecord(state);
        record.qThreshold = options_.autoThresholdFraction * q;
        if (options_.qMinimum == 0) record.qMinimum = options_.hysteresisFraction * record.qThreshold;
        // A given Q_M at or above it would release every engagement at once, and the run would chatter.
        if (!(record.qMinimum < record.qThreshold)) {
            char text[320];
            std::snprintf(text, sizeof text,
                          "Q_M (--q-minimum or approximation.q_minimum) %.6g N is not accepted: it must be below Q_Th, "
                          "here automatic, %.6g N (%g x the settled grasp's quality); give a smaller Q_M or a --q-threshold "
                          "above it", record.qMinimum, record.qThreshold, options_.autoThresholdFraction);
            throw InputError(text);
        }
    }
    std::optional<ComplianceReleaseLimits> limits;
    if (findEngageObstacle(state, reports, q, getRecord(state).qThreshold, limits).empty()) engage(state, q, reports, limits);
}

std::string GraspSwitch::findEngageObstacle(const SimTK::State& state) const {
    if (isEngaged(state)) return {};
    context_.model.getSystem().realize(state, SimTK::Stage::Velocity);
    const std::vector<contact::ContactReport> reports = context_.contacts.findContactReports(state);
    const std::string goal = findGoalWithoutContact(reports);
    if (!goal.empty()) return "no contact on the goal segment " + goal;
    const double q = calcQualityOf(state, reports);
    double qThreshold = getRecord(state).qThreshold;
    if (qThreshold == 0) {
        if (state.getTime() < context_.settleTime - 1e-12) return formatText("before the settle time, %.6g s", context_.settleTime);
        qThreshold = options_.autoThresholdFraction * q;  // as the check would set it now
    }
    std::optional<ComplianceReleaseLimits> limits;
    return findEngageObstacle(state, reports, q, qThreshold, limits);
}

// checkEngage's tests after full contact and Q_Th, in its order; `limits` receives the compliance
// limits an engagement would take.
std::string GraspSwitch::findEngageObstacle(const SimTK::State& state, const std::vector<contact::ContactReport>& reports, double q,
                                            double qThreshold, std::optional<ComplianceReleaseLimits>& limits) const {
    if (const contact::ContactReport* c = findSlidingContact(reports)) {
        return "the contact of " + c->bodyA + formatText(" slips at %.6g m/s, not below the transition velocity %.6g m/s",
                                                     c->slipVelocity_G.norm(), context_.contactParameters.transitionVelocity);
    }
    // Not at the instant of a release (a witness may release at a check's time): the contacts just
    // restored still carry the pre-release state, and would re-engage what just failed.
    const std::vector<GraspEvent>& events = getRecord(state).events;
    if (!events.empty() && events.back().kind == GraspEventKind::Release && !(state.getTime() > events.back().time)) {
        return "released at this instant";
    }
    if (!(q > 0 && q >= qThreshold)) return formatText("grasp quality %.6g N below Q_Th = %.6g N", q, qThreshold);
    // Not while the grasp carries a load at its compliance limits, nor while it is still taking up
    // its load (findReengageObstacle): handed back because the load reached them, the grasp stays
    // in full contact, which decides the slip. Before the first engagement the limits are this
    // state's: a grasp that has not settled yet (a side still at zero) would be handed back at once.
    limits = getRecord(state).releaseLimits;
    if (!limits && !multi_ && options_.releaseTrigger == ApproxReleaseTrigger::Compliance) {
        const SimTK::Transform& X_GO = context_.object.getBodyTransform(state);
        const double mu = findLimitFriction(context_.contactParameters, options_, true);
        limits = calcComplianceLimits(context_, state, reports, mu, calcFrictionLimits(reports, mu), X_GO.R(), X_GO.p(),
                                      options_.releaseGive.value_or(kDefaultReleaseGive));
    }
    if (!limits) return {};
    const std::string obstacle = findReengageObstacle(context_, state, reports, *limits);
    return obstacle.empty() ? obstacle : "the held load at the compliance limits: " + obstacle;
}

// The engage event's text: the threshold and the limits (one force and one torque for the thesis's
// box, every axis for per-axis limits, both sides of every axis for two-sided ones).
std::string GraspSwitch::describeEngagement(double qThreshold, const grasp::AttachmentEngagement& engagement) const {
    const SimTK::Vec6& limits = engagement.limits;
    if (engagement.lowerLimits) {
        return formatText("Q >= Q_Th = %.6g N; compliance limits", qThreshold) + describeTwoSided(*engagement.lowerLimits, limits);
    }
    if (options_.limitModel == grasp::FrictionLimitModel::Thesis) {
        return formatText("Q >= Q_Th = %.6g N; limits %.6g N", qThreshold, limits[3]) + formatText(", %.6g N m", limits[0]);
    }
    return formatText("Q >= Q_Th = %.6g N; contact limits %.6g", qThreshold, limits[3]) + formatText(" %.6g", limits[4]) +
           formatText(" %.6g N, ", limits[5]) + formatText("%.6g %.6g", limits[0], limits[1]) + formatText(" %.6g N m", limits[2]);
}

void GraspSwitch::engage(SimTK::State& state, double quality, const std::vector<contact::ContactReport>& reports,
                         std::optional<ComplianceReleaseLimits> releaseLimits) const {
    updRecord(state).tracker.capture(state, reports);  // penetration, for both attachments; Q tracking is merged's
    const double qThreshold = getRecord(state).qThreshold;
    if (multi_) {
        const std::string limitsText = multi_->engage(state, reports);
        updRecord(state).events.push_back({state.getTime(), GraspEventKind::Engage, quality, formatText("Q >= Q_Th = %.6g N; ", qThreshold) + limitsText});
        return;
    }
    grasp::AttachmentEngagement engagement;
    const contact::ContactParameters& pair = context_.contactParameters;
    const bool compliance = options_.limitModel == grasp::FrictionLimitModel::Compliance;
    const double mu = findLimitFriction(pair, options_, compliance);
    // M at the contact centroid, where the friction acts; for the compliance limits, which are the
    // model's capacities for loads through M's origin, at the object's centre of mass (O's origin),
    // where the loads an object carries act (its weight and inertia, the capacity protocol's ramp).
    const SimTK::Vec3 p_GM = compliance ? context_.object.getBodyOriginLocation(state) : findContactCentroid(reports);
    placeConstraintFrames(state, p_GM, engagement);
    if (options_.limitModel == grasp::FrictionLimitModel::Thesis) {
        engagement.limits = calcFrictionLimits(reports, mu);
    } else if (compliance) {
        const ComplianceReleaseLimits limits =
            calcComplianceLimits(context_, state, reports, mu, calcFrictionLimits(reports, mu), context_.object.getBodyTransform(state).R(), p_GM,
                                 grasp::ComplianceLimitOptions{}.slipDistance);
        engagement.limits = limits.upper;
        engagement.lowerLimits = limits.lower;
    } else {
        engagement.limits = calcContactGeometryLimits(reports, mu, context_.object.getBodyTransform(state).R(), p_GM);
    }
    engagement.leverArm = findLeverArm(reports, p_GM);
    engagement.penetrationBound = options_.maxEngagedPenetration;
    FollowedGrasp followed;
    if (options_.bushingGive == ApproxBushingGive::Model || options_.bushingGive == ApproxBushingGive::Coupled) {
        const bool coupled = options_.bushingGive == ApproxBushingGive::Coupled;
        followed = captureFollowedGrasp(context_, state, reports, setModelGive(context_, state, reports, p_GM, coupled, engagement));
    }
    for (int k = 0; k < 6; ++k) engagement.lockedAxes[k] = !(*options_.relaxedAxes)[k];
    context_.contacts.setPairsEnabled(state, context_.contacts.findAllPairIndices(), false);  // (b)
    setFingersMerged(state, true);                                                        // (c)
    context_.attachment.engage(state, engagement);                                                // (d)
    const SimTK::Transform X_HO = ~context_.palm.getBodyTransform(state) * context_.object.getBodyTransform(state);
    std::string text = describeEngagement(qThreshold, engagement);
    text += describeModelGive(engagement);
    // As --limits compliance computes them (static friction unless told otherwise, M at O's origin
    // with O's orientation), whatever the constraint's own limits are; at the first engagement
    // only, on the unloaded grasp, and kept for the run.
    if (getRecord(state).releaseLimits) {
        text += "; release at the first engagement's compliance limits";
    } else if (releaseLimits) {
        capAtSlipOnset(*releaseLimits, engagement.lowerLimits.value_or(engagement.limits), engagement.limits,
                       engagement.lockedAxes, context_.attachment.getSlipOnsetFraction());
        text += "; release at compliance limits" + describeTwoSided(releaseLimits->lower, releaseLimits->upper) +
                describeSlipOnsetSides(*releaseLimits);
    }
    GraspSwitchRecord& record = updRecord(state);
    record.X_HO_engaged = X_HO;
    record.releaseLimits = releaseLimits;
    if (options_.releaseCreep.value_or(true) && releaseLimits) {
        const auto beyond = findCarriedLoadBeyondEngagement(state, *releaseLimits).value_or(Eigen::Matrix<double, 6, 1>::Zero());
        updCreepWatch(state) = startCreepWatch(*releaseLimits, context_.contactParameters, beyond, state.getTime());
    }
    record.followed = std::move(followed);
    record.events.push_back({state.getTime(), GraspEventKind::Engage, quality, text});  // (e)
}

// F on the palm and M on the object coincide at the contact centroid, with O's orientation.
void GraspSwitch::placeConstraintFrames(const SimTK::State& state, const SimTK::Vec3& p_GC,
                                        grasp::AttachmentEngagement& engagement) const {
    const SimTK::Transform& X_GO = context_.object.getBodyTransform(state);
    const SimTK::Transform& X_GH = context_.palm.getBodyTransform(state);
    engagement.X_OM = SimTK::Transform(~X_GO * p_GC);  // O's orientation
    engagement.X_HF = ~X_GH * X_GO * engagement.X_OM;
}

}  // namespace graspsim::simulation
