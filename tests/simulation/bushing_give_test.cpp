// The merged bushing's give from the grasp's compliance model: its whole coupled stiffness (the
// default, --bushing-give coupled) and its rotations only (--bushing-give model), against the
// second method, full contact.
#include "graspsim/simulation/bushing_give.h"

#include "graspsim/error.h"
#include "graspsim/scenario/scenario_file.h"
#include "graspsim/simulation/grasp_simulation.h"
#include "graspsim/simulation/simulation_options.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>

namespace graspsim {
namespace {

TEST(BushingGive, ModelAndCoupledAreParsedAndNeedTheMergedBushing) {
    EXPECT_EQ(simulation::parseApproxBushingGive("model", "--bushing-give"), simulation::ApproxBushingGive::Model);
    EXPECT_EQ(simulation::parseApproxBushingGive("coupled", "--bushing-give"), simulation::ApproxBushingGive::Coupled);
    EXPECT_EQ(simulation::parseApproxBushingGive("auto", "--bushing-give"), simulation::ApproxBushingGive::Automatic);
    EXPECT_THROW(simulation::parseApproxBushingGive("soft", "--bushing-give"), InputError);
    for (simulation::ApproxBushingGive give : {simulation::ApproxBushingGive::Model, simulation::ApproxBushingGive::Coupled}) {
        simulation::ApproxOptions options;
        options.bushingGive = give;
        EXPECT_NO_THROW(simulation::resolveApproxOptions(options, {}));
        options.constraint = simulation::ApproxConstraint::Weld;
        EXPECT_THROW(simulation::resolveApproxOptions(options, {}), InputError);
        options.constraint = simulation::ApproxConstraint::Bushing;
        options.attach = simulation::ApproxAttach::Multi;
        EXPECT_THROW(simulation::resolveApproxOptions(options, {}), InputError);
    }
}

// The default gives on the merged bushing only; the weld and the multi-bushing keep theirs.
TEST(BushingGive, TheDefaultIsTheCoupledModelOnTheMergedBushingOnly) {
    simulation::ApproxOptions options;
    EXPECT_EQ(options.bushingGive, simulation::ApproxBushingGive::Automatic);
    EXPECT_EQ(simulation::resolveApproxOptions(options, {}).bushingGive, simulation::ApproxBushingGive::Coupled);
    options.constraint = simulation::ApproxConstraint::Weld;
    EXPECT_EQ(simulation::resolveApproxOptions(options, {}).bushingGive, simulation::ApproxBushingGive::Stiff);
    options.constraint = simulation::ApproxConstraint::Bushing;
    options.attach = simulation::ApproxAttach::Multi;
    EXPECT_EQ(simulation::resolveApproxOptions(options, {}).bushingGive, simulation::ApproxBushingGive::Stiff);
}

// The phone pulled along x by a quarter of full contact's ramp slip onset (0.789 N; docs/capacity.md,
// "Below capacity, every force direction"), from just after the engagement, for 1 s. Full contact
// pivots the phone in the pinch by about 2 mm, which the stiff bushing does not (2.23 mm apart).
// With the model's rotational give, and with the default's coupled give, the approximation stays
// engaged and follows full contact within the 2 mm (measured 1.18 mm and 0.79 mm).
TEST(BushingGive, APhonePulledAtAQuarterOfItsCapacityFollowsFullContactEngaged) {
    scenario::Scenario s = scenario::findBuiltinScenario("phone-pinch");
    scenario::Perturbation pull;
    pull.name = "quarter";
    pull.force = {0.25 * 0.7894, 0, 0};
    pull.start = 1.1;
    pull.duration = 1.0;
    s.perturbations = {pull};
    simulation::SimulationOptions options;
    options.duration = pull.start + pull.duration;
    options.accuracy = 3e-4;
    options.perturbation = pull.name;
    const simulation::SimulationResult full = simulation::runGraspSimulation(s, options);
    ASSERT_TRUE(full.summary.complete && full.summary.held) << "the oracle: full contact holds the phone";
    options.mode = simulation::SimulationMode::Approx;
    const std::pair<simulation::ApproxBushingGive, const char*> gives[] = {
        {simulation::ApproxBushingGive::Model, "rotational stiffness from the compliance model"},
        {simulation::ApproxBushingGive::Automatic, "stiffness from the compliance model, 6 x 6 coupled"}};
    for (const auto& [give, text] : gives) {
        options.approx.bushingGive = give;
        const simulation::SimulationResult approx = simulation::runGraspSimulation(s, options);
        ASSERT_TRUE(approx.summary.complete) << approx.summary.failure;
        ASSERT_EQ(approx.events.size(), 1u) << "engaged once and never released";
        EXPECT_NE(approx.events[0].reason.find(text), std::string::npos) << approx.events[0].reason;
        ASSERT_EQ(approx.trajectory.size(), full.trajectory.size());
        double distance = 0;
        for (std::size_t k = 0; k < full.trajectory.size(); ++k) {
            distance = std::max(distance, (approx.trajectory[k].p_GO - full.trajectory[k].p_GO).norm());
        }
        EXPECT_LT(distance, 2e-3) << text;
        RecordProperty(simulation::toString(give) + "_distance_m", std::to_string(distance));
    }
}

}  // namespace
}  // namespace graspsim
