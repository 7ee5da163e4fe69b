// The approximation's options resolved before anything is built (simulation_options.h). Oracle:
// the precedence rule itself (a value given to the run wins; 0 or unset takes the scenario's) and
// the accepted ranges, checked on hand-picked values.

#include "graspsim/simulation/simulation_options.h"

#include "graspsim/error.h"
#include "graspsim/scenario/scenario.h"

#include <gtest/gtest.h>

#include <cmath>

#include <string>

using namespace graspsim;

namespace {

scenario::ApproximationSpec makeScenarioSection() {
    scenario::ApproximationSpec spec;
    spec.qThreshold = 3.0;
    spec.qMinimum = 1.0;
    spec.relaxedAxes = {true, false, true, false, true, false};
    return spec;
}

std::string findMessage(const simulation::ApproxOptions& given) {
    try {
        simulation::resolveApproxOptions(given, makeScenarioSection());
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(ResolveApproxOptions, TakesTheScenariosValuesWhereTheRunGivesNone) {
    const simulation::ApproxOptions resolved = simulation::resolveApproxOptions({}, makeScenarioSection());
    EXPECT_EQ(resolved.qThreshold, 3.0);
    EXPECT_EQ(resolved.qMinimum, 1.0);
    ASSERT_TRUE(resolved.relaxedAxes.has_value());
    EXPECT_EQ(*resolved.relaxedAxes, makeScenarioSection().relaxedAxes);
}

TEST(ResolveApproxOptions, ValuesGivenToTheRunWin) {
    simulation::ApproxOptions given;
    given.qThreshold = 5.0;
    given.qMinimum = 2.0;
    given.relaxedAxes = std::array<bool, 6>{false, false, false, true, true, true};
    const simulation::ApproxOptions resolved = simulation::resolveApproxOptions(given, makeScenarioSection());
    EXPECT_EQ(resolved.qThreshold, 5.0);
    EXPECT_EQ(resolved.qMinimum, 2.0);
    EXPECT_EQ(*resolved.relaxedAxes, *given.relaxedAxes);
}

TEST(ResolveApproxOptions, RejectsWhatTheSwitchCannotUse) {
    simulation::ApproxOptions given;
    given.qThreshold = -1;
    EXPECT_NE(findMessage(given).find("must be >= 0"), std::string::npos);
    given = {};
    given.qMinimum = 4.0;  // above the scenario's Q_Th of 3 N
    EXPECT_NE(findMessage(given).find("Q_M (4 N) must be below Q_Th (3 N)"), std::string::npos);
    given = {};
    given.releaseSlideDistance = 0;
    EXPECT_NE(findMessage(given).find("slide distance must be > 0 m"), std::string::npos);
    given = {};
    given.releasePenetration = std::nan("");
    EXPECT_NE(findMessage(given).find("release penetration must be > 0 m"), std::string::npos);
    given = {};
    given.maxEngagedPenetration = -1e-4;
    EXPECT_NE(findMessage(given).find("penetration bound must be > 0 m"), std::string::npos);
    EXPECT_EQ(findMessage({}), "");
}

// The stepper's step: the run's, else the scenario's, else the integrator's own (the IK interval
// with error control, 1 ms at fixed steps); the messages name the same source.
TEST(FindStepSize, TheRunsStepThenTheScenariosThenTheIntegratorsOwn) {
    scenario::Scenario s;
    s.source = "grasp.yaml";
    s.controller.ikInterval = 0.02;
    simulation::SimulationOptions controlled, fixed;
    fixed.integrator = simulation::IntegratorChoice::LinearlyImplicitFixed;
    EXPECT_EQ(simulation::findStepSize(s, controlled).step, 0.02);
    EXPECT_NE(simulation::findStepSize(s, controlled).source.find("controller.ik_interval"), std::string::npos);
    EXPECT_EQ(simulation::findStepSize(s, fixed).step, simulation::kDefaultFixedStepSize);
    EXPECT_NE(simulation::findStepSize(s, fixed).source.find("default fixed step"), std::string::npos);
    s.simulation.stepSize = 0.004;
    for (const simulation::SimulationOptions& o : {controlled, fixed}) {
        EXPECT_EQ(simulation::findStepSize(s, o).step, 0.004);
        EXPECT_EQ(simulation::findStepSize(s, o).source, "grasp.yaml: simulation.step_size");
    }
    controlled.stepSize = fixed.stepSize = 0.003;
    for (const simulation::SimulationOptions& o : {controlled, fixed}) {
        EXPECT_EQ(simulation::findStepSize(s, o).step, 0.003);
        EXPECT_EQ(simulation::findStepSize(s, o).source, "--step-size");
    }
}

// The default integrator: the linearly implicit stepper where it has every stiff element's
// Jacobian (full compliant contact, the merged bushing), CPodes elsewhere; a choice given wins.
TEST(ResolveIntegrator, AutomaticTakesTheImplicitStepperWhereItHasEveryJacobian) {
    scenario::Scenario s;
    simulation::SimulationOptions o;
    ASSERT_EQ(o.integrator, simulation::IntegratorChoice::Automatic);
    EXPECT_EQ(simulation::resolveIntegrator(s, o), simulation::IntegratorChoice::LinearlyImplicit);
    o.mode = simulation::SimulationMode::Approx;
    EXPECT_EQ(simulation::resolveIntegrator(s, o), simulation::IntegratorChoice::LinearlyImplicit);
    o.approx.attach = simulation::ApproxAttach::Multi;
    EXPECT_EQ(simulation::resolveIntegrator(s, o), simulation::IntegratorChoice::SimbodyCpodes);
    o.approx.attach = simulation::ApproxAttach::Merged;
    o.approx.constraint = simulation::ApproxConstraint::Weld;
    EXPECT_EQ(simulation::resolveIntegrator(s, o), simulation::IntegratorChoice::SimbodyCpodes);
    o = simulation::SimulationOptions{};
    s.friction.model = contact::FrictionModel::Anchor;
    EXPECT_EQ(simulation::resolveIntegrator(s, o), simulation::IntegratorChoice::SimbodyCpodes);
    s.friction.model = contact::FrictionModel::Regularized;
    o.contact = simulation::ContactModel::Rigid;
    EXPECT_EQ(simulation::resolveIntegrator(s, o), simulation::IntegratorChoice::SimbodyCpodes);
    o.contact = simulation::ContactModel::Compliant;
    o.integrator = simulation::IntegratorChoice::Cvode;
    EXPECT_EQ(simulation::resolveIntegrator(s, o), simulation::IntegratorChoice::Cvode);
    EXPECT_EQ(simulation::parseIntegratorChoice("auto", "--integrator"), simulation::IntegratorChoice::Automatic);
    EXPECT_EQ(simulation::toString(simulation::IntegratorChoice::Automatic), "auto");
}
