// The bushing's force Jacobians (grasp/limited_bushing_jacobian.h) against a second method:
// central differences of the element's own generalized force, in every speed (D) and along every
// mobility's displacement (K), for a palm on a pin and an object on a free joint, engaged and
// then displaced; and nothing from a released bushing or a sliding axis.

#include "graspsim/grasp/limited_bushing_jacobian.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace graspsim::grasp {
namespace {

using SimTK::Vec3;

// A 250 g palm on a pin about Ground's z, and a 200 g object on a free joint, held by a bushing
// from a frame F on the palm to a frame M on the object (both off the bodies' origins).
struct BushedObject {
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter{system};
    SimTK::GeneralForceSubsystem forces{system};
    SimTK::MobilizedBody::Pin palm;
    SimTK::MobilizedBody::Free object;
    LimitedBushing bushing;
    SimTK::State state;

    // With `coupled`, the bushing takes a coupled stiffness (setStiffness with a matrix) at engagement.
    explicit BushedObject(const std::optional<SimTK::Mat66>& coupled = std::nullopt) {
        const SimTK::Body::Rigid palmBody(SimTK::MassProperties(0.25, Vec3(0), SimTK::UnitInertia::brick(0.04, 0.05, 0.01)));
        const SimTK::Body::Rigid objectBody(SimTK::MassProperties(0.2, Vec3(0), SimTK::UnitInertia::sphere(0.04)));
        palm = SimTK::MobilizedBody::Pin(matter.updGround(), SimTK::Transform(Vec3(0, 0.3, 0)), palmBody, SimTK::Transform());
        object = SimTK::MobilizedBody::Free(matter.updGround(), objectBody);
        const SimTK::Transform X_HF(SimTK::Rotation(0.4, SimTK::XAxis), Vec3(0.02, -0.06, 0.01));
        const SimTK::Transform X_OM(SimTK::Rotation(-0.2, SimTK::YAxis), Vec3(0.01, 0.02, 0));
        bushing = LimitedBushing(forces, palm, X_HF, object, X_OM, SimTK::Vec6(2, 3, 4, 2e4, 3e4, 4e4),
                                 SimTK::Vec6(0.02, 0.03, 0.04, 20, 30, 40));
        state = system.realizeTopology();
        system.realizeModel(state);
        palm.setOneQ(state, 0, 0.3);
        // The object where M meets F, then engaged there and displaced a little.
        system.realize(state, SimTK::Stage::Position);
        const SimTK::Transform X_GO = palm.getBodyTransform(state) * X_HF * ~X_OM;
        object.setQToFitTransform(state, X_GO);
        system.realize(state, SimTK::Stage::Position);
        bushing.resetAnchor(state);
        if (coupled) bushing.setStiffness(state, *coupled, bushing.getDamping());
        object.setQToFitTransform(state, SimTK::Transform(SimTK::Rotation(SimTK::BodyRotationSequence, 1e-3, SimTK::XAxis,
                                                                          -2e-3, SimTK::YAxis, 1e-3, SimTK::ZAxis),
                                                          Vec3(1e-4, -2e-4, 1e-4)) * X_GO);
        palm.setOneU(state, 0, 0.5);
        object.setUToFitAngularVelocity(state, Vec3(0.2, -0.1, 0.3));
        object.setUToFitLinearVelocity(state, Vec3(0.01, 0.02, -0.01));
        system.realize(state, SimTK::Stage::Dynamics);
    }

