#include "graspsim/grasp/ferrari_canny.h"

#include "example_grasps.h"
#include "graspsim/error.h"
#include "graspsim/grasp/grasp_matrix.h"

#include <gtest/gtest.h>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace graspsim;
using namespace graspsim::grasp;

namespace {

// Independent oracle 1, exact: every facet of a 6-D polytope spans a hyperplane through 6 affinely
// independent vertices, so trying every 6-subset of the columns and keeping the hyperplanes with
// all columns on one side finds every facet; epsilon is the nearest one's distance (0 if the
// origin is not strictly inside). No qhull, no linear programming.
double bruteForceFacetEpsilon(const Eigen::MatrixXd& G) {
    const int n = static_cast<int>(G.cols());
    const double scale = G.cwiseAbs().maxCoeff();
    double epsilon = std::numeric_limits<double>::infinity();
    std::vector<int> idx = {0, 1, 2, 3, 4, 5};
    while (true) {
        Eigen::Matrix<double, 5, 6> edges;
        for (int r = 0; r < 5; ++r) edges.row(r) = (G.col(idx[r + 1]) - G.col(idx[0])).transpose();
        Eigen::FullPivLU<Eigen::Matrix<double, 5, 6>> lu(edges);
        lu.setThreshold(1e-10);
        if (lu.rank() == 5) {
            Eigen::Matrix<double, 6, 1> a = lu.kernel().col(0).normalized();
            double b = a.dot(G.col(idx[0]));
            if (b < 0) {
                a = -a;
                b = -b;
            }
            const Eigen::VectorXd side = a.transpose() * G;
            const bool allBelow = (side.array() <= b + 1e-12 * scale).all();
            const bool allAbove = (side.array() >= b - 1e-12 * scale).all();
            if (allBelow)
                epsilon = std::min(epsilon, b);  // origin on the hull's side
            else if (allAbove)
                epsilon = std::min(epsilon, -b);  // origin beyond this facet
        }
        int k = 5;  // next 6-subset in lexicographic order
        while (k >= 0 && idx[k] == n - 6 + k) --k;
        if (k < 0) break;
        ++idx[k];
        for (int m = k + 1; m < 6; ++m) idx[m] = idx[m - 1] + 1;
    }
    return std::max(0.0, epsilon);
}

// Independent oracle 2, from the definition: epsilon = min over unit d of h(d) = max_j d . w_j.
// Random directions give an upper bound; a shrinking random local search from the best ones
// closes in on the minimizing facet normal.
double supportFunction(const Eigen::MatrixXd& G, const Eigen::Matrix<double, 6, 1>& d) {
    return (d.normalized().transpose() * G).maxCoeff();
}

double sampledEpsilon(const Eigen::MatrixXd& G) {
    std::mt19937 rng(12345);
    std::normal_distribution<double> gauss;
    auto randomDirection = [&] {
        Eigen::Matrix<double, 6, 1> d;
        for (int i = 0; i < 6; ++i) d(i) = gauss(rng);
        return Eigen::Matrix<double, 6, 1>(d.normalized());
    };
    std::vector<std::pair<double, Eigen::Matrix<double, 6, 1>>> samples;
    for (int s = 0; s < 20000; ++s) {
        const Eigen::Matrix<double, 6, 1> d = randomDirection();
        samples.emplace_back(supportFunction(G, d), d);
    }
    std::partial_sort(samples.begin(), samples.begin() + 20, samples.end(),
                      [](const auto& a, const auto& b) { return a.first < b.first; });
    double best = samples.front().first;
    for (int start = 0; start < 20; ++start) {
        auto [h, d] = samples[start];
        for (double step = 0.3; step > 1e-6; step *= 0.7) {
            for (int tries = 0; tries < 60; ++tries) {
                const Eigen::Matrix<double, 6, 1> candidate =
                    (d + step * randomDirection()).normalized();
                const double hc = supportFunction(G, candidate);
                if (hc < h) {
                    h = hc;
                    d = candidate;
                }
            }
        }
        best = std::min(best, h);
    }
    return best;
}

Eigen::MatrixXd crossPolytope() {
    Eigen::MatrixXd G(6, 12);
    G << Eigen::MatrixXd::Identity(6, 6), -Eigen::MatrixXd::Identity(6, 6);
    return G;
}

}  // namespace

// Hand oracle: the facet of the cross-polytope conv{+-e_k} through e_1..e_6 is sum x_k = 1, at
// distance 1/sqrt(6) from the origin; by symmetry every facet is.
TEST(FerrariCanny, CrossPolytopeHasInradiusOneOverRootSix) {
    EXPECT_NEAR(calcFerrariCanny(crossPolytope()), 1 / std::sqrt(6.0), 1e-14);
}

