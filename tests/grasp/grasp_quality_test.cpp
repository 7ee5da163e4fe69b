#include "graspsim/grasp/grasp_quality.h"

#include "example_grasps.h"
#include "graspsim/error.h"
#include "graspsim/grasp/ferrari_canny.h"
#include "graspsim/grasp/grasp_matrix.h"

#include <gtest/gtest.h>

#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <random>

using namespace graspsim;
using namespace graspsim::grasp;

namespace {

// All six singular values of G, ascending.
Eigen::VectorXd singularValuesAscending(const Eigen::MatrixXd& G) {
    Eigen::VectorXd s = Eigen::JacobiSVD<Eigen::MatrixXd>(G).singularValues();
    std::sort(s.data(), s.data() + s.size());
    return s;
}

Eigen::VectorXd ascending(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return Eigen::Map<Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
}

QualityOptions withMu(double mu, FrictionCone cone = FrictionCone::Box, int edges = 4) {
    QualityOptions options;
    options.mu = mu;
    options.cone = cone;
    options.edges = edges;
    return options;
}

}  // namespace

TEST(MinSingularValue, IsZeroWithoutContactsOrWithOneContact) {
    EXPECT_EQ(calcGraspQuality({}, {}, {}), 0);
    EXPECT_EQ(calcGraspQuality({examples::antipodalGrasp(0.05)[0]}, {}, {}), 0);
    // Even with 6 basis forces a single contact spans only 3 wrench directions.
    const std::vector<GraspContact> one = {examples::antipodalGrasp(0.05)[0]};
    EXPECT_NEAR(calcGraspQuality(one, {}, withMu(0.5, FrictionCone::Polyhedral, 6)), 0, 1e-15);
}

// Hand computation, box cone, unit normal forces, O at the centre, c_1 = -c_2 = (r, 0, 0),
// n = -+x. Both contacts have M = 4 n n^T + 4 mu^2 (I - n n^T) = diag(4, 4mu^2, 4mu^2).
// The cross blocks cancel (c_1^ M + c_2^ M = 0), so G G^T = blockdiag(2M, 2 c^ M c^T^), and
// c^ = [0 0 0; 0 0 -r; 0 r 0] gives c^ M c^T^ = diag(0, 4 mu^2 r^2, 4 mu^2 r^2). Hence
//     eig(G G^T) = {8, 8mu^2, 8mu^2, 0, 8mu^2 r^2, 8mu^2 r^2},
//     sigma(G)   = {2 sqrt2, 2 sqrt2 mu (x2), 2 sqrt2 mu r (x2), 0}.
// The 0 is torsion about the x axis: point contacts on one line cannot twist the object about it.
TEST(MinSingularValue, AntipodalTwoFingerGraspMatchesHandComputation) {
    const double mu = 0.6, r = 0.05, s2 = std::sqrt(2.0);
    const Eigen::MatrixXd G = calcGraspMatrix(examples::antipodalGrasp(r), {}, withMu(mu));
    const Eigen::VectorXd expected =
        ascending({2 * s2, 2 * s2 * mu, 2 * s2 * mu, 0, 2 * s2 * mu * r, 2 * s2 * mu * r});
    EXPECT_NEAR((singularValuesAscending(G) - expected).norm(), 0, 1e-14);
    EXPECT_NEAR(calcMinSingularValue(G), 0, 1e-14);
}

// Same with the 4-edge polyhedral cone (n +- mu t1, n +- mu t2): M = diag(4, 2mu^2, 2mu^2), so
// sigma(G) = {2 sqrt2, 2mu (x2), 2mu r (x2), 0}.
TEST(MinSingularValue, AntipodalGraspWithFourEdgedPolyhedralCone) {
    const double mu = 0.6, r = 0.05;
    const Eigen::MatrixXd G =
        calcGraspMatrix(examples::antipodalGrasp(r), {}, withMu(mu, FrictionCone::Polyhedral, 4));
    const Eigen::VectorXd expected =
        ascending({2 * std::sqrt(2.0), 2 * mu, 2 * mu, 0, 2 * mu * r, 2 * mu * r});
    EXPECT_NEAR((singularValuesAscending(G) - expected).norm(), 0, 1e-14);
}

