#include "graspsim/contact/shape_contact.h"

#include "box_contact.h"
#include "box_object_contact.h"
#include "graspsim/error.h"
#include "object_solid_contact.h"
#include "object_solid_surface.h"
#include "swept_sphere_contact.h"

namespace graspsim::contact {

namespace {

bool isSwept(const ContactShape& shape) {
    return shape.type == ContactShape::Type::Sphere || shape.type == ContactShape::Type::Capsule;
}

// Canonical order of the pair's shapes: swept spheres, boxes, the other object solids
// (cylinder, ellipsoid, convex mesh), half-spaces.
int findRank(const ContactShape& shape) {
    if (isSwept(shape)) return 0;
    if (shape.type == ContactShape::Type::Box) return 1;
    if (isObjectSolid(shape)) return 2;
    return 3;
}

// Contacts of a box or object solid `first` with a later-ranked `second` (not a swept sphere).
void appendSolidSolidContacts(const ContactShape& first, const SimTK::Transform& X_GF,
                              const ContactShape& second, const SimTK::Transform& X_GS,
                              std::vector<ContactPoint>& contacts) {
    if (first.type == ContactShape::Type::Box) {
        if (second.type == ContactShape::Type::Box) {
            appendBoxBoxContacts(first, X_GF, second, X_GS, contacts);
        } else if (second.type == ContactShape::Type::HalfSpace) {
            appendBoxHalfSpaceContacts(first, X_GF, X_GS, contacts);
        } else {
            appendBoxObjectContacts(first, X_GF, second, X_GS, contacts);
        }
    } else if (second.type == ContactShape::Type::HalfSpace) {
        appendObjectHalfSpaceContacts(first, X_GF, X_GS, contacts);
    } else {
        throw InputError(
            "contact between two object solids (cylinder, ellipsoid, convex mesh) is not "
            "supported; the hand is made of spheres, capsules and boxes");
    }
}

// Contacts for the pair in canonical order (findRank). Normals point from `first` to `second`.
void appendOrderedContacts(const ContactShape& first, const SimTK::Transform& X_GF,
                           const ContactShape& second, const SimTK::Transform& X_GS, CapsuleContact rule,
                           std::vector<ContactPoint>& contacts) {
    if (isSwept(first)) {
        const SweptSphere swept = makeSweptSphere(first, X_GF);
        if (isSwept(second)) {
            appendSweptSweptContact(swept, makeSweptSphere(second, X_GS), contacts);
        } else if (isObjectSolid(second)) {
            appendSweptObjectContact(swept, second, X_GS, rule, contacts);
        } else {
            appendSweptSolidContact(swept, second, X_GS, rule, contacts);
        }
    } else {
        appendSolidSolidContacts(first, X_GF, second, X_GS, contacts);
    }
}

// Whether (a, b) must be swapped to be in canonical order.
bool isReversed(const ContactShape& a, const ContactShape& b) { return findRank(a) > findRank(b); }

}  // namespace

void appendContacts(const ContactShape& a, const SimTK::Transform& X_GA, const ContactShape& b,
                    const SimTK::Transform& X_GB, std::vector<ContactPoint>& contacts, CapsuleContact rule) {
    if (a.type == ContactShape::Type::HalfSpace && b.type == ContactShape::Type::HalfSpace) {
        throw InputError("contact between two half-spaces is not supported");
    }
    if (!isReversed(a, b)) {
        appendOrderedContacts(a, X_GA, b, X_GB, rule, contacts);
        return;
    }
    const std::size_t first = contacts.size();
    appendOrderedContacts(b, X_GB, a, X_GA, rule, contacts);
    for (std::size_t i = first; i < contacts.size(); ++i) {
        contacts[i].n_G = -contacts[i].n_G;  // computed from b toward a
    }
}

std::vector<ContactPoint> findContacts(const ContactShape& a, const SimTK::Transform& X_GA,
                                       const ContactShape& b, const SimTK::Transform& X_GB) {
    std::vector<ContactPoint> contacts;
    appendContacts(a, X_GA, b, X_GB, contacts);
    return contacts;
}

std::vector<ContactPoint> findContacts(const model::Geometry& a, const SimTK::Transform& X_GA,
                                       const model::Geometry& b, const SimTK::Transform& X_GB) {
    return findContacts(ContactShape::fromGeometry(a), X_GA, ContactShape::fromGeometry(b), X_GB);
}

}  // namespace graspsim::contact
