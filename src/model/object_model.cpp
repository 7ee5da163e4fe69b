#include "graspsim/model/object_model.h"

#include "graspsim/error.h"
#include "graspsim/model/geometry_inertia.h"
#include "graspsim/model/triangle_mesh.h"

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

namespace {

Geometry makeAxialGeometry(Geometry::Type type, const std::string& name, double radius, double length) {
    Geometry g;
    g.type = type;
    g.name = name;
    g.radius = radius;
    g.length = length;
    return g;
}

}  // namespace

ModelDescription buildCylinderModel(double mass, double radius, double length) {
    return makeSolidObject("cylinder", makeAxialGeometry(Geometry::Type::Cylinder, "cylinder_shape", radius, length),
                           mass);
}

ModelDescription buildCapsuleModel(double mass, double radius, double length) {
    return makeSolidObject("capsule", makeAxialGeometry(Geometry::Type::Capsule, "capsule_shape", radius, length), mass);
}

ModelDescription buildEllipsoidModel(double mass, const Vec3& semiAxes) {
    Geometry ellipsoid;
    ellipsoid.type = Geometry::Type::Ellipsoid;
    ellipsoid.name = "ellipsoid_shape";
    ellipsoid.semiAxes = semiAxes;
    return makeSolidObject("ellipsoid", ellipsoid, mass);
}

ModelDescription buildMeshModel(double mass, const TriangleMesh& mesh, const std::string& meshFile,
                                const Vec3& scale) {
    const Vec3 centroid = calcMeshMassProperties(mesh).p_BCm;
    Geometry g;
    g.type = Geometry::Type::Mesh;
    g.name = "mesh_shape";
    g.meshFile = meshFile;
    g.meshScale = scale;
    // The geometry keeps the file's frame (so an exported URDF can name the file), placed so that
    // the solid's centroid falls on O.
    g.X_BG = Transform::translation({-centroid[0], -centroid[1], -centroid[2]});
    g.mesh = std::make_shared<const TriangleMesh>(mesh);
    return makeSolidObject("mesh", g, mass);
}

ModelDescription buildObjectModel(const std::string& name, const std::string& source) {
    if (name == "ball") return buildBallModel();
    if (name == "phone") return buildPhoneModel();
    throw InputError(source + ": object '" + name + "' is not accepted; use ball or phone");
}

}  // namespace graspsim::model
