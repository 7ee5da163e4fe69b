// A plan's numbers rounded as its scenario file writes them. Oracles: the C library's strtod of
// the decimal text a file holds, and anthropometry::fromDegrees of it, as the scenario reader
// converts a written angle; the rounded values must be those doubles exactly, not the noisy
// products of a count and its step (1805 * 1e-4 = 0.18050000000000002).

#include "graspsim/planning/plan_rounding.h"

#include "graspsim/anthropometry/units.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

using namespace graspsim;
using namespace graspsim::planning;

namespace {

// n tenths of a unit's 10^-k written out: "-0.1805" for n = -1805, k = 4.
std::string writeDecimal(int n, int decimals) {
    int scale = 1;
    for (int i = 0; i < decimals; ++i) scale *= 10;
    char text[32];
    std::snprintf(text, sizeof text, "%s%d.%0*d", n < 0 ? "-" : "", std::abs(n) / scale, decimals, std::abs(n) % scale);
    return text;
}

}  // namespace

TEST(PlanRounding, TenthsOfAMillimetreAreTheDoublesTheirDecimalsReadAs) {
    int wrong = 0, noisyProducts = 0;
    for (int n = -20000; n <= 20000; ++n) {  // -2 m to 2 m
        const double written = std::strtod(writeDecimal(n, 4).c_str(), nullptr);
        noisyProducts += n * 1e-4 != written;
        for (const double metres : {n * 1e-4, (n + 0.3) * 1e-4, (n - 0.3) * 1e-4}) {
            if (roundToTenthMillimetre(metres) != written) ++wrong;
        }
        if (fromTenthMillimetres(n) != written) ++wrong;
    }
    EXPECT_EQ(wrong, 0);
    EXPECT_GT(noisyProducts, 1000);  // what the rounding used to give instead
    EXPECT_EQ(roundToTenthMillimetre(-0.18050000000000002), std::strtod("-0.1805", nullptr));
}

TEST(PlanRounding, TenthsOfADegreeAreTheRadiansTheirDecimalsReadAs) {
    int wrong = 0;
    for (int n = -3600; n <= 3600; ++n) {  // -360 deg to 360 deg
        const double read = anthropometry::fromDegrees(std::strtod(writeDecimal(n, 1).c_str(), nullptr));
        const double noisy = n * 0.1 * anthropometry::fromDegrees(1.0);  // the count times the step
        for (const double radians : {noisy, read, anthropometry::fromDegrees((n + 0.3) * 0.1)}) {
            if (roundToTenthDegree(radians) != read) ++wrong;
        }
    }
    EXPECT_EQ(wrong, 0);
}

// The object's orientation: the angles recovered from a rotation built from rounded ones carry
// float noise (97.60000000000001 deg); rounded again, they are the written angles exactly.
TEST(PlanRounding, AnOrientationBuiltFromRoundedAnglesGivesThemBack) {
    const double degree = anthropometry::fromDegrees(1.0);
    for (const SimTK::Vec3& written : {SimTK::Vec3(97.6, 20.9, -145), SimTK::Vec3(93.6, 55.1, -109.6), SimTK::Vec3(-0.1, 0, 179.9)}) {
        const SimTK::Vec3 xyz(anthropometry::fromDegrees(written[0]), anthropometry::fromDegrees(written[1]),
                              anthropometry::fromDegrees(written[2]));
        const SimTK::Rotation R_GO(SimTK::BodyRotationSequence, xyz[0], SimTK::XAxis, xyz[1], SimTK::YAxis, xyz[2], SimTK::ZAxis);
        const SimTK::Vec3 recovered = R_GO.convertRotationToBodyFixedXYZ();
        EXPECT_NEAR(recovered[0] / degree, written[0], 1e-9);
        const SimTK::Vec3 rounded = findRoundedOrientation(R_GO);
        for (int i = 0; i < 3; ++i) EXPECT_EQ(rounded[i], xyz[i]) << written << " component " << i;
    }
}

// A plan's rounded numbers, each snapped to its written decimal; its diagnostics stay.
TEST(PlanRounding, SnappingAPlanRoundsEveryNumberItsFileWrites) {
    GraspPlan plan;
    plan.jointAngles["index_dip_flexion"] = 164 * 0.1 * anthropometry::fromDegrees(1.0);
    plan.X_GO = SimTK::Transform(SimTK::Vec3(4631 * 1e-4, -1805 * 1e-4, -269 * 1e-4));
    plan.goals["thumb_tip"] = SimTK::Vec3(3 * 1e-4, -27 * 1e-4, 554 * 1e-4);
    model::SegmentPoint point;
    point.p_B[0] = 3 * 1e-4;
    plan.segmentPoints.push_back(point);
    plan.diagnostics.quality = 0.5;
    snapToWrittenDecimals(plan);
    EXPECT_EQ(plan.jointAngles.at("index_dip_flexion"), anthropometry::fromDegrees(16.4));
    EXPECT_EQ(plan.X_GO.p(), SimTK::Vec3(0.4631, -0.1805, -0.0269));
    EXPECT_EQ(plan.goals.at("thumb_tip"), SimTK::Vec3(0.0003, -0.0027, 0.0554));
    EXPECT_EQ(plan.segmentPoints[0].p_B[0], 0.0003);
    for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < 3; ++k) EXPECT_EQ(plan.X_GO.R()[i][k], i == k ? 1.0 : 0.0);
    }
    EXPECT_EQ(plan.diagnostics.quality, 0.5);
}
