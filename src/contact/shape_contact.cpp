#include "graspsim/contact/shape_contact.h"

#include "box_contact.h"
#include "graspsim/error.h"
#include "swept_sphere_contact.h"

namespace graspsim::contact {

namespace {

bool isSwept(const ContactShape& shape) {
    return shape.type == ContactShape::Type::Sphere || shape.type == ContactShape::Type::Capsule;
}

// Contacts for the pair in a canonical order: a swept sphere before a solid, a box before a
// half-space. Normals point from `first` to `second`.
void appendOrderedContacts(const ContactShape& first, const SimTK::Transform& X_GF,
                           const ContactShape& second, const SimTK::Transform& X_GS,
                           std::vector<ContactPoint>& contacts) {
    if (isSwept(first)) {
        const SweptSphere swept = makeSweptSphere(first, X_GF);
        if (isSwept(second)) {
            appendSweptSweptContact(swept, makeSweptSphere(second, X_GS), contacts);
        } else {
            appendSweptSolidContact(swept, second, X_GS, contacts);
        }
    } else if (second.type == ContactShape::Type::Box) {
        appendBoxBoxContacts(first, X_GF, second, X_GS, contacts);
    } else {
        appendBoxHalfSpaceContacts(first, X_GF, X_GS, contacts);
    }
}

// Whether (a, b) must be swapped to be in canonical order.
bool isReversed(const ContactShape& a, const ContactShape& b) {
    if (isSwept(a)) return false;
    if (isSwept(b)) return true;
    return a.type == ContactShape::Type::HalfSpace;
}

}  // namespace

void appendContacts(const ContactShape& a, const SimTK::Transform& X_GA, const ContactShape& b,
                    const SimTK::Transform& X_GB, std::vector<ContactPoint>& contacts) {
    if (a.type == ContactShape::Type::HalfSpace && b.type == ContactShape::Type::HalfSpace) {
        throw InputError("contact between two half-spaces is not supported");
    }
    if (!isReversed(a, b)) {
        appendOrderedContacts(a, X_GA, b, X_GB, contacts);
        return;
    }
    const std::size_t first = contacts.size();
    appendOrderedContacts(b, X_GB, a, X_GA, contacts);
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
