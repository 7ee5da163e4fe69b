#pragma once
/// @file
/// Signed-distance geometry for rigid (constraint-based) contact: where two posed shapes are
/// closest, along which normal, and how far apart, whether they overlap or not.
///
/// Rigid contact needs the gap of shapes that do not yet touch (to decide which contacts are
/// "proximal" for the next step) as well as the depth of shapes that overlap. findContacts()
/// only reports overlaps, so this adds the gap exactly: at least one of the two shapes must be a
/// swept sphere (sphere or capsule, see shape_contact.h), and that shape's radius is grown by a
/// search margin m before calling findContacts(). Growing the radius of a swept sphere moves
/// its surface by exactly m along the normal, and every signed distance findContacts() uses is
/// exact outside the solids too (point/segment distances, the box's Euclidean exterior
/// distance, the half-space's plane distance), so the gap is exactly m - depth and the normal
/// and the contact point are the true ones. If the inflated shapes still do not overlap, the
/// margin is multiplied by 8 and the query repeated.
///
/// Supported pairs: sphere or capsule against sphere, capsule, box, half-space, cylinder,
/// ellipsoid or convex mesh (either order; the cylinder's, ellipsoid's and polytope's signed
/// distances are exact outside too). Box-box and box-half-space pairs have several simultaneous contacts and are not
/// supported by the rigid model (see rigid_contact.h).
#include "graspsim/simbody.h"

#include "graspsim/contact/contact_shape.h"

namespace graspsim::contact {

/// The closest-point geometry of a pair, expressed in whatever frame F the poses were given in.
struct RigidContactGeometry {
    SimTK::Vec3 p_F{0, 0, 0};  ///< contact point, midway between the two surfaces along n (m)
    SimTK::UnitVec3 n_F;       ///< unit normal, pointing from shape A toward shape B
    double separation = 0;     ///< signed gap between the surfaces along n (m), < 0 if overlapping
};

/// Whether the rigid model supports the pair: at least one shape is a sphere or a capsule.
bool isRigidContactSupported(const ContactShape& a, const ContactShape& b);

/// Closest-point geometry of shape `a` posed at X_FA and shape `b` posed at X_FB (poses of the
/// shape frames in a common frame F).
/// @param searchMargin first radius growth tried (m, > 0); any value gives the same result,
///        a margin larger than the usual gap just avoids repeated queries.
/// @throws graspsim::InputError if the pair is not supported (see isRigidContactSupported()).
/// @throws graspsim::NumericalError if no contact is found within 1e6 m (non-finite poses).
RigidContactGeometry findRigidContactGeometry(const ContactShape& a, const SimTK::Transform& X_FA,
                                              const ContactShape& b, const SimTK::Transform& X_FB,
                                              double searchMargin);

}  // namespace graspsim::contact
