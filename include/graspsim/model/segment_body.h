#pragma once
/// @file
/// A rigid body for one de Leva (1996) segment, scaled to a subject.
///
/// Scaling: length L = L_ref * stature / stature_ref; mass = massFraction * body mass;
/// centre of mass at comFraction * L from the proximal endpoint; central moments
/// m (r L)^2 with r the radius-of-gyration fraction about each axis.
/// Body frame: origin at the joint that connects the segment to its parent; in the
/// anatomical position x points anterior (sagittal axis), y proximally along the segment's
/// long axis, z to the subject's right (transverse axis). So I_xx uses the sagittal radius,
/// I_yy the longitudinal one and I_zz the transverse one.

#include "graspsim/anthropometry/segment_table.h"
#include "graspsim/anthropometry/subject.h"
#include "graspsim/model/model_description.h"

#include <string>

namespace graspsim::model {

/// Which end of the segment the body frame sits at.
enum class SegmentOrigin {
    Proximal,  ///< at the first endpoint of de Leva's table (limbs hanging from their parent); segment along -y
    Distal     ///< at the second endpoint (trunk and head stacked on the pelvis); segment along +y
};

/// Segment length for the subject (m).
double calcSegmentLength(const anthropometry::SegmentParameters& segment, const anthropometry::Subject& subject);

/// Body for a segment scaled to the subject, with a capsule along the long axis whose radius
/// gives a solid cylinder the segment's longitudinal radius of gyration (R = sqrt(2) r_long L).
Body makeSegmentBody(const anthropometry::SegmentParameters& segment, const anthropometry::Subject& subject,
                     const std::string& name, SegmentOrigin origin);

}  // namespace graspsim::model