// Hand oracle: the hypercube [-1, 1]^6 has facets x_k = +-1, at distance 1.
TEST(FerrariCanny, HypercubeHasInradiusOne) {
    Eigen::MatrixXd G(6, 64);
    for (int v = 0; v < 64; ++v)
        for (int k = 0; k < 6; ++k) G(k, v) = (v >> k) & 1 ? 1.0 : -1.0;
    EXPECT_NEAR(calcFerrariCanny(G), 1, 1e-14);
}

TEST(FerrariCanny, IsZeroWhenTheOriginIsOnTheBoundaryOrOutside) {
    // Without -e_6 the origin lies on the facet x_6 = 0.
    EXPECT_NEAR(calcFerrariCanny(crossPolytope().leftCols(11)), 0, 1e-14);
    // Shifted by 0.5 along e_1 + e_2 + e_3: the origin is outside (1.5/sqrt(6) > 1/sqrt(6)).
    Eigen::MatrixXd shifted = crossPolytope();
    shifted.topRows(3).array() += 0.5;
    EXPECT_EQ(calcFerrariCanny(shifted), 0);
}

TEST(FerrariCanny, IsZeroForLowerDimensionalHulls) {
    EXPECT_EQ(calcFerrariCanny(Eigen::MatrixXd(6, 0)), 0);
    EXPECT_EQ(calcFerrariCanny(crossPolytope().leftCols(6)), 0);  // a 5-simplex
    EXPECT_EQ(calcFerrariCanny(calcGraspMatrix(examples::antipodalGrasp(0.05), {}, {})), 0);
    Eigen::MatrixXd flat = crossPolytope();
    flat.row(5).setZero();  // the cross-polytope squashed into x_6 = 0
    EXPECT_EQ(calcFerrariCanny(flat), 0);
}

// All normals in one half-space: the grasp cannot resist a push along +y.
TEST(FerrariCanny, IsZeroWhenNotForceClosure) {
    const Eigen::MatrixXd G = calcGraspMatrix(examples::supportGrasp(), {}, {});
    ASSERT_GT(G.row(1).minCoeff(), 0);  // every wrench pushes up
    EXPECT_EQ(calcFerrariCanny(G), 0);
}

// The symmetric 6-finger cube grasp (box cone, L = a), against both independent oracles.
// Hand upper bound: for the pure x-torque direction d, only the y and z faces' friction forces
// have an x moment, at most a mu, so h(d) = mu (after dividing by L = a) and epsilon <= mu.
// Brute force shows the bound is attained: epsilon = mu.
TEST(FerrariCanny, CubeGraspMatchesBruteForceAndSampledSupportFunction) {
    QualityOptions options;
    options.mu = 0.5;
    options.torqueScale = 0.04;  // the cube's half-size: forces and torques/L comparable
    const Eigen::MatrixXd G = calcGraspMatrix(examples::cubeGrasp(0.04), {}, options);
    const double epsilon = calcFerrariCanny(G);
    EXPECT_NEAR(epsilon, options.mu, 1e-12);
    EXPECT_NEAR(epsilon, bruteForceFacetEpsilon(G), 1e-9);
    const double sampled = sampledEpsilon(G);
    EXPECT_GE(sampled, epsilon * (1 - 1e-9));  // every sample is an upper bound
    EXPECT_NEAR(sampled, epsilon, 0.01 * epsilon);
}

TEST(FerrariCanny, ThreeFingerGraspMatchesBruteForce) {
    QualityOptions options;
    options.mu = 0.7;
    options.torqueScale = 0.05;
    const Eigen::MatrixXd G = calcGraspMatrix(examples::threeFingerGrasp(0.05), {}, options);
    const double epsilon = calcFerrariCanny(G);
    EXPECT_GT(epsilon, 0);
    EXPECT_NEAR(epsilon, bruteForceFacetEpsilon(G), 1e-9);
}

// The header's claim: negating the torque rows or swapping the force and torque blocks (the
// thesis's other conventions) is an orthogonal map of wrench space and leaves epsilon unchanged.
TEST(FerrariCanny, IsUnchangedByTheThesisRowOrderAndSign) {
    QualityOptions options;
    options.torqueScale = 0.04;
    const Eigen::MatrixXd G = calcGraspMatrix(examples::cubeGrasp(0.04), {}, options);
    Eigen::MatrixXd thesisOrder(6, G.cols());
    thesisOrder << -G.bottomRows(3), G.topRows(3);
    EXPECT_NEAR(calcFerrariCanny(thesisOrder), calcFerrariCanny(G), 1e-12);
}

TEST(FerrariCanny, RejectsAMatrixThatIsNotSixRows) {
    try {
        calcFerrariCanny(Eigen::MatrixXd::Identity(3, 8));
        FAIL() << "3-row matrix accepted";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "Ferrari-Canny: the grasp matrix must have 6 rows (got 3)");
    }
    Eigen::MatrixXd G = crossPolytope();
    G(2, 3) = std::nan("");
    EXPECT_THROW(calcFerrariCanny(G), InputError);
}