// Hand computation, box cone: contacts c_i = r(cos th_i, sin th_i, 0), th_i = 0, 120, 240 deg,
// n_i = -c_i / r. M_i = 4mu^2 I + (4 - 4mu^2) n_i n_i^T, and sum_i n_i n_i^T = (3/2) diag(1,1,0).
//   force block  A = sum M_i = diag(6 + 6mu^2, 6 + 6mu^2, 12 mu^2)
//   cross block  B = sum c_i^ M_i = 4mu^2 (sum c_i)^ = 0   (c_i^ n_i = 0 and sum c_i = 0)
//   torque block C = 4mu^2 sum c_i^ c_i^T^ = 4mu^2 sum (r^2 I - c_i c_i^T)
//                  = mu^2 r^2 diag(6, 6, 12)
// so sigma(G) = {sqrt(6 + 6mu^2) (x2), sqrt12 mu, sqrt6 mu r (x2), sqrt12 mu r}, and for
// r < sqrt2 m the smallest is sqrt6 mu r.
TEST(MinSingularValue, EquilateralThreeFingerGraspMatchesHandComputation) {
    const double mu = 0.5, r = 0.045;
    const Eigen::MatrixXd G = calcGraspMatrix(examples::threeFingerGrasp(r), {}, withMu(mu));
    const double a = std::sqrt(6 + 6 * mu * mu), s6 = std::sqrt(6.0), s12 = std::sqrt(12.0);
    const Eigen::VectorXd expected =
        ascending({a, a, s12 * mu, s6 * mu * r, s6 * mu * r, s12 * mu * r});
    EXPECT_NEAR((singularValuesAscending(G) - expected).norm(), 0, 1e-14);
    EXPECT_NEAR(calcMinSingularValue(G), s6 * mu * r, 1e-15);
    EXPECT_NEAR(calcGraspQuality(examples::threeFingerGrasp(r), {}, withMu(mu)), s6 * mu * r,
                1e-15);
}

// Polyhedral k: M_i = k n n^T + (k mu^2 / 2)(I - n n^T), so C = (k mu^2 / 2) r^2 diag(3/2, 3/2, 3)
// and sigma_min = mu r sqrt(3k) / 2 (for small r).
TEST(MinSingularValue, ThreeFingerGraspWithPolyhedralConesMatchesHandComputation) {
    const double mu = 0.5, r = 0.045;
    for (int k : {3, 4, 8, 16}) {
        EXPECT_NEAR(calcGraspQuality(examples::threeFingerGrasp(r), {},
                                     withMu(mu, FrictionCone::Polyhedral, k)),
                    mu * r * std::sqrt(3.0 * k) / 2, 1e-15)
            << "k = " << k;
    }
}

// With L = r the torque block becomes mu^2 diag(6, 6, 12): sigma_min = min(sqrt12 mu, sqrt6 mu).
TEST(MinSingularValue, TorqueScaleMakesTheGraspSizeIndependent) {
    const double mu = 0.5;
    for (double r : {0.01, 0.045, 0.2}) {
        QualityOptions options = withMu(mu);
        options.torqueScale = r;
        EXPECT_NEAR(calcGraspQuality(examples::threeFingerGrasp(r), {}, options),
                    std::sqrt(6.0) * mu, 1e-14);
    }
}

// Hand computation, box cone, cube of half-size a with L = a: sum_i n_i n_i^T = 2I over the six
// faces, so A = sum M_i = 24mu^2 I + 2(4 - 4mu^2) I = (8 + 16mu^2) I; opposite faces cancel in B;
// C = 4mu^2 sum (a^2 I - c_i c_i^T) / a^2 = 4mu^2 (6I - 2I) = 16mu^2 I. So sigma_min = 4mu.
TEST(MinSingularValue, CubeGraspMatchesHandComputation) {
    for (double mu : {0.2, 0.5}) {
        QualityOptions options = withMu(mu);
        options.torqueScale = 0.04;
        const Eigen::MatrixXd G = calcGraspMatrix(examples::cubeGrasp(0.04), {}, options);
        const double a = std::sqrt(8 + 16 * mu * mu);
        EXPECT_NEAR(
            (singularValuesAscending(G) - ascending({a, a, a, 4 * mu, 4 * mu, 4 * mu})).norm(), 0,
            1e-13);
    }
}

TEST(MinSingularValue, ScalesWithTheNormalForce) {
    std::vector<GraspContact> contacts = examples::threeFingerGrasp(0.045);
    for (GraspContact& c : contacts) c.normalForce = 3.5;
    EXPECT_NEAR(calcGraspQuality(contacts, {}, withMu(0.5)), 3.5 * std::sqrt(6.0) * 0.5 * 0.045,
                1e-14);
}

