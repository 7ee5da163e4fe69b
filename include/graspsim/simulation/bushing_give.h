#pragma once
/// @file
/// The merged bushing's rotational give (ApproxOptions::bushingGive Model, `--bushing-give model`;
/// docs/capacity.md, "The bushing's rotational give"): a research option.
///
/// Full contact's object turns in the palm under a load long before it slides: its fingers yield,
/// its contacts' springs shear and its preloaded pads roll (grasp/rolling_stiffness.h). The bushing
/// stiffened for the penetration bound (grasp_switch.h) turns a hundred times less. Here, at
/// engagement:
///  - each rotation axis of M gets the grasp's stiffness about it with M's origin held, the
///    diagonal of the rotational block of the compliance model's sticking stiffness
///    (grasp/grasp_stiffness.h, rolling included), in M's axes;
///  - the translations keep the bound's stiffness: a translation moves the pads along their
///    normals, into the object, while a turn about an axis through the contact centroid mostly
///    slides them along it;
///  - the bushing is preloaded with the contacts' wrench on the object about M's origin, so that
///    taking over from the contacts does not first sag the object into the soft spring;
///  - the locked fingers follow the object's turn by their share of it (finger_follow.h), so that
///    the pads neither sink into the object nor leave it, and full contact takes back fingers that
///    carry the load.

#include "graspsim/contact/compliant_contact_force.h"
#include "graspsim/grasp/compliant_grasp_capacity.h"
#include "graspsim/grasp/grasp_attachment.h"
#include "graspsim/simulation/approximation_context.h"

#include "graspsim/simbody.h"

#include <vector>

namespace graspsim::simulation {

/// Sets `engagement.stiffness` (rotations 0-2, N m/rad; translations left to the bound) and
/// `engagement.preload` (N m, N; along M's axes) from the grasp's compliance model in `state`
/// (contacts `reports`), for the constraint frame M at p_GM (m, in G) with O's orientation. An
/// axis whose model stiffness is not positive keeps the bound's. Nothing is set without a pressing
/// contact. Returns the model's contacts, one per pressing report in order, for the fingers that
/// follow the give (finger_follow.h). Realizes `state` to Stage::Velocity.
std::vector<grasp::CompliantContact> setModelGive(const ApproximationContext& context, const SimTK::State& state,
                                                  const std::vector<contact::ContactReport>& reports, const SimTK::Vec3& p_GM,
                                                  grasp::AttachmentEngagement& engagement);

}  // namespace graspsim::simulation
