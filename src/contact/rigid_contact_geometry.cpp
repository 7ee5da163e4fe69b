#include "graspsim/contact/rigid_contact_geometry.h"

#include <cmath>
#include <sstream>
#include <vector>

#include "graspsim/contact/shape_contact.h"
#include "graspsim/error.h"

namespace graspsim::contact {
namespace {

bool isSweptSphere(const ContactShape& shape) {
    return shape.type == ContactShape::Type::Sphere || shape.type == ContactShape::Type::Capsule;
}

constexpr double kMaxSearchMargin = 1e6;  // m; beyond this the poses cannot be meaningful

}  // namespace

bool isRigidContactSupported(const ContactShape& a, const ContactShape& b) {
    return isSweptSphere(a) || isSweptSphere(b);
}

RigidContactGeometry findRigidContactGeometry(const ContactShape& a, const SimTK::Transform& X_FA,
                                              const ContactShape& b, const SimTK::Transform& X_FB,
                                              double searchMargin) {
    if (!isRigidContactSupported(a, b))
        throw InputError(
            "rigid contact: the pair needs a sphere or a capsule on at least one side "
            "(box-box and box-half-space pairs are not supported by the rigid model)");
    if (!(searchMargin > 0) || !std::isfinite(searchMargin)) {
        std::ostringstream message;
        message << "rigid contact: searchMargin (" << searchMargin << ") must be finite and > 0 m";
        throw InputError(message.str());
    }
    const bool growA = isSweptSphere(a);
    std::vector<ContactPoint> contacts;
    for (double margin = searchMargin; margin <= kMaxSearchMargin; margin *= 8) {
        ContactShape grownA = a;
        ContactShape grownB = b;
        (growA ? grownA : grownB).radius += margin;
        contacts.clear();
        appendContacts(grownA, X_FA, grownB, X_FB, contacts);
        if (contacts.empty()) continue;
        // A swept sphere against anything gives exactly one contact.
        const ContactPoint& c = contacts.front();
        RigidContactGeometry g;
        g.n_F = c.n_G;
        g.separation = margin - c.depth;
        // The grown surface moved by `margin` toward the other shape, so the midpoint moved by
        // half of it: toward B (+n) if A grew, toward A (-n) if B grew.
        g.p_F = c.p_G + (growA ? -0.5 : 0.5) * margin * SimTK::Vec3(c.n_G);
        return g;
    }
    throw NumericalError("rigid contact: no closest point found within 1e6 m (non-finite pose?)");
}

}  // namespace graspsim::contact
