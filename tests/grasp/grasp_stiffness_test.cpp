#include "graspsim/grasp/grasp_stiffness.h"

#include "graspsim/error.h"

#include "pressing_contact.h"

#include <gtest/gtest.h>

namespace graspsim::grasp {
namespace {

using Matrix6 = Eigen::Matrix<double, 6, 6>;

// A plate 2a thick pinched along x by two spherical pads of radius rho with force N, each contact
// a normal spring k_n and a tangential one k_t in series with a finger of compliance c: along the
// pinch 2 / (1 / k_n + c), across it 2 / (1 / k_t + c); turned across the pinch the pads' tangential
// springs form a couple 2 a^2 / (1 / k_t + c) and the preload's rolling adds 2 N (rho + a); about
// the pinch axis point contacts hold nothing. By symmetry nothing couples.
TEST(GraspStiffness, APinchedPlateHasItsSpringsInSeriesAndTheRollingCouple) {
    const double n = 1.3, kn = 2.1e4, kt = 1.4e4, c = 3e-4;
    for (const double rho : {0.006, 0.011}) {
        for (const double a : {0.0015, 0.0045}) {
            std::vector<CompliantContact> pinch{examples::makePressingContact({-a, 0, 0}, {1, 0, 0}, n, kn, kt, c),
                                                examples::makePressingContact({a, 0, 0}, {-1, 0, 0}, n, kn, kt, c)};
            for (CompliantContact& contact : pinch) contact.fingerCurvature = 1 / rho;
            const Matrix6 k = calcStickingGraspStiffness(pinch, Eigen::Vector3d::Zero());
            const double normal = 2 / (1 / kn + c), tangential = 2 / (1 / kt + c);
            Matrix6 expected = Matrix6::Zero();
            expected.diagonal() << normal, tangential, tangential, 0, tangential * a * a + 2 * n * (rho + a),
                tangential * a * a + 2 * n * (rho + a);
            EXPECT_LT((k - expected).norm(), 1e-9 * expected.norm()) << k;
        }
    }
}

// Taken about a point off the contacts, the same grasp's stiffness is the one about the centre
// moved by the rigid map: K_Q = T^T K_P T, T = [I, q^ ; 0, I], q from P to Q (untouched by rolling: no curvatures).
TEST(GraspStiffness, MovesWithTheReferencePointAsARigidMap) {
    const std::vector<CompliantContact> grasp{
        examples::makePressingContact({0.01, -0.02, 0.005}, {-0.6, 0.8, 0}, 2.0, 1.5e4, 1e4, 2e-4),
        examples::makePressingContact({-0.015, 0.01, 0.0}, {0.8, -0.2, 0.1}, 1.1, 1.2e4, 0.9e4, 1e-4),
        examples::makePressingContact({0.0, 0.02, -0.012}, {0.1, -0.7, 0.7}, 0.7, 1.8e4, 1.1e4, 0)};
    const Eigen::Vector3d d(0.004, -0.007, 0.011);
    const Matrix6 about0 = calcStickingGraspStiffness(grasp, Eigen::Vector3d::Zero());
    const Matrix6 aboutD = calcStickingGraspStiffness(grasp, -d);
    Eigen::Matrix3d dHat;
    dHat << 0, -d.z(), d.y(), d.z(), 0, -d.x(), -d.y(), d.x(), 0;
    Matrix6 t = Matrix6::Identity();
    t.block<3, 3>(0, 3) = -dHat;  // q = -d from the old point to the new
    const Matrix6 moved = t.transpose() * about0 * t;
    EXPECT_LT((aboutD - moved).norm(), 1e-9 * about0.norm()) << aboutD << "\n\n" << moved;
}

TEST(GraspStiffness, RefusesAContactWithoutStiffness) {
    const std::vector<CompliantContact> grasp{examples::makePressingContact({0, 0, 0}, {1, 0, 0}, 1.0, 0, 1e4)};
    EXPECT_THROW(calcStickingGraspStiffness(grasp, Eigen::Vector3d::Zero()), InputError);
}

}  // namespace
}  // namespace graspsim::grasp
