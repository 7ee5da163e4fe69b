// The suite's plan: every approximation run follows the full-contact run it is compared with,
// and unknown names are rejected naming the option.

#include "graspsim/validation/validation_plan.h"

#include "graspsim/error.h"
#include "graspsim/scenario/scenario_file.h"
#include "graspsim/simulation/setup_check.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

using namespace graspsim;

TEST(ValidationPlan, FullSuiteCoversEveryExperimentPerturbationAndVariantWithReferencesFirst) {
    const std::vector<validation::ValidationRun> runs = validation::makeValidationPlan({});
    std::size_t expected = 0;
    for (const std::string& e : validation::getThesisExperiments()) {
        // Every variant per perturbation, except the CVODE reference, which runs once (no perturbation).
        const std::size_t perturbations = 1 + scenario::findBuiltinScenario(e).perturbations.size();
        expected += perturbations * (validation::getAvailableVariants().size() - 1) + 1;
    }
    ASSERT_EQ(runs.size(), expected + 1);  // + the long hold
    std::set<std::string> seen;
    for (const validation::ValidationRun& r : runs) {
        EXPECT_TRUE(seen.insert(r.id).second) << "duplicate id " << r.id;
        if (!r.reference.empty()) {
            EXPECT_TRUE(seen.count(r.reference)) << r.id << " before its reference";
        }
        EXPECT_EQ(r.options.mode == simulation::SimulationMode::Full, r.variant.rfind("full", 0) == 0) << r.id;
        EXPECT_EQ(r.options.integrator == simulation::IntegratorChoice::Cvode, r.variant == "full-cvode") << r.id;
        EXPECT_EQ(r.options.contact == simulation::ContactModel::Rigid, r.variant == "full-rigid") << r.id;
        EXPECT_EQ(r.options.approx.constraint == simulation::ApproxConstraint::Weld, r.variant.find("weld") != std::string::npos);
        EXPECT_EQ(r.options.approx.attach == simulation::ApproxAttach::Multi, r.variant.find("multi") != std::string::npos);
    }
    EXPECT_TRUE(runs.back().longHold);
    EXPECT_EQ(runs.back().options.duration, 600);
}

TEST(ValidationPlan, QuickIsBallClutchWithoutPerturbationTwoSecondsAfterSettling) {
    validation::PlanOptions options;
    options.quick = true;
    const std::vector<validation::ValidationRun> runs = validation::makeValidationPlan(options);
    ASSERT_EQ(runs.size(), validation::getAvailableVariants().size() - 1);  // no full-rigid
    const double settle = scenario::findBuiltinScenario("ball-clutch").simulation.settleTime;
    for (const validation::ValidationRun& r : runs) {
        EXPECT_EQ(r.scenario, "ball-clutch");
        EXPECT_EQ(r.options.perturbation, "none");
        EXPECT_DOUBLE_EQ(r.options.duration, settle + 2.0);
        EXPECT_FALSE(r.longHold);
        EXPECT_EQ(r.options.contact, simulation::ContactModel::Compliant);
    }
}

TEST(ValidationPlan, ApproximationOnlyStillRunsItsReference) {
    validation::PlanOptions options;
    options.experiments = {"phone-pinch"};
    options.variants = {"approx-bushing-merged"};
    options.longHoldDuration = 0;
    const std::vector<validation::ValidationRun> runs = validation::makeValidationPlan(options);
    ASSERT_EQ(runs.size(), 2 * (1 + scenario::findBuiltinScenario("phone-pinch").perturbations.size()));
    EXPECT_EQ(runs[0].variant, "full");
    EXPECT_EQ(runs[1].reference, runs[0].id);
}

TEST(ValidationPlan, UnknownNamesAreRejectedNamingTheOption) {
    validation::PlanOptions options;
    options.experiments = {"mug-grasp"};
    try {
        validation::makeValidationPlan(options);
        FAIL() << "accepted an unknown experiment";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("--experiment: 'mug-grasp'"), std::string::npos) << e.what();
    }
    options.experiments.clear();
    options.variants = {"approx-glue"};
    EXPECT_THROW(validation::makeValidationPlan(options), InputError);
}

// Every run of the full suite starts a grasp the set-up check accepts (setup_check.h), so
// `graspsim validate` never refuses its own plan.
TEST(ValidationPlan, EveryRunPassesTheSetUpCheck) {
    for (const validation::ValidationRun& run : validation::makeValidationPlan(validation::PlanOptions{})) {
        const simulation::SetupCheck check =
            simulation::checkScenarioSetup(scenario::findBuiltinScenario(run.scenario), run.options);
        EXPECT_LE(check.initialPenetration, simulation::kMaxInitialPenetration) << run.id;
    }
}

// The planned scenes are the built-ins that are not the thesis's, each a scenario that loads.
TEST(ValidationPlan, PlannedExperimentsAreTheBuiltinsBesideTheThesisScenes) {
    const std::vector<std::string>& planned = validation::getPlannedExperiments();
    EXPECT_EQ(planned, (std::vector<std::string>{"ball-tripod", "can-power", "key-lateral"}));
    for (const std::string& name : validation::getThesisExperiments()) {
        EXPECT_EQ(std::find(planned.begin(), planned.end(), name), planned.end()) << name;
    }
    for (const std::string& name : planned) EXPECT_NO_THROW(scenario::findBuiltinScenario(name)) << name;
}
