#pragma once
/// @file
/// The compliance release trigger of the grasp switch (`--release-at compliance`,
/// ApproxReleaseTrigger::Compliance; grasp_switch.h): the compliance model's two-sided limits of the
/// grasp at its first engagement (grasp/compliance_limits.h), and where a wrench on the object
/// stands against them. Frame: O's origin (the centre of mass) with O's orientation, moment first.

#include "graspsim/contact/compliant_contact_force.h"
#include "graspsim/simulation/approximation_context.h"

#include "graspsim/simbody.h"

#include <string>
#include <vector>

namespace graspsim::simulation {

/// Two-sided per-axis limits of the grasp's compliance model at engagement (grasp/compliance_limits.h),
/// rotation first (N m for 0-2, N for 3-5): the reaction on the object along axis k of the frame at
/// O's origin with O's orientation stays in [-lower_k, +upper_k].
struct ComplianceReleaseLimits {
    SimTK::Vec6 lower{0};
    SimTK::Vec6 upper{0};
};

/// The first axis side on which `wrench` (on the object about O's origin, along O's axes, moment
/// first: N m, N) has reached `limits`, described with both numbers; empty if it is inside on every axis.
std::string findAxisAtLimit(const SimTK::Vec6& wrench, const ComplianceReleaseLimits& limits);

/// The smallest distance (N m or N, mixed) of `wrench` from the side of `limits` it points to:
/// negative once a side is passed (the release witness's value).
double findLimitMargin(const SimTK::Vec6& wrench, const ComplianceReleaseLimits& limits);

/// The contacts' (`reports`) wrench on the object about O's origin, along O's axes (moment first,
/// N m, N), as the compliance limits' W0 (grasp::calcContactWrenchInM of the compliance model's
/// pressing contacts, simulation::findPressingContact): what the constraint would carry if it
/// engaged in `state`. Needs Stage::Position.
SimTK::Vec6 calcContactWrenchInO(const ApproximationContext& context, const SimTK::State& state,
                                 const std::vector<contact::ContactReport>& reports);

}  // namespace graspsim::simulation
