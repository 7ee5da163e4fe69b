#pragma once
/// @file
/// Builds the contact pairs of a grasp: every geometry of the hand's bodies against every
/// geometry of the grasped object, each pair with the same contact parameters.

#include "graspsim/simbody.h"

#include <functional>
#include <string>
#include <vector>

#include "graspsim/contact/contact_pair.h"
#include "graspsim/model/model_description.h"
#include "graspsim/system/multibody_model.h"

namespace graspsim::contact {

/// Chooses the bodies of a model description that take part.
using BodyFilter = std::function<bool(const model::Body&)>;

/// The default hand filter: the bodies the model builder gave the palm or digit role (every hand
/// of the model; filter by name prefix as well for one hand of a humanoid).
bool isHandSegmentBody(const model::Body& body);

/// Pairs (a = hand geometry, b = object geometry) for every geometry of every body of `hand`'s
/// description accepted by `isHandBody` (massless joint-chain bodies are skipped: they carry no
/// geometry) against every geometry of `objectBody`, another body of the same model. Pair order:
/// description body order, then geometry order, then object geometry order.
/// @throws graspsim::InputError if objectBody does not exist, is chosen by the filter, or has no
///         geometry; or if a geometry's shape is invalid (ContactSurface::fromGeometry()). The
///         parameters are validated by the contact element that takes the pairs.
std::vector<ContactPair> makeHandObjectPairs(const system::MultibodyModel& hand,
                                             const BodyFilter& isHandBody,
                                             const std::string& objectBody,
                                             const ContactParameters& parameters);

/// As above for an object that is not part of `hand`'s description (for example a body the
/// simulation added with hand.updMatter()): `object` describes its geometry (in its body frame)
/// and `objectMobod` is the mobilized body carrying it.
std::vector<ContactPair> makeHandObjectPairs(const system::MultibodyModel& hand,
                                             const BodyFilter& isHandBody,
                                             const SimTK::MobilizedBody& objectMobod,
                                             const model::Body& object,
                                             const ContactParameters& parameters);

}  // namespace graspsim::contact
