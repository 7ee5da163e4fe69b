// Reading STL (ASCII, binary) and OBJ meshes through assimp, and refusing the meshes graspsim
// cannot use: one line naming the place, the file and what is wrong.
#include "graspsim/model/mesh_file.h"

#include "graspsim/error.h"
#include "graspsim/model/triangle_mesh.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

using namespace graspsim::model;

namespace {

const std::string kMeshDir = GRASPSIM_TEST_DATA_DIR "/meshes/";

std::string readError(const std::string& path, const Vec3& scale = {1, 1, 1}) {
    try {
        readMeshFile(path, scale, "test.yaml:9: field 'object.mesh' mesh file");
    } catch (const graspsim::InputError& e) {
        return e.what();
    }
    return "";
}

// Binary STL: 80-byte header, triangle count, then per triangle normal, 3 vertices (float32), 2 spare bytes.
void writeBinaryStl(const std::string& path, const TriangleMesh& mesh) {
    std::ofstream out(path, std::ios::binary);
    char header[80] = "binary STL written by mesh_file_test";
    out.write(header, 80);
    const std::uint32_t count = static_cast<std::uint32_t>(mesh.triangles.size());
    out.write(reinterpret_cast<const char*>(&count), 4);
    for (const auto& t : mesh.triangles) {
        float values[12] = {};
        for (int k = 0; k < 3; ++k)
            for (int i = 0; i < 3; ++i) values[3 + 3 * k + i] = static_cast<float>(mesh.vertices[t[k]][i]);
        out.write(reinterpret_cast<const char*>(values), sizeof values);
        const std::uint16_t spare = 0;
        out.write(reinterpret_cast<const char*>(&spare), 2);
    }
}

// Box 0.04 x 0.06 x 0.02 m as the test files write it (corner at the origin); assimp stores
// single precision, so comparisons allow float rounding.
void expectTestBox(const TriangleMesh& mesh, double scale = 1) {
    EXPECT_EQ(mesh.vertices.size(), 8u);
    EXPECT_EQ(mesh.triangles.size(), 12u);
    const MassProperties mp = calcMeshMassProperties(mesh);
    const double a = 0.04 * scale, b = 0.06 * scale, c = 0.02 * scale, V = a * b * c;
    EXPECT_NEAR(mp.mass, V, 1e-6 * V);
    EXPECT_NEAR(mp.p_BCm[1], b / 2, 1e-7 * b);
    EXPECT_NEAR(mp.inertia.zz, V * (a * a + b * b) / 12, 1e-6 * V * (a * a + b * b) / 12);
}

}  // namespace

TEST(MeshFile, AsciiStlAndObjOfTheSameBoxAgree) {
    expectTestBox(readMeshFile(kMeshDir + "box.stl", {1, 1, 1}, "test"));
    expectTestBox(readMeshFile(kMeshDir + "box.obj", {1, 1, 1}, "test"));
}

TEST(MeshFile, BinaryStlIsRead) {
    const TriangleMesh box = readMeshFile(kMeshDir + "box.obj", {1, 1, 1}, "test");
    const std::string path = (std::filesystem::temp_directory_path() / "graspsim_mesh_file_test_box.stl").string();
    writeBinaryStl(path, box);
    expectTestBox(readMeshFile(path, {1, 1, 1}, "test"));
    std::filesystem::remove(path);
}

TEST(MeshFile, ScaleIsAppliedPerAxis) {
    const TriangleMesh mesh = readMeshFile(kMeshDir + "box.stl", {2, 2, 2}, "test");
    expectTestBox(mesh, 2);
    const TriangleMesh stretched = readMeshFile(kMeshDir + "tetrahedron.obj", {1, 2, 3}, "test");
    EXPECT_NEAR(calcMeshMassProperties(stretched).mass, 6 * 0.03 * 0.03 * 0.03 / 6, 1e-6 * 2.7e-5);
}

TEST(MeshFile, TetrahedronHasItsClosedFormVolume) {
    EXPECT_NEAR(calcMeshMassProperties(readMeshFile(kMeshDir + "tetrahedron.stl", {1, 1, 1}, "test")).mass,
                0.03 * 0.03 * 0.03 / 6, 1e-6 * 4.5e-6);
}

TEST(MeshFile, NonFiniteVertexIsRefused) {
    // A binary STL can hold NaN; it must not slip through the volume comparisons.
    TriangleMesh box = readMeshFile(kMeshDir + "box.obj", {1, 1, 1}, "test");
    box.vertices[3][1] = std::numeric_limits<double>::quiet_NaN();
    const std::string path = (std::filesystem::temp_directory_path() / "graspsim_mesh_file_test_nan.stl").string();
    writeBinaryStl(path, box);
    EXPECT_NE(readError(path).find("not a finite number"), std::string::npos) << readError(path);
    std::filesystem::remove(path);
}

struct BadMesh {
    std::string what;
    std::string file;
    std::vector<std::string> expected;
};

class MeshFileBadInput : public ::testing::TestWithParam<BadMesh> {};

TEST_P(MeshFileBadInput, IsRefusedInOneLine) {
    const BadMesh& bad = GetParam();
    const std::string message = readError(kMeshDir + bad.file);
    ASSERT_FALSE(message.empty()) << bad.what << " was accepted";
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.rfind("test.yaml:9: field 'object.mesh' mesh file '", 0), 0u) << message;
    EXPECT_NE(message.find(bad.file), std::string::npos) << message;
    for (const std::string& part : bad.expected) EXPECT_NE(message.find(part), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    EachCase, MeshFileBadInput,
    ::testing::Values(BadMesh{"missing", "no_such_mesh.stl", {"not a readable file", "STL or OBJ"}},
                      BadMesh{"empty", "empty.stl", {"is empty"}},
                      BadMesh{"open stl", "open_box.stl", {"is not closed", "exactly two triangles"}},
                      BadMesh{"open obj", "open_box.obj", {"is not closed"}},
                      BadMesh{"inverted stl", "inverted_box.stl", {"inverted normals", "-4.8e-05 m^3"}},
                      BadMesh{"inverted obj", "inverted_box.obj", {"inverted normals"}},
                      BadMesh{"not convex stl", "l_shape.stl",
                              {"not convex", "convex hull has volume", "vs 7e-06", "pass a convex mesh"}},
                      BadMesh{"not convex obj", "l_shape.obj", {"not convex"}},
                      BadMesh{"not a mesh", "not_a_mesh.obj", {"STL"}}),
    [](const ::testing::TestParamInfo<BadMesh>& param) {
        std::string name;
        for (char c : param.param.what) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
        return name;
    });
