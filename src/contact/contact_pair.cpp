#include "graspsim/contact/contact_pair.h"

#include "graspsim/error.h"

namespace graspsim::contact {

ContactSurface ContactSurface::fromGeometry(const SimTK::MobilizedBody& body,
                                            const std::string& bodyName,
                                            const model::Geometry& geometry) {
    ContactSurface surface;
    surface.body = body;
    surface.bodyName = bodyName;
    surface.shapeName = geometry.name;
    try {
        surface.shape = ContactShape::fromGeometry(geometry);
        surface.X_BS = findGeometryPose(geometry);
    } catch (const InputError& e) {
        throw InputError("body '" + bodyName + "' " + e.what());
    }
    return surface;
}

std::string ContactPair::describe() const {
    return a.bodyName + "/" + a.shapeName + " vs " + b.bodyName + "/" + b.shapeName;
}

}  // namespace graspsim::contact
