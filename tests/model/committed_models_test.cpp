// Pins the generated files in models/ to their one source, the builders: regenerating each must
// reproduce the committed file byte for byte. After changing a builder or a table, run
//   cmake --build build --target regenerate_models
// and commit the result.

#include "graspsim/io/atomic_file.h"
#include "graspsim/model/body_model.h"
#include "graspsim/model/object_model.h"
#include "graspsim/model/urdf_export.h"

#include <gtest/gtest.h>

using namespace graspsim;

namespace {

std::string committed(const std::string& name) {
    return io::readTextFile(std::string(GRASPSIM_SOURCE_DIR) + "/models/" + name);
}

}  // namespace

TEST(CommittedModels, DefaultArmMatchesTheBuilder) {
    EXPECT_EQ(committed("arm_male_reference.urdf"), model::writeUrdf(model::buildBodyModel(model::BuildOptions{})))
        << "models/arm_male_reference.urdf is stale: cmake --build build --target regenerate_models";
}

TEST(CommittedModels, ObjectsMatchTheBuilder) {
    EXPECT_EQ(committed("ball.urdf"), model::writeUrdf(model::buildBallModel()))
        << "models/ball.urdf is stale: cmake --build build --target regenerate_models";
    EXPECT_EQ(committed("phone.urdf"), model::writeUrdf(model::buildPhoneModel()))
        << "models/phone.urdf is stale: cmake --build build --target regenerate_models";
}
