#pragma once
/// @file
/// Grasp quality of the current finger-object contacts: the bridge from the contact layer's
/// reports to the grasp layer's metric (the quantity the grasp switch will watch).

#include "graspsim/contact/compliant_contact_force.h"
#include "graspsim/contact/contact_parameters.h"
#include "graspsim/grasp/quality_options.h"

#include "graspsim/simbody.h"

#include <vector>

namespace graspsim::simulation {

/// Grasp quality (grasp::calcGraspQuality) of the contacts in `reports` acting on the object,
/// whose frame O has pose X_GO. Each contact's friction-basis forces are scaled by its normal
/// force (the thesis builds them from the contact solution); the object is surface b of every
/// pair, so n_G (from a toward b) points into it. No contacts give 0.
double calcContactGraspQuality(const std::vector<contact::ContactReport>& reports, const SimTK::Transform& X_GO,
                               const grasp::QualityOptions& options);

/// The options of the simulation's grasp quality Q for contacts with `contact`'s parameters:
/// mu = the static friction (what a held, sticking grasp can use), the other options at their
/// defaults (box cone, smallest singular value: the thesis's Q). The recorder, the grasp switch
/// and the engaged tracker all take these, so that the recorded Q, Q_Th and the engaged Q are
/// one quantity.
grasp::QualityOptions makeQualityOptions(const contact::ContactParameters& contact);

}  // namespace graspsim::simulation