// Moving the whole scene (contacts and object frame) by a rigid motion changes nothing in O.
TEST(GraspQuality, IsIndependentOfTheWorldFrame) {
    for (QualityMetric metric : {QualityMetric::MinSingularValue, QualityMetric::FerrariCanny}) {
        QualityOptions options = withMu(0.4);
        options.metric = metric;
        options.torqueScale = 0.04;
        std::vector<GraspContact> contacts = examples::threeFingerGrasp(0.04);
        contacts.push_back(examples::cubeGrasp(0.04)[4]);  // a finger on top: no symmetry left
        ObjectFrame frame;
        frame.R_GO = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()).toRotationMatrix();
        frame.p_GO = {0.002, -0.001, 0.003};  // O off the contacts' centre
        const double q = calcGraspQuality(contacts, frame, options);
        EXPECT_GT(q, 1e-3) << toString(metric);
        examples::moveRigidly(contacts, frame, examples::someRotation(), {0.4, -1.2, 2.5});
        EXPECT_NEAR(calcGraspQuality(contacts, frame, options), q, 1e-12) << toString(metric);
    }
}

// Turning each contact's tangent basis about its normal leaves G G^T, hence sigma_min, unchanged
// (the lemma in example_grasps.h), for both cone models.
TEST(MinSingularValue, IsIndependentOfTheTangentBasis) {
    for (QualityOptions options : {withMu(0.7), withMu(0.7, FrictionCone::Polyhedral, 5)}) {
        std::vector<GraspContact> contacts = examples::threeFingerGrasp(0.05);
        contacts.push_back(examples::cubeGrasp(0.05)[5]);
        for (GraspContact& c : contacts) c.p_GC += Eigen::Vector3d(0.01, 0.02, -0.005);
        const double q = calcGraspQuality(contacts, {}, options);
        double angle = 0.4;
        for (GraspContact& c : contacts) {
            const Eigen::Vector3d t1 = findTangent(c.n_G);
            c.t_G = std::cos(angle) * t1 + std::sin(angle) * c.n_G.cross(t1);
            angle += 1.3;
        }
        EXPECT_NEAR(calcGraspQuality(contacts, {}, options), q, 1e-12);
    }
}

TEST(GraspQuality, DispatchesToTheSelectedMetric) {
    const std::vector<GraspContact> contacts = examples::cubeGrasp(0.03);
    QualityOptions options = withMu(0.5);
    const Eigen::MatrixXd G = calcGraspMatrix(contacts, {}, options);
    EXPECT_EQ(calcGraspQuality(contacts, {}, options), calcMinSingularValue(G));
    options.metric = QualityMetric::FerrariCanny;
    EXPECT_EQ(calcGraspQuality(contacts, {}, options), calcFerrariCanny(G));
    EXPECT_GT(calcFerrariCanny(G), 0);
}

// Oracle: Eigen's Jacobi SVD of the same matrix. Random grasp-like matrices from well conditioned
// to singular, so that both the Gram-matrix fast path and the Jacobi fallback are exercised.
TEST(MinSingularValue, AgreesWithTheJacobiSvdFromWellConditionedToSingular) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> entry(-1, 1);
    double worst = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const int columns = 6 + trial % 60;
        Eigen::MatrixXd G(6, columns);
        for (Eigen::Index i = 0; i < G.size(); ++i) G.data()[i] = entry(random);
        G.row(trial % 6) *= std::pow(10.0, -8.0 * (trial % 9) / 8.0);  // sigma_6 / sigma_1 from ~1 to ~1e-8
        if (trial % 5 == 0) G.row((trial + 1) % 6) = 1.001 * G.row(trial % 6) + 1e-3 * G.row((trial + 2) % 6);  // near-double sigma_6
        if (trial % 11 == 0) G.row((trial + 1) % 6) = G.row(trial % 6);   // rank 5: sigma_6 = 0 up to round-off
        const double jacobi = Eigen::JacobiSVD<Eigen::MatrixXd>(G).singularValues()(5);
        const double q = calcMinSingularValue(G);
        const double scale = Eigen::JacobiSVD<Eigen::MatrixXd>(G).singularValues()(0);
        EXPECT_NEAR(q, jacobi, 1e-12 * jacobi + 1e-15 * scale) << "trial " << trial;
        if (jacobi > 1e-6 * scale) worst = std::max(worst, std::abs(q - jacobi) / jacobi);
    }
    EXPECT_LT(worst, 1e-12);
}

TEST(MinSingularValue, RejectsAMatrixThatIsNotSixRows) {
    EXPECT_THROW(calcMinSingularValue(Eigen::MatrixXd::Identity(3, 3)), InputError);
}
