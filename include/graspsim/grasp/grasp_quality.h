#pragma once
/// @file
/// Grasp quality Q: the number the grasp approximation compares with its thresholds (thesis
/// section 2.2.1 and chapter 4: contacts are replaced by one constraint once Q >= Q_Th, and
/// restored when Q < Q_M).

#include "graspsim/grasp/grasp_contact.h"
#include "graspsim/grasp/quality_options.h"

#include <Eigen/Core>

#include <vector>

namespace graspsim::grasp {

/// Smallest singular value of the 6 x n grasp matrix G (the thesis's Q; same units as G's
/// entries: N per unit normal force with the default torque scale). It is sigma_6, the sixth
/// singular value, so it is 0 when G has fewer than 6 columns (no contacts: 0; one box-cone
/// contact: 0) and near 0 (round-off) whenever G has rank < 6, e.g. two antipodal point contacts,
/// which cannot resist torsion about the line through them. Unlike Ferrari–Canny it does not
/// test force closure: it measures how well the basis forces span wrench space.
/// @throws graspsim::InputError if G does not have 6 rows or has a non-finite entry.
double calcMinSingularValue(const Eigen::MatrixXd& G);

/// Q of the grasp: builds G (calcGraspMatrix) and applies options.metric.
/// @throws graspsim::InputError as calcGraspMatrix does.
double calcGraspQuality(const std::vector<GraspContact>& contacts, const ObjectFrame& frame,
                        const QualityOptions& options);

}  // namespace graspsim::grasp
