#include "urdf_capsule.h"

#include "urdf_number.h"

#include <algorithm>
#include <cmath>

namespace graspsim::model {

namespace {

bool endsWith(const std::string& text, std::string_view suffix) {
    return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

struct TripletReader {
    const std::vector<Geometry>& geometry;
    std::string field;  // "link '<name>' capsule '<base>'"
    int line;
    const UrdfSource& source;

    const Geometry& findPart(const std::string& base, std::string_view suffix, Geometry::Type type) const {
        const std::string name = base + std::string(suffix);
        const auto count = std::count_if(geometry.begin(), geometry.end(), [&](const Geometry& g) { return g.name == name; });
        if (count != 1) {
            source.reject(line, field + " collision " + quoted(name), count == 0 ? "(missing)" : "repeated",
                          "a capsule is exactly one cylinder '<name>__capsule_cylinder' and two spheres "
                          "'<name>__capsule_cap_pos' and '<name>__capsule_cap_neg'");
        }
        const Geometry& part = *std::find_if(geometry.begin(), geometry.end(), [&](const Geometry& g) { return g.name == name; });
        if (part.type != type) {
            source.reject(line, field + " collision " + quoted(name) + " shape", "not a " + describeType(type),
                          "the capsule encoding needs a cylinder and two spheres");
        }
        return part;
    }

    void checkCap(const Geometry& cylinder, const Geometry& cap, double z) const {
        if (!(std::abs(cap.radius - cylinder.radius) <= kCapsuleTolerance)) {
            source.reject(line, field + " collision " + quoted(cap.name) + " radius", formatUrdfNumber(cap.radius),
                          "the caps must have the cylinder's radius " + formatUrdfNumber(cylinder.radius) + " m");
        }
        const Vec3 expected = cylinder.X_BG.shiftFrameStationToBase({0, 0, z});
        const Vec3& actual = cap.X_BG.p;
        const double distance = std::hypot(actual[0] - expected[0], actual[1] - expected[1], actual[2] - expected[2]);
        if (!(distance <= kCapsuleTolerance)) {
            source.reject(line, field + " collision " + quoted(cap.name) + " origin xyz", formatUrdfTriple(actual),
                          "the cap must be centred on the cylinder end at " + formatUrdfTriple(expected) + " m");
        }
    }

    static std::string describeType(Geometry::Type type) { return type == Geometry::Type::Sphere ? "sphere" : "cylinder"; }
};

Geometry readTriplet(const std::string& base, const TripletReader& reader) {
    const Geometry& cylinder = reader.findPart(base, kCapsuleCylinderSuffix, Geometry::Type::Cylinder);
    reader.checkCap(cylinder, reader.findPart(base, kCapsuleCapPosSuffix, Geometry::Type::Sphere), cylinder.length / 2);
    reader.checkCap(cylinder, reader.findPart(base, kCapsuleCapNegSuffix, Geometry::Type::Sphere), -cylinder.length / 2);
    Geometry capsule = cylinder;
    capsule.type = Geometry::Type::Capsule;
    capsule.name = base;
    return capsule;
}

}  // namespace

bool hasCapsuleSuffix(const std::string& name) {
    return endsWith(name, kCapsuleCylinderSuffix) || endsWith(name, kCapsuleCapPosSuffix) ||
           endsWith(name, kCapsuleCapNegSuffix);
}

std::array<Geometry, 3> splitCapsule(const Geometry& capsule) {
    Geometry cylinder = capsule;
    cylinder.type = Geometry::Type::Cylinder;
    cylinder.name = capsule.name + std::string(kCapsuleCylinderSuffix);
    Geometry capPos = capsule;
    capPos.type = Geometry::Type::Sphere;
    capPos.length = 0;
    capPos.name = capsule.name + std::string(kCapsuleCapPosSuffix);
    capPos.X_BG.p = capsule.X_BG.shiftFrameStationToBase({0, 0, capsule.length / 2});
    Geometry capNeg = capPos;
    capNeg.name = capsule.name + std::string(kCapsuleCapNegSuffix);
    capNeg.X_BG.p = capsule.X_BG.shiftFrameStationToBase({0, 0, -capsule.length / 2});
    return {cylinder, capPos, capNeg};
}

std::vector<Geometry> mergeCapsuleTriplets(const std::vector<Geometry>& geometry, const std::string& linkName, int line,
                                           const UrdfSource& source) {
    std::vector<Geometry> merged;
    for (const Geometry& g : geometry) {
        if (!hasCapsuleSuffix(g.name)) {
            merged.push_back(g);
            continue;
        }
        // Every part finds its own cylinder, so a stray cap is reported too; the capsule is
        // emitted once, where its cylinder stands.
        const std::string_view suffix = endsWith(g.name, kCapsuleCylinderSuffix) ? kCapsuleCylinderSuffix
                                        : endsWith(g.name, kCapsuleCapPosSuffix) ? kCapsuleCapPosSuffix
                                                                                 : kCapsuleCapNegSuffix;
        const std::string base = g.name.substr(0, g.name.size() - suffix.size());
        const TripletReader reader{geometry, "link " + quoted(linkName) + " capsule " + quoted(base), line, source};
        const Geometry capsule = readTriplet(base, reader);
        if (suffix == kCapsuleCylinderSuffix) merged.push_back(capsule);
    }
    return merged;
}

}  // namespace graspsim::model
