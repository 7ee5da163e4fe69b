// The grasp simulation run by two independent integrators, Simbody's CPodes and the SUNDIALS
// CVODE reference: they must agree on the motion within what their tolerances allow.

#include "graspsim/simulation/grasp_simulation.h"

#include "graspsim/error.h"
#include "graspsim/scenario/scenario_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

using namespace graspsim;

namespace {

std::string toText(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

simulation::SimulationResult runWith(const scenario::Scenario& s, simulation::IntegratorChoice integrator, double duration) {
    simulation::SimulationOptions options;
    options.duration = duration;
    options.integrator = integrator;
    return simulation::runGraspSimulation(s, options);
}

}  // namespace

// Oracle: each integrator keeps its local error within rtol (|y| + 1) (unit length and angle
// scales), and the held grasp is strongly damped (PD-controlled stiff fingers, dissipative
// contact), so errors do not accumulate beyond that band; two solutions each inside the band
// around the true one differ by at most twice its width. The run covers the held approach,
// the release (an Instance-stage change) and 0.3 s of free contact with IK updates every 10 ms.
TEST(IntegratorChoice, CvodeAgreesWithSimbodyCpodesOnBallClutch) {
    const scenario::Scenario s = scenario::findBuiltinScenario("ball-clutch");
    const double duration = 0.8, rtol = s.simulation.accuracy;
    const simulation::SimulationResult simbody = runWith(s, simulation::IntegratorChoice::SimbodyCpodes, duration);
    const simulation::SimulationResult cvode = runWith(s, simulation::IntegratorChoice::Cvode, duration);
    ASSERT_TRUE(simbody.summary.complete) << simbody.summary.failure;
    ASSERT_TRUE(cvode.summary.complete) << cvode.summary.failure;
    ASSERT_EQ(simbody.trajectory.size(), cvode.trajectory.size());
    double maxPositionDifference = 0, maxAngleDifference = 0, positionBound = SimTK::Infinity, angleBound = SimTK::Infinity;
    for (std::size_t k = 0; k < simbody.trajectory.size(); ++k) {
        const simulation::TrajectorySample& a = simbody.trajectory[k];
        const simulation::TrajectorySample& b = cvode.trajectory[k];
        ASSERT_EQ(a.time, b.time);
        maxPositionDifference = std::max(maxPositionDifference, (a.p_GO - b.p_GO).norm());
        positionBound = std::min(positionBound, 2 * rtol * (a.p_GO.norm() + 1));
        for (std::size_t j = 0; j < a.jointAngles.size(); ++j) {
            maxAngleDifference = std::max(maxAngleDifference, std::abs(a.jointAngles[j] - b.jointAngles[j]));
            angleBound = std::min(angleBound, 2 * rtol * (std::abs(a.jointAngles[j]) + 1));
        }
    }
    RecordProperty("max_object_position_difference_m", toText(maxPositionDifference));
    RecordProperty("max_joint_angle_difference_rad", toText(maxAngleDifference));
    RecordProperty("cpodes_steps", toText(static_cast<double>(simbody.summary.steps)));
    RecordProperty("cvode_steps", toText(static_cast<double>(cvode.summary.steps)));
    EXPECT_LT(maxPositionDifference, positionBound);
    EXPECT_LT(maxAngleDifference, angleBound);
    // Both really ran, and CVODE handled every IK update as a scheduled event.
    EXPECT_EQ(simbody.summary.integrator, "simbody-cpodes-bdf");
    EXPECT_EQ(cvode.summary.integrator, "cvode-bdf");
    const long ikUpdates = std::lround(duration / s.controller.ikInterval);
    EXPECT_GE(cvode.summary.integratorStatistics.scheduledEvents, ikUpdates);
    EXPECT_GT(cvode.summary.integratorStatistics.jacobianEvaluations, 0);
}

TEST(IntegratorChoice, ParsesNamesAndRejectsOthers) {
    EXPECT_EQ(simulation::parseIntegratorChoice("cvode", "--integrator"), simulation::IntegratorChoice::Cvode);
    EXPECT_EQ(simulation::parseIntegratorChoice("simbody", "--integrator"), simulation::IntegratorChoice::SimbodyCpodes);
    EXPECT_EQ(simulation::parseIntegratorChoice("implicit", "--integrator"), simulation::IntegratorChoice::LinearlyImplicit);
    EXPECT_EQ(simulation::parseIntegratorChoice("implicit-fixed", "--integrator"),
              simulation::IntegratorChoice::LinearlyImplicitFixed);
    EXPECT_THROW(simulation::parseIntegratorChoice("rk4", "--integrator"), InputError);
}