    // The bushing's generalized forces (one per mobility) at `s`.
    SimTK::Vector calcGeneralizedForce(const SimTK::State& s) const {
        system.realize(s, SimTK::Stage::Velocity);
        SimTK::Vector_<SimTK::SpatialVec> bodyForces(matter.getNumBodies(), SimTK::SpatialVec(Vec3(0), Vec3(0)));
        SimTK::Vector_<Vec3> particles;
        SimTK::Vector mobility(s.getNU(), 0.0), f;
        bushing.calcForceContribution(s, bodyForces, particles, mobility);
        matter.multiplyBySystemJacobianTranspose(s, bodyForces, f);
        return f + mobility;
    }
};

// The diagonal of BushedObject's bushing with rotations and translations coupled (N/rad between
// rotation x and translation y, rotation z and translation x) and translations x and z coupled.
SimTK::Mat66 makeCoupledStiffness() {
    SimTK::Mat66 K;
    const SimTK::Vec6 diagonal(2, 3, 4, 2e4, 3e4, 4e4);
    for (int r = 0; r < 6; ++r) {
        for (int c = 0; c < 6; ++c) K(r, c) = r == c ? diagonal[r] : 0.0;
    }
    K(0, 4) = K(4, 0) = 100;
    K(2, 3) = K(3, 2) = -150;
    K(3, 5) = K(5, 3) = 5e3;
    return K;
}

void expectJacobianMatchesFiniteDifferences(BushedObject& b) {
    // Made as the simulation makes it: through the attachment interface.
    const GraspAttachment& attachment = b.bushing;
    const std::unique_ptr<integration::ForceJacobianContributor> made = attachment.makeForceJacobian(b.matter, b.palm, b.object);
    ASSERT_NE(made, nullptr);
    const integration::ForceJacobianContributor& jacobian = *made;
    const int nu = b.state.getNU();
    SimTK::Matrix D(nu, nu, 0.0), K(nu, nu, 0.0);
    jacobian.addForceJacobians(b.state, D, K);
    double largestD = 0, largestK = 0;
    SimTK::Matrix fdKAll(nu, nu);
    for (int c = 0; c < nu; ++c) {
        const double du = 1e-7;
        SimTK::State plus = b.state, minus = b.state;
        plus.updU()[c] += du;
        minus.updU()[c] -= du;
        const SimTK::Vector fdD = (b.calcGeneralizedForce(plus) - b.calcGeneralizedForce(minus)) / (2 * du);
        // A displacement dx along mobility c: q + N(q) dx.
        const double dx = 1e-7;
        SimTK::Vector unit(nu, 0.0), dq;
        unit[c] = dx;
        b.matter.multiplyByN(b.state, false, unit, dq);
        plus = b.state;
        minus = b.state;
        plus.updQ() += dq;
        minus.updQ() -= dq;
        const SimTK::Vector fdK = (b.calcGeneralizedForce(plus) - b.calcGeneralizedForce(minus)) / (2 * dx);
        for (int r = 0; r < nu; ++r) {
            largestD = std::max(largestD, std::abs(fdD[r]));
            largestK = std::max(largestK, std::abs(fdK[r]));
            EXPECT_NEAR(D(r, c), fdD[r], 1e-5 * (1 + std::abs(fdD[r]))) << "D(" << r << "," << c << ")";
            fdKAll(r, c) = fdK[r];
        }
    }
    // K leaves out the geometric terms (d(J^T)/dq f, and the anchor frame's turning with the palm
    // acting on the 0.2 mm, 2 mrad displacement): measured up to 0.5 % of an entry; 1 % of each
    // entry plus 2e-5 of the largest (4e4) is allowed.
    for (int c = 0; c < nu; ++c) {
        for (int r = 0; r < nu; ++r) {
            EXPECT_NEAR(K(r, c), fdKAll(r, c), 1e-2 * std::abs(fdKAll(r, c)) + 2e-5 * largestK) << "K(" << r << "," << c << ")";
        }
    }
    testing::Test::RecordProperty("largest_K", std::to_string(largestK));
    EXPECT_GT(largestD, 1);    // the 20-40 N s/m damping is in there
    EXPECT_GT(largestK, 1e3);  // and the 2e4-4e4 N/m stiffness
}

TEST(LimitedBushingJacobian, MatchesFiniteDifferencesOfTheGeneralizedForce) {
    BushedObject b;
    expectJacobianMatchesFiniteDifferences(b);
}

// The same with a coupled stiffness: K's off-diagonal blocks reach the mobilities through J^T K J.
TEST(LimitedBushingJacobian, MatchesFiniteDifferencesWithACoupledStiffness) {
    BushedObject b(makeCoupledStiffness());
    ASSERT_EQ(b.bushing.findStiffnessMatrix(b.state)(3, 5), 5e3);
    expectJacobianMatchesFiniteDifferences(b);
}

TEST(LimitedBushingJacobian, ReleasedBushingAndSlidingAxesAddNothing) {
    BushedObject b;
    const LimitedBushingJacobian jacobian(b.matter, b.bushing, b.palm, b.object);
    const int nu = b.state.getNU();
    std::vector<int> active;
    jacobian.appendActiveSet(b.state, active);
    EXPECT_EQ(active, (std::vector<int>{0, 1, 2, 3, 4, 5, 6}));  // enabled, every axis holding
    // Every axis at a limit far below its load and loading: all slide, so no stiffness is left.
    b.bushing.setLimits(b.state, SimTK::Vec6(1e-6));
    for (int k = 0; k < 6; ++k) b.bushing.setAxisLocked(b.state, static_cast<BushingAxis>(k), false);
    b.system.realize(b.state, SimTK::Stage::Dynamics);
    active.clear();
    jacobian.appendActiveSet(b.state, active);
    SimTK::Matrix D(nu, nu, 0.0), K(nu, nu, 0.0);
    jacobian.addForceJacobians(b.state, D, K);
    const int sliding = 6 - (static_cast<int>(active.size()) - 1);  // the axes no longer listed
    RecordProperty("sliding_axes", std::to_string(sliding));
    EXPECT_GE(sliding, 1);
    b.bushing.setEnabled(b.state, false);
    b.system.realize(b.state, SimTK::Stage::Dynamics);
    SimTK::Matrix D0(nu, nu, 0.0), K0(nu, nu, 0.0);
    jacobian.addForceJacobians(b.state, D0, K0);
    active.clear();
    jacobian.appendActiveSet(b.state, active);
    EXPECT_TRUE(active.empty());
    EXPECT_EQ(SimTK::max(SimTK::abs(D0)).norm() + SimTK::max(SimTK::abs(K0)).norm(), 0.0);
}

}  // namespace
}  // namespace graspsim::grasp
