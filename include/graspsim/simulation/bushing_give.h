#pragma once
/// @file
/// The merged bushing's give from the grasp's compliance model: the whole sticking stiffness
/// (ApproxOptions::bushingGive Coupled, the default on the merged bushing; docs/capacity.md, "The
/// bushing's coupled give"), or its rotations only (Model, `--bushing-give model`, "The bushing's
/// rotational give"; a research option).
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
///  - coupled instead: the bushing takes the model's whole 6 x 6 sticking stiffness, in M's axes
///    (rotation first) and symmetrized. A force through the object's centre of mass then turns it
///    as well as shifting it, as full contact's pads and fingers let it: what the diagonal alone
///    misses (along y and -y it let the ball slide while engaged), and what makes the object shift
///    toward the palm under a push as full contact's does (ball -z). Where the symmetrized matrix
///    is not positive definite (a preload that rolls the object unstably), the rotational diagonal
///    is used, and the engagement's event says so;
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

#include <string>
#include <vector>

namespace graspsim::simulation {

/// Sets `engagement.stiffness` (rotations 0-2, N m/rad; translations left to the bound), with
/// `coupled` also `engagement.stiffnessMatrix` (6 x 6, rotation first, along M's axes; when
/// positive definite), and `engagement.preload` (N m, N; along M's axes) from the grasp's compliance model in `state`
/// (contacts `reports`), for the constraint frame M at p_GM (m, in G) with O's orientation. An
/// axis whose model stiffness is not positive keeps the bound's. Nothing is set without a pressing
/// contact. Returns the model's contacts, one per pressing report in order, for the fingers that
/// follow the give (finger_follow.h). Realizes `state` to Stage::Velocity.
std::vector<grasp::CompliantContact> setModelGive(const ApproximationContext& context, const SimTK::State& state,
                                                  const std::vector<contact::ContactReport>& reports, const SimTK::Vec3& p_GM,
                                                  bool coupled, grasp::AttachmentEngagement& engagement);

/// For the engagement's event: "; rotational stiffness from the compliance model a b c N m/rad"
/// (an axis left to the bound named as such), or with a coupled matrix "; stiffness from the
/// compliance model, 6 x 6 coupled, diagonal a b c N m/rad, d e f N/m". Empty without a give.
std::string describeModelGive(const grasp::AttachmentEngagement& engagement);

}  // namespace graspsim::simulation
