// The new object shapes end to end, from scenario file to simulated grasp, against shapes whose
// motion they must reproduce: the phone as a mesh of its box moves as the box phone, and the ball
// as an ellipsoid of equal semi-axes moves as the sphere. The approach is shortened to 0.05 s, so
// the 0.3 s run is mostly the released object settling in the fingers.

#include "graspsim/scenario/scenario_file.h"
#include "graspsim/simulation/grasp_simulation.h"

#include "scratch_folder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <algorithm>


namespace graspsim::simulation {
namespace {

namespace fs = std::filesystem;

std::string replaceOnce(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

// A built-in scenario's text with the approach and settling shortened.
std::string readShortScenario(const std::string& name) {
    std::ifstream in(fs::path(GRASPSIM_SOURCE_DIR) / "models/scenarios" / (name + ".yaml"));
    std::stringstream text;
    text << in.rdbuf();
    return replaceOnce(replaceOnce(text.str(), "approach_time: 0.5 ", "approach_time: 0.05"), "settle_time: 1.0 ",
                       "settle_time: 0.15");
}

// Largest distance between the object's centres of mass at equal output times (m).
double calcLargestDrift(const SimulationResult& a, const SimulationResult& b) {
    EXPECT_EQ(a.trajectory.size(), b.trajectory.size());
    double largest = 0, moved = 0;
    for (std::size_t i = 0; i < std::min(a.trajectory.size(), b.trajectory.size()); ++i) {
        largest = std::max(largest, (a.trajectory[i].p_GO - b.trajectory[i].p_GO).norm());
        moved = std::max(moved, (a.trajectory[i].p_GO - a.trajectory[0].p_GO).norm());
    }
    // The comparison means something only if the object moved (released, pressed by the fingers).
    EXPECT_GT(moved, 100 * largest);
    return largest;
}

SimulationResult runShort(const scenario::Scenario& scenario) {
    SimulationOptions options;
    options.duration = 0.3;
    return runGraspSimulation(scenario, options);
}

TEST(ObjectShapeScenario, PhoneAsAMeshOfItsBoxMovesAsTheBox) {
    const fs::path dir = graspsim::testing::makeScratchFolder("shape_scenario");
    // The phone's box, 0.07 x 0.14 x 0.008 m, as an OBJ file (a corner-centred box would do too:
    // the object frame goes to the centroid).
    std::ofstream obj(dir / "phone.obj");
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            for (int k = 0; k < 2; ++k) obj << "v " << (i - 0.5) * 0.07 << " " << (j - 0.5) * 0.14 << " " << (k - 0.5) * 0.008 << "\n";
    for (const char* face : {"1 2 4", "1 4 3", "5 7 8", "5 8 6", "1 5 6", "1 6 2", "3 4 8", "3 8 7", "1 3 7", "1 7 5", "2 6 8", "2 8 4"})
        obj << "f " << face << "\n";
    obj.close();
    const std::string text = readShortScenario("phone-pinch");
    const std::string meshText =
        replaceOnce(replaceOnce(text, "shape: box", "shape: mesh"), "size: [0.070, 0.140, 0.008]", "mesh: phone.obj");
    const scenario::Scenario box = scenario::parseScenario(text, "phone-pinch.yaml");
    const scenario::Scenario mesh = scenario::parseScenario(meshText, (dir / "phone-mesh.yaml").string());
    fs::remove_all(dir);
    // assimp reads single precision: the mesh's corners are off by up to 4e-9 m, and full contact
    // with the controller's ramped targets carries such a difference to about 0.09 mm over the run;
    // 0.5 mm is a quarter of the validation suite's 2 mm agreement bound between two methods.
    EXPECT_LT(calcLargestDrift(runShort(box), runShort(mesh)), 5e-4);
}

TEST(ObjectShapeScenario, BallAsARoundEllipsoidMovesAsTheSphere) {
    const std::string text = readShortScenario("ball-clutch");
    const std::string ellipsoidText = replaceOnce(replaceOnce(text, "shape: sphere ", "shape: ellipsoid "),
                                                  "radius: 0.045 ", "semi_axes: [0.045, 0.045, 0.045] ");
    const scenario::Scenario sphere = scenario::parseScenario(text, "ball-clutch.yaml");
    const scenario::Scenario ellipsoid = scenario::parseScenario(ellipsoidText, "ball-ellipsoid.yaml");
    EXPECT_LT(calcLargestDrift(runShort(sphere), runShort(ellipsoid)), 1e-6);
}

}  // namespace
}  // namespace graspsim::simulation
