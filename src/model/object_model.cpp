#include "graspsim/model/object_model.h"

#include "graspsim/error.h"
#include "graspsim/model/geometry_inertia.h"

namespace graspsim::model {

namespace {

ModelDescription makeSolidObject(const std::string& name, Geometry geometry, double mass) {
    Body body;
    body.name = name;
    const MassProperties mp = calcSolidMassProperties(geometry, mass / calcVolume(geometry));
    body.mass = mass;
    body.p_BCm = mp.p_BCm;
    body.inertia = mp.inertia;
    body.geometry.push_back(std::move(geometry));
    ModelDescription model;
    model.name = name;
    model.bodies.push_back(std::move(body));
    model.validate("object '" + name + "'");
    return model;
}

}  // namespace

ModelDescription buildBallModel(double mass, double radius) {
    Geometry sphere;
    sphere.type = Geometry::Type::Sphere;
    sphere.name = "ball_sphere";
    sphere.radius = radius;
    return makeSolidObject("ball", sphere, mass);
}

ModelDescription buildPhoneModel(double mass, const Vec3& size) {
    Geometry box;
    box.type = Geometry::Type::Box;
    box.name = "phone_box";
    box.halfLengths = {size[0] / 2, size[1] / 2, size[2] / 2};
    return makeSolidObject("phone", box, mass);
}

ModelDescription buildObjectModel(const std::string& name, const std::string& source) {
    if (name == "ball") return buildBallModel();
    if (name == "phone") return buildPhoneModel();
    throw InputError(source + ": object '" + name + "' is not accepted; use ball or phone");
}

}  // namespace graspsim::model
