#include "graspsim/contact/hand_object_pairs.h"

#include "graspsim/error.h"

namespace graspsim::contact {

bool isHandSegmentBody(const model::Body& body) { return body.role != model::BodyRole::Other; }

std::vector<ContactPair> makeHandObjectPairs(const system::MultibodyModel& hand,
                                             const BodyFilter& isHandBody,
                                             const std::string& objectBody,
                                             const ContactParameters& parameters) {
    const model::Body* object = hand.getDescription().findBody(objectBody);
    if (object == nullptr) {
        throw InputError("hand-object contact: model '" + hand.getDescription().name +
                         "' has no object body named '" + objectBody + "'");
    }
    if (isHandBody(*object)) {
        throw InputError("hand-object contact: object body '" + objectBody +
                         "' is also chosen as a hand body");
    }
    return makeHandObjectPairs(hand, isHandBody, hand.getMobilizedBody(objectBody), *object,
                               parameters);
}

std::vector<ContactPair> makeHandObjectPairs(const system::MultibodyModel& hand,
                                             const BodyFilter& isHandBody,
                                             const SimTK::MobilizedBody& objectMobod,
                                             const model::Body& object,
                                             const ContactParameters& parameters) {
    if (object.geometry.empty()) {
        throw InputError("hand-object contact: object body '" + object.name + "' has no geometry");
    }
    std::vector<ContactSurface> objectSurfaces;
    for (const model::Geometry& g : object.geometry) {
        objectSurfaces.push_back(ContactSurface::fromGeometry(objectMobod, object.name, g));
    }
    std::vector<ContactPair> pairs;
    for (const model::Body& body : hand.getDescription().bodies) {
        // Massless joint-chain links have no geometry; the test keeps the rule explicit.
        if (body.isVirtual() || body.geometry.empty() || !isHandBody(body)) continue;
        const SimTK::MobilizedBody& mobod = hand.getMobilizedBody(body.name);
        for (const model::Geometry& g : body.geometry) {
            const ContactSurface handSurface = ContactSurface::fromGeometry(mobod, body.name, g);
            for (const ContactSurface& objectSurface : objectSurfaces) {
                pairs.push_back({handSurface, objectSurface, parameters, true});
            }
        }
    }
    return pairs;
}

}  // namespace graspsim::contact
