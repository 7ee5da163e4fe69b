#pragma once
/// @file
/// A plan's numbers as its scenario file writes them: joint angles and the object's orientation
/// to 0.1 deg, lengths to 0.1 mm, each the double that the file's decimal reads back as.
///
/// A count of steps times the step carries float noise (1805 * 1e-4 = 0.18050000000000002, and
/// 164 * 0.1 deg in rad divided back gives 16.400000000000002), which the file would show, and
/// which would read back as another double than the plan's. Here the count is divided by 10^k
/// (one correctly rounded division, as the reader's strtod) and degrees are converted with
/// anthropometry::fromDegrees (as the reader converts them), so a planned scenario file shows
/// 0.1805 and 16.4 and reads back as the plan, bit for bit.

#include "graspsim/planning/grasp_planner.h"
#include "graspsim/simbody.h"

namespace graspsim::planning {

/// `count` tenths of a millimetre in metres (m): the double a file's decimal ("0.1805") reads as.
double fromTenthMillimetres(double count);

/// `metres` rounded to 0.1 mm (m), as fromTenthMillimetres.
double roundToTenthMillimetre(double metres);

/// `radians` rounded to 0.1 deg (rad): the radians the scenario reader makes of the decimal
/// degrees ("16.4").
double roundToTenthDegree(double radians);

/// The body-fixed X-Y-Z angles of R_GO (the scenario's object.orientation), each rounded to
/// 0.1 deg (rad). The angles recovered from a rotation built from rounded ones carry float
/// noise; rounding them again removes it.
SimTK::Vec3 findRoundedOrientation(const SimTK::Rotation& R_GO);

/// Rounds, as above, a plan's joint angles, object pose (orientation rebuilt from its rounded
/// angles), goals and added end-effector points; leaves its diagnostics as they are.
void snapToWrittenDecimals(GraspPlan& plan);

}  // namespace graspsim::planning
