#pragma once
/// @file
/// The compliance release trigger of the grasp switch (`--release-at compliance`,
/// ApproxReleaseTrigger::Compliance; grasp_switch.h): the compliance model's two-sided limits of the
/// grasp at its first engagement (grasp/compliance_limits.h), and where a wrench on the object
/// stands against them. Frame: O's origin (the centre of mass) with O's orientation, moment first.

#include "graspsim/contact/compliant_contact_force.h"
#include "graspsim/grasp/compliance_limits.h"
#include "graspsim/simulation/approximation_context.h"

#include "graspsim/simbody.h"

#include <array>
#include <string>
#include <vector>

namespace graspsim::simulation {

/// Two-sided per-axis limits of the grasp's compliance model at engagement (grasp/compliance_limits.h),
/// rotation first (N m for 0-2, N for 3-5): the reaction on the object along axis k of the frame at
/// O's origin with O's orientation stays in [-lower_k, +upper_k].
struct ComplianceReleaseLimits {
    SimTK::Vec6 lower{0};
    SimTK::Vec6 upper{0};
    /// Per side, true where capAtSlipOnset() replaced the model's limit by the constraint's slip onset.
    std::array<bool, 6> lowerAtSlipOnset{};
    std::array<bool, 6> upperAtSlipOnset{};
    /// The model's contacts at engagement in O's frame (points from O's origin, m; normals, forces
    /// in N, finger compliances in m/N, all along O's axes), for the load's own direction
    /// (findDirectionAtLimit); empty: the per-axis sides alone.
    std::vector<grasp::CompliantContact> contacts_O;
    /// The finger segment (contact report's body a) of each of contacts_O, in the same order;
    /// empty where calcComplianceLimits did not fill contacts_O.
    std::vector<std::string> contactBodies;
    /// Where the model measures the slip (m, from O's origin, along O's axes); empty: the contacts.
    std::vector<Eigen::Vector3d> slipPoints_O;
    SimTK::Vec6 w0{0};  ///< the contacts' wrench at engagement (frame and order as the sides)
    double mu = 0;      ///< where a contact breaks loose
    double kineticMu = 0;  ///< at which it then slides
    double slipDistance = 2e-3;  ///< m: the model's give at the slip points that counts as its onset
};
/// Two-sided limits of the constraint frame M (orientation R_GM, origin p_GM, in G) from the
/// compliance model of the grasp in `state` (its contacts `reports`, friction coefficient `mu`,
/// kinetic mu_d from the contact parameters; grasp/compliance_limits.h), rotation first. A side the
/// model never lets go of is capped at 4 `box` (the thesis's limits on that axis, N m and N).
/// `slipDistance` (m, > 0) is the model's give that counts as its onset: the capacity ramp's 2 mm
/// for the constraint's own limits, ApproxOptions::releaseGive for the release trigger's.
ComplianceReleaseLimits calcComplianceLimits(const ApproximationContext& context, const SimTK::State& state,
                                             const std::vector<contact::ContactReport>& reports, double mu,
                                             const SimTK::Vec6& box, const SimTK::Rotation& R_GM, const SimTK::Vec3& p_GM,
                                             double slipDistance);
/// Caps the force sides (axes 3-5) of `limits` at `onsetFraction` times the constraint's limits
/// `lower` and `upper` (N, along the constraint frame M, which has O's orientation): where the
/// model's side lies beyond the constraint's own limit, the constraint starts to slide before the
/// reaction could reach it, and the reaction, clamped there, never would. The moment sides are
/// left alone: the constraint's moment limits are about M's origin (the contact centroid for the
/// thesis's box), the release limits about O's. Locked axes (`locked`, limit infinite) are left too.
void capAtSlipOnset(ComplianceReleaseLimits& limits, const SimTK::Vec6& lower, const SimTK::Vec6& upper,
                    const std::array<bool, 6>& locked, double onsetFraction);
/// " (translation x lower side at the constraint's slip onset)" for each capped side; empty if none.
std::string describeSlipOnsetSides(const ComplianceReleaseLimits& limits);

/// Fills `limits`' model of the load's own direction from the grasp's compliance model's contacts
/// at engagement (`contacts_G`, in G) and O's pose (R_GO, p_GO; m), with the friction and slip
/// points (`options`) of the sides.
void setDirectionModel(ComplianceReleaseLimits& limits, const std::vector<grasp::CompliantContact>& contacts_G,
                       const SimTK::Rotation& R_GO, const SimTK::Vec3& p_GO, const grasp::ComplianceLimitOptions& options);

/// The load the constraint carries beyond the engagement's, w0 - `wrench` (`wrench` the
/// constraint's reaction on the object; frame, order and units as the sides).
Eigen::Matrix<double, 6, 1> findLoadBeyondEngagement(const SimTK::Vec6& wrench, const ComplianceReleaseLimits& limits);

/// The direction model of `limits` (its contacts, friction and slip points; O's origin as the
/// model's origin) followed along `load` (about O's origin, along O's axes, moment first: N m, N)
/// up to `maxLoad` multiples of it (grasp::calcCompliantCapacityAlong).
grasp::CompliantCapacity followDirectionModel(const ComplianceReleaseLimits& limits, const Eigen::Matrix<double, 6, 1>& load,
                                              double maxLoad);

/// The sides are the model's onsets for loads along one axis at a time; a load that combines axes
/// draws on the same friction cones and can reach the model's onset inside every side (the
/// phone's −z ramp, docs/capacity.md). The load the constraint carries beyond the engagement's,
/// w0 - `wrench`, reaches the model's onset along its own direction
/// (grasp::calcCompliantCapacityAlong) when that onset is at most 1 times it: described with the
/// load and the onset; empty if it has not, or without a direction model.
std::string findDirectionAtLimit(const SimTK::Vec6& wrench, const ComplianceReleaseLimits& limits);

/// findAxisAtLimit, then findDirectionAtLimit: the first reason `wrench` is at the limits. With a
/// `name` (what the wrench is, when it is not the constraint's reaction) the axis text names it
/// and the direction text is prefixed by it.
std::string findComplianceLimitReached(const SimTK::Vec6& wrench, const ComplianceReleaseLimits& limits,
                                       const char* name = nullptr);

/// The first axis side on which `wrench` (on the object about O's origin, along O's axes, moment
/// first: N m, N) has reached `limits`, described with both numbers and `name` (what the wrench is);
/// empty if it is inside on every axis.
std::string findAxisAtLimit(const SimTK::Vec6& wrench, const ComplianceReleaseLimits& limits,
                            const char* name = "constraint reaction");

/// The smallest distance (N m or N, mixed) of `wrench` from the side of `limits` it points to:
/// zero or negative once a side is reached (findAxisAtLimit).
double findAxisMargin(const SimTK::Vec6& wrench, const ComplianceReleaseLimits& limits);

/// How far the load beyond engagement (w0 - `wrench`, findDirectionAtLimit) is from the model's
/// onset along its own direction, in the load's Euclidean norm (N m and N mixed): (s - 1) |load|
/// for an onset at s times the load, s up to 2; |load| beyond. Zero or negative exactly when
/// findDirectionAtLimit reports the onset reached; infinite without a direction model or load.
double findDirectionMargin(const SimTK::Vec6& wrench, const ComplianceReleaseLimits& limits);

/// The release witness's value: the smaller of findAxisMargin and findDirectionMargin, zero or
/// negative exactly when findComplianceLimitReached reports a reason. Costs one run of the
/// compliance model along the load (a few small solves).
double findLimitMargin(const SimTK::Vec6& wrench, const ComplianceReleaseLimits& limits);

/// The contacts' (`reports`) wrench on the object about O's origin, along O's axes (moment first,
/// N m, N), as the compliance limits' W0 (grasp::calcContactWrenchInM of the compliance model's
/// pressing contacts, simulation::findPressingContact): what the constraint would carry if it
/// engaged in `state`. Needs Stage::Position.
SimTK::Vec6 calcContactWrenchInO(const ApproximationContext& context, const SimTK::State& state,
                                 const std::vector<contact::ContactReport>& reports);

/// The wrench the attachment would carry if it engaged in `state` and held the object at rest in
/// the palm: the contacts' wrench (calcContactWrenchInO) less the object's inertial wrench
/// relative to the palm, m (a_O - a_P) and I (alpha_O - alpha_H) with a_P the acceleration of the
/// palm point at O's origin (frame and order as calcContactWrenchInO; velocity products left out).
/// Object: m a_O = C + m g + E (contacts C, every other load E); held: m a_P = R + m g + E, so
/// R = C - m (a_O - a_P). In a grasp at rest the two are the contacts' wrench; while the grasp
/// is still taking up a load (the give after a release), the contacts' wrench alone lags the load
/// and the inertial part makes up the rest. Needs Stage::Acceleration.
SimTK::Vec6 calcHeldWrenchInO(const ApproximationContext& context, const SimTK::State& state,
                              const std::vector<contact::ContactReport>& reports);

/// The largest speed (m/s) relative to the palm of the object's material points at the grasp
/// goals (the points the capacity protocol measures slip at). Needs Stage::Velocity.
double findGoalSpeedInPalm(const ApproximationContext& context, const SimTK::State& state);

/// Why the switch must not engage in `state` at `limits` (after a hand-back, the first engagement's;
/// before the first engagement, those it would engage with); empty when it may. Two conditions, both about a grasp that carries a
/// load near the limits it was released at: the object still moves in the palm faster than the
/// contacts' transition velocity (the grasp is still taking up its load, the give after the
/// hand-back, and is not firm), or the wrench the attachment would hold (calcHeldWrenchInO),
/// times the peak of the critically damped bushing's pick-up of it (1 + e^-2), is outside
/// `limits`. Re-engaged during the give, where the contacts' wrench lags the load, the bushing
/// took the whole load, passed the limits and released again, and each release gave the contacts
/// the load anew as a step (docs/capacity.md, "The hand-back's step"). Realizes `state` to
/// Stage::Acceleration.
std::string findReengageObstacle(const ApproximationContext& context, const SimTK::State& state,
                                 const std::vector<contact::ContactReport>& reports, const ComplianceReleaseLimits& limits);

}  // namespace graspsim::simulation
