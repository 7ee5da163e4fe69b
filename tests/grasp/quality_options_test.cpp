#include "graspsim/grasp/quality_options.h"

#include "graspsim/error.h"

#include <gtest/gtest.h>

#include <limits>

using namespace graspsim;

TEST(QualityOptions, DefaultsAreTheThesisBoxConeAndMinSingularValue) {
    const grasp::QualityOptions options;
    EXPECT_EQ(options.cone, grasp::FrictionCone::Box);
    EXPECT_EQ(options.metric, grasp::QualityMetric::MinSingularValue);
    EXPECT_EQ(options.torqueScale, 1.0);
    EXPECT_NO_THROW(grasp::validate(options));
}

TEST(QualityOptions, RejectsBadFieldsNamingTheValue) {
    grasp::QualityOptions options;
    options.torqueScale = 0;
    try {
        grasp::validate(options);
        FAIL() << "zero torque scale accepted";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "grasp quality: torqueScale (0) must be finite and > 0 (m)");
    }
    options.torqueScale = std::numeric_limits<double>::infinity();
    EXPECT_THROW(grasp::validate(options), InputError);
    options = {};
    options.mu = -1;
    EXPECT_THROW(grasp::validate(options), InputError);
    options = {};
    options.cone = grasp::FrictionCone::Polyhedral;
    options.edges = 2;
    EXPECT_THROW(grasp::validate(options), InputError);
}

TEST(QualityMetric, ParsesWhatToStringWrites) {
    for (auto metric : {grasp::QualityMetric::MinSingularValue, grasp::QualityMetric::FerrariCanny})
        EXPECT_EQ(grasp::parseQualityMetric(grasp::toString(metric), "--metric"), metric);
    try {
        grasp::parseQualityMetric("epsilon", "--metric");
        FAIL() << "unknown metric accepted";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(),
                     "--metric: unknown grasp quality metric 'epsilon' (accepted: "
                     "min-singular-value, ferrari-canny)");
    }
}
