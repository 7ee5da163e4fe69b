#include "graspsim/grasp/grasp_matrix.h"

#include "example_grasps.h"
#include "graspsim/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace graspsim;
using namespace graspsim::grasp;

namespace {

// The force and torque parts of a wrench column, by name rather than by row index.
Eigen::Vector3d forceOf(const Eigen::MatrixXd& G, int col) { return G.col(col).head<3>(); }
Eigen::Vector3d torqueOf(const Eigen::MatrixXd& G, int col) { return G.col(col).tail<3>(); }

std::string messageOf(const std::vector<GraspContact>& contacts, const ObjectFrame& frame,
                      const QualityOptions& options = {}) {
    try {
        calcGraspMatrix(contacts, frame, options);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST(GraspMatrix, HasOneColumnPerBasisForceContactByContact) {
    QualityOptions options;
    EXPECT_EQ(calcGraspMatrix({}, {}, options).cols(), 0);
    EXPECT_EQ(calcGraspMatrix(examples::threeFingerGrasp(0.05), {}, options).cols(), 12);
    options.cone = FrictionCone::Polyhedral;
    options.edges = 6;
    const Eigen::MatrixXd G = calcGraspMatrix(examples::threeFingerGrasp(0.05), {}, options);
    EXPECT_EQ(G.rows(), 6);
    EXPECT_EQ(G.cols(), 18);
}

// Oracle: w = [f_O ; p_OC x f_O] worked out by hand for an object frame turned 90 degrees about
// z and moved. C = (1, 2, 0) in G, O at (1, 0, 0) with x_O = y_G, so p_OC = (2, 0, 0) in O.
// The finger pushes along -y_G = -x_O; frictionless, so f_O = (-1, 0, 0) and the moment is 0.
// A second contact pushing along +z at C gives f_O = (0, 0, 1), moment p_OC x f_O = (0, -2, 0).
TEST(GraspMatrix, ColumnsAreForceAndMomentAboutTheObjectOriginInTheObjectFrame) {
    ObjectFrame frame;
    frame.R_GO = Eigen::AngleAxisd(examples::kPi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    frame.p_GO = {1, 0, 0};
    GraspContact along, up;
    along.p_GC = up.p_GC = {1, 2, 0};
    along.n_G = {0, -1, 0};
    up.n_G = {0, 0, 1};
    QualityOptions options;
    options.mu = 0;
    const Eigen::MatrixXd G = calcGraspMatrix({along, up}, frame, options);
    EXPECT_NEAR((forceOf(G, 0) - Eigen::Vector3d(-1, 0, 0)).norm(), 0, 1e-15);
    EXPECT_NEAR(torqueOf(G, 0).norm(), 0, 1e-15);
    EXPECT_NEAR((forceOf(G, 4) - Eigen::Vector3d(0, 0, 1)).norm(), 0, 1e-15);
    EXPECT_NEAR((torqueOf(G, 4) - Eigen::Vector3d(0, -2, 0)).norm(), 0, 1e-15);
}

TEST(GraspMatrix, EveryColumnIsTheWrenchOfItsBasisForce) {
    const std::vector<GraspContact> contacts = examples::threeFingerGrasp(0.04);
    QualityOptions options;
    options.mu = 0.8;
    const Eigen::MatrixXd G = calcGraspMatrix(contacts, {}, options);
    for (int i = 0; i < 3; ++i) {
        const Eigen::Vector3d& c = contacts[i].p_GC;
        const Eigen::Vector3d t1 = findTangent(contacts[i].n_G);
        const Eigen::Matrix3Xd f =
            calcFrictionConeBasis(contacts[i].n_G, t1, options.mu, FrictionCone::Box);
        for (int j = 0; j < 4; ++j) {
            EXPECT_NEAR((forceOf(G, 4 * i + j) - f.col(j)).norm(), 0, 1e-15);
            EXPECT_NEAR((torqueOf(G, 4 * i + j) - c.cross(f.col(j))).norm(), 0, 1e-15);
        }
    }
}

TEST(GraspMatrix, TorqueScaleDividesTheTorqueRowsOnly) {
    QualityOptions options;
    const Eigen::MatrixXd G1 = calcGraspMatrix(examples::cubeGrasp(0.03), {}, options);
    options.torqueScale = 0.03;
    const Eigen::MatrixXd GL = calcGraspMatrix(examples::cubeGrasp(0.03), {}, options);
    EXPECT_NEAR((GL.topRows(3) - G1.topRows(3)).norm(), 0, 1e-15);
    EXPECT_NEAR((GL.bottomRows(3) - G1.bottomRows(3) / 0.03).norm(), 0, 1e-13);
}

TEST(GraspMatrix, ScalesWithTheNormalForce) {
    std::vector<GraspContact> contacts = examples::threeFingerGrasp(0.05);
    const Eigen::MatrixXd G1 = calcGraspMatrix(contacts, {}, {});
    contacts[1].normalForce = 2.5;
    contacts[2].normalForce = 0;
    const Eigen::MatrixXd G = calcGraspMatrix(contacts, {}, {});
    EXPECT_NEAR((G.middleCols(0, 4) - G1.middleCols(0, 4)).norm(), 0, 1e-15);
    EXPECT_NEAR((G.middleCols(4, 4) - 2.5 * G1.middleCols(4, 4)).norm(), 0, 1e-14);
    EXPECT_EQ(G.middleCols(8, 4).norm(), 0);
}

TEST(GraspMatrix, UsesAGivenTangentAsFirstFrictionDirection) {
    std::vector<GraspContact> contacts = examples::antipodalGrasp(0.05);
    contacts[0].t_G = Eigen::Vector3d(0, 1, 1).normalized();
    QualityOptions options;
    options.mu = 0.5;
    options.cone = FrictionCone::Polyhedral;
    const Eigen::MatrixXd G = calcGraspMatrix(contacts, {}, options);
    EXPECT_NEAR((forceOf(G, 0) - (contacts[0].n_G + 0.5 * contacts[0].t_G)).norm(), 0, 1e-15);
}

TEST(GraspMatrix, RejectsInvalidContactsNamingTheContactAndValue) {
    std::vector<GraspContact> contacts = examples::threeFingerGrasp(0.05);
    contacts[2].n_G *= 0.5;
    EXPECT_EQ(messageOf(contacts, {}),
              "grasp contact 2: normal n_G has length 0.5; it must be a unit vector (to 1e-6)");
    contacts = examples::threeFingerGrasp(0.05);
    contacts[1].normalForce = -3;
    EXPECT_EQ(messageOf(contacts, {}),
              "grasp contact 1: normalForce (-3) must be finite and >= 0 (N)");
    contacts = examples::threeFingerGrasp(0.05);
    contacts[0].t_G = Eigen::Vector3d(1, 1, 0).normalized();
    EXPECT_EQ(messageOf(contacts, {}).rfind("grasp contact 0: tangent t_G is not perpendicular", 0),
              0u);
    contacts = examples::threeFingerGrasp(0.05);
    contacts[0].p_GC.x() = std::nan("");
    EXPECT_EQ(messageOf(contacts, {}), "grasp contact 0: p_GC has a non-finite component");
}

TEST(GraspMatrix, RejectsAnObjectFrameThatIsNotARotation) {
    ObjectFrame frame;
    frame.R_GO.col(2) *= -1;  // a reflection
    EXPECT_EQ(messageOf(examples::threeFingerGrasp(0.05), frame)
                  .rfind("object frame: R_GO is not a proper rotation", 0),
              0u);
    frame.R_GO = 1.01 * Eigen::Matrix3d::Identity();
    EXPECT_THROW(calcGraspMatrix({}, frame, {}), InputError);
    QualityOptions options;
    options.torqueScale = -1;
    EXPECT_THROW(calcGraspMatrix({}, {}, options), InputError);
}
