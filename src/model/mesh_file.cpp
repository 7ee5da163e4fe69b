#include "graspsim/model/mesh_file.h"

#include "graspsim/error.h"
#include "graspsim/model/triangle_mesh.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace graspsim::model {

namespace {

std::string formatNumber(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

void checkFinite(const Vec3& v, const std::string& what) {
    if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) {
        throw InputError(what + " has a vertex that is not a finite number (" + formatNumber(v[0]) + ", " +
                         formatNumber(v[1]) + ", " + formatNumber(v[2]) + "); give finite coordinates");
    }
}

// Triangles of every mesh in the scene, vertices of equal position joined. assimp's
// JoinIdenticalVertices keeps apart vertices whose normals differ (every corner of an STL file,
// which stores one normal per face), so positions are joined here as well: closedness is a
// property of positions.
TriangleMesh collectTriangles(const aiScene& scene, const Vec3& scale, const std::string& what) {
    TriangleMesh mesh;
    std::map<Vec3, int> indexOf;
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        const aiMesh& part = *scene.mMeshes[m];
        for (unsigned f = 0; f < part.mNumFaces; ++f) {
            const aiFace& face = part.mFaces[f];
            if (face.mNumIndices != 3) continue;  // points and lines bound no volume
            std::array<int, 3> triangle{};
            for (int k = 0; k < 3; ++k) {
                const aiVector3D& v = part.mVertices[face.mIndices[k]];
                const Vec3 p{v.x * scale[0], v.y * scale[1], v.z * scale[2]};
                checkFinite(p, what);  // before the map, which cannot order NaN
                const auto [it, added] = indexOf.emplace(p, static_cast<int>(mesh.vertices.size()));
                if (added) mesh.vertices.push_back(p);
                triangle[k] = it->second;
            }
            mesh.triangles.push_back(triangle);
        }
    }
    return mesh;
}

}  // namespace

void checkSolidConvexMesh(const TriangleMesh& mesh, const std::string& what) {
    if (mesh.triangles.empty()) throw InputError(what + " has no triangles; give a closed convex STL or OBJ mesh");
    for (const Vec3& v : mesh.vertices) checkFinite(v, what);
    if (const auto edge = findOpenEdge(mesh)) {
        const Vec3& a = mesh.vertices[edge->first];
        const Vec3& b = mesh.vertices[edge->second];
        throw InputError(what + " is not closed: the edge from (" + formatNumber(a[0]) + ", " + formatNumber(a[1]) +
                         ", " + formatNumber(a[2]) + ") to (" + formatNumber(b[0]) + ", " + formatNumber(b[1]) +
                         ", " + formatNumber(b[2]) +
                         ") is not shared by exactly two triangles; give a closed (watertight) mesh");
    }
    const double volume = calcMeshMassProperties(mesh).mass;
    if (volume < 0) {
        throw InputError(what + " has inverted normals (enclosed volume " + formatNumber(volume) +
                         " m^3 < 0); order each triangle counter-clockwise seen from outside");
    }
    if (volume == 0) throw InputError(what + " encloses no volume; give a solid mesh");
    const double hullVolume = calcConvexHullVolume(mesh, what);
    if (hullVolume > volume * (1 + kConvexVolumeTolerance)) {
        throw InputError(what + " is not convex: its convex hull has volume " + formatNumber(hullVolume) +
                         " m^3 vs " + formatNumber(volume) +
                         " m^3 for the mesh; pass a convex mesh (e.g. the hull)");
    }
}

TriangleMesh readMeshFile(const std::string& path, const Vec3& scale, const std::string& place) {
    const std::string what = place + " '" + path + "'";
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error) || !std::ifstream(path)) {
        throw InputError(what + " is not a readable file; give an STL or OBJ mesh file");
    }
    std::ifstream file(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << file.rdbuf();
    if (!file) throw InputError(what + " cannot be read; give a readable STL or OBJ mesh file");
    std::string format = std::filesystem::path(path).extension().string();
    if (!format.empty()) format.erase(0, 1);
    return parseMeshBytes(bytes.str(), format, scale, what);
}

TriangleMesh parseMeshBytes(const std::string& bytes, const std::string& format, const Vec3& scale,
                            const std::string& what) {
    if (bytes.empty()) throw InputError(what + " is empty; give a closed convex STL or OBJ mesh");
    Assimp::Importer importer;
    const aiScene* scene =
        importer.ReadFileFromMemory(bytes.data(), bytes.size(),
                                    aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                        aiProcess_PreTransformVertices,
                                    format.c_str());
    if (!scene || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) {
        throw InputError(what + " cannot be read as a mesh (assimp: " + foldToOneLine(importer.GetErrorString()) +
                         "); give an STL (ASCII or binary) or OBJ file");
    }
    TriangleMesh mesh = collectTriangles(*scene, scale, what);
    checkSolidConvexMesh(mesh, what);
    return mesh;
}

}  // namespace graspsim::model
