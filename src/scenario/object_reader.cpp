#include "object_reader.h"

#include <optional>

#include "graspsim/anthropometry/units.h"
#include "graspsim/model/geometry_inertia.h"
#include "graspsim/model/mesh_file.h"
#include "graspsim/model/triangle_mesh.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace graspsim::scenario {

namespace {

constexpr const char* kShapes = "shape must be sphere, box, cylinder, capsule, ellipsoid or mesh";

// The size fields each shape takes; every other size field given is an error.
struct ShapeFields {
    ObjectShape shape;
    std::vector<std::string> keys;
    const char* description;  // "a cylinder has radius and length"
};

const std::vector<ShapeFields>& getShapeFields() {
    static const std::vector<ShapeFields> table{
        {ObjectShape::Sphere, {"radius"}, "a sphere has a radius"},
        {ObjectShape::Box, {"size"}, "a box has a size [x, y, z]"},
        {ObjectShape::Cylinder, {"radius", "length"}, "a cylinder has radius and length"},
        {ObjectShape::Capsule, {"radius", "length"}, "a capsule has radius and length"},
        {ObjectShape::Ellipsoid, {"semi_axes"}, "an ellipsoid has semi_axes [a, b, c]"},
        {ObjectShape::Mesh, {"mesh", "scale"}, "a mesh has mesh (a file) and scale"},
    };
    return table;
}

const std::vector<std::string> kSizeKeys{"radius", "size", "length", "semi_axes", "mesh", "scale"};

ObjectShape readShape(const YamlField& field) {
    const std::string text = field.asText(kShapes);
    for (const ShapeFields& entry : getShapeFields()) {
        if (toString(entry.shape) == text) return entry.shape;
    }
    field.reject(kShapes);
}

void rejectForeignFields(const YamlField& section, const ShapeFields& fields) {
    for (const std::string& key : kSizeKeys) {
        if (std::find(fields.keys.begin(), fields.keys.end(), key) != fields.keys.end()) continue;
        if (const std::optional<YamlField> field = section.find(key)) {
            field->reject(std::string(fields.description) + ", not a " + key);
        }
    }
}

// `scale`: one number for all axes or [sx, sy, sz], each > 0; default 1.
model::Vec3 readMeshScale(const YamlField& section) {
    const std::optional<YamlField> field = section.find("scale");
    if (!field) return {1, 1, 1};
    const NumberRule rule = NumberRule::positive("scale", "");
    if (field->isSequence()) return field->asVec3(rule);
    const double s = field->asNumber(rule);
    return {s, s, s};
}

// The mesh file relative to the scenario file's folder (as written when absolute).
std::string resolveMeshPath(const YamlField& root, const std::string& written) {
    const std::filesystem::path path(written);
    if (path.is_absolute()) return written;
    return (std::filesystem::path(root.getSource()).parent_path() / path).lexically_normal().string();
}

void readMesh(const YamlField& root, const YamlField& section, ObjectSpec& object) {
    const YamlField field = section.require("mesh", "a mesh object needs mesh: a path to an STL or OBJ file");
    object.mesh = field.asText("mesh must be a path to an STL or OBJ file, relative to the scenario file");
    object.meshScale = readMeshScale(section);
    const std::string path = resolveMeshPath(root, object.mesh);
    object.meshData = std::make_shared<const model::TriangleMesh>(
        model::readMeshFile(path, object.meshScale, field.describePlace() + " mesh file"));
    object.meshPath = std::filesystem::absolute(path).lexically_normal().string();
    // The object frame is at the centre of mass: the solid's centroid.
    object.meshCentroid = model::calcMeshMassProperties(*object.meshData).p_BCm;
}

void readDimensions(const YamlField& root, const YamlField& section, ObjectSpec& object) {
    switch (object.shape) {
        case ObjectShape::Sphere:
            object.radius = section.getNumber("radius", NumberRule::positive("radius", "m"));
            break;
        case ObjectShape::Box: object.size = section.getVec3("size", NumberRule::positive("size", "m")); break;
        case ObjectShape::Cylinder:
        case ObjectShape::Capsule:
            object.radius = section.getNumber("radius", NumberRule::positive("radius", "m"));
            object.length = section.getNumber("length", NumberRule::positive("length", "m"));
            break;
        case ObjectShape::Ellipsoid:
            object.semiAxes = section.getVec3("semi_axes", NumberRule::positive("semi-axes", "m"));
            break;
        case ObjectShape::Mesh: readMesh(root, section, object); break;
    }
}

// A mass in grams read as kilograms (mass: 100 for a 100 g phone) gives an object a thousand times
// too dense. The bound is well above the densest solid (osmium, 22,590 kg/m^3), so that a
// deliberately heavy test object (a phone twenty times its weight) still reads.
constexpr double kMaxObjectDensity = 1e5;  // kg/m^3

void checkDensity(const YamlField& section, const ObjectSpec& object) {
    double volume = 0;
    for (const model::Body& body : buildObjectModel(object).bodies) {
        for (const model::Geometry& g : body.geometry) volume += model::calcVolume(g);
    }
    if (!(volume > 0) || object.mass / volume <= kMaxObjectDensity) return;
    char text[240];
    std::snprintf(text, sizeof text, "%g kg in %.3g m^3 is %.3g kg/m^3, denser than any solid (osmium: 22590 kg/m^3); mass is in kg",
                  object.mass, volume, object.mass / volume);
    section.find("mass")->reject(text);
}

}  // namespace

ObjectSpec readObject(const YamlField& root, bool planned) {
    const YamlField section = root.require(
        "object", "a scenario needs the object: shape, mass, its size fields (docs/shapes.md), position");
    section.requireMap({"shape", "mass", "radius", "size", "length", "semi_axes", "mesh", "scale", "position",
                        "orientation"});
    ObjectSpec object;
    object.shape = readShape(section.require("shape", kShapes));
    object.mass = section.getNumber("mass", NumberRule::positive("mass", "kg"));
    for (const ShapeFields& fields : getShapeFields()) {
        if (fields.shape == object.shape) rejectForeignFields(section, fields);
    }
    readDimensions(root, section, object);
    checkDensity(section, object);
    if (planned) {  // the planner places the object
        for (const char* key : {"position", "orientation"}) {
            if (const std::optional<YamlField> field = section.find(key)) {
                field->reject(std::string("the grasp planner places the object: leave out ") + key + " with grasp.type");
            }
        }
        return object;
    }
    object.position = section.getVec3("position", NumberRule::any("position", "m"));
    const model::Vec3 degrees =
        section.findVec3("orientation", NumberRule::closed("orientation", "deg", -360, 360), {0, 0, 0});
    for (int i = 0; i < 3; ++i) object.orientation[i] = anthropometry::fromDegrees(degrees[i]);
    return object;
}

}  // namespace graspsim::scenario
