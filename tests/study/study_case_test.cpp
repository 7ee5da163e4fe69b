// Cases of a study: grid order and count, seeded sampling (the same seed, the same cases; a
// Latin hypercube uses each stratum once), and sharding (every case exactly once over K shards).

#include "graspsim/error.h"
#include "graspsim/study/study_case.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

using namespace graspsim::study;

namespace {

StudySpec makeSpec(const std::string& sampling, const std::string& extra = "") {
    return parseStudy("name: t\nbase: ball-clutch\naxes:\n  subject.stature: [1.5, 1.7, 1.9]\n"
                      "  contact.static_friction: {from: 0.5, to: 1.0, steps: 6}\n  mode: [full, approx]\n"
                      "sampling: " + sampling + "\n" + extra + "measures: [held]\n",
                      "t.yaml");
}

}  // namespace

TEST(StudyCase, GridHasEveryCombinationOnceLastAxisFastest) {
    const std::vector<StudyCase> cases = expandCases(makeSpec("grid"));
    ASSERT_EQ(cases.size(), 3u * 6u * 2u);
    EXPECT_EQ(cases[0].values, (std::vector<std::string>{"1.5", "0.5", "full"}));
    EXPECT_EQ(cases[1].values, (std::vector<std::string>{"1.5", "0.5", "approx"}));
    EXPECT_EQ(cases[2].values, (std::vector<std::string>{"1.5", "0.6", "full"}));
    EXPECT_EQ(cases.back().values, (std::vector<std::string>{"1.9", "1", "approx"}));
    std::set<std::vector<std::string>> distinct;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        EXPECT_EQ(cases[i].index, static_cast<int>(i));
        distinct.insert(cases[i].values);
    }
    EXPECT_EQ(distinct.size(), cases.size());
}

TEST(StudyCase, SamplingIsSeededAndInRange) {
    const std::vector<StudyCase> a = expandCases(makeSpec("random", "samples: 20\nseed: 7\n"));
    const std::vector<StudyCase> b = expandCases(makeSpec("random", "samples: 20\nseed: 7\n"));
    const std::vector<StudyCase> c = expandCases(makeSpec("random", "samples: 20\nseed: 8\n"));
    ASSERT_EQ(a.size(), 20u);
    bool differs = false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].values, b[i].values);
        differs = differs || a[i].values != c[i].values;
        const double friction = std::stod(a[i].values[1]);
        EXPECT_GE(friction, 0.5);
        EXPECT_LE(friction, 1.0);
        EXPECT_TRUE(a[i].values[2] == "full" || a[i].values[2] == "approx");
    }
    EXPECT_TRUE(differs) << "another seed must give other cases";
}

// Oracle: the definition of a Latin hypercube. Each of the n strata of [0.5, 1] holds exactly one
// case's friction; a list axis of 3 values over 9 cases takes each value 3 times.
TEST(StudyCase, LatinHypercubeUsesEachStratumOnce) {
    const int n = 9;
    const std::vector<StudyCase> cases = expandCases(makeSpec("latin", "samples: 9\n"));
    ASSERT_EQ(cases.size(), static_cast<std::size_t>(n));
    std::set<int> strata;
    std::map<std::string, int> statures;
    for (const StudyCase& c : cases) {
        strata.insert(static_cast<int>((std::stod(c.values[1]) - 0.5) / 0.5 * n));
        ++statures[c.values[0]];
    }
    EXPECT_EQ(strata.size(), static_cast<std::size_t>(n));
    for (const auto& [value, count] : statures) EXPECT_EQ(count, 3) << value;
}

// Every case in exactly one shard, for several K, including K above the case count.
TEST(StudyCase, ShardsRunEveryCaseExactlyOnce) {
    const std::vector<StudyCase> cases = expandCases(makeSpec("grid"));  // 36 cases
    for (int count : {1, 2, 3, 5, 8, 36, 37, 100}) {
        std::map<int, int> runs;
        for (int index = 0; index < count; ++index) {
            const Shard shard = parseShard(std::to_string(index) + "/" + std::to_string(count));
            for (const StudyCase& c : selectShard(cases, shard)) ++runs[c.index];
        }
        ASSERT_EQ(runs.size(), cases.size()) << "K = " << count;
        for (const auto& [index, times] : runs) EXPECT_EQ(times, 1) << "case " << index << ", K = " << count;
    }
}

TEST(StudyCase, ShardSpecOutsideItsRangeIsRefused) {
    for (const char* bad : {"5/4", "4/4", "-1/4", "1/0", "1", "a/b", "1/4/2", "/4", "1/"}) {
        try {
            parseShard(bad);
            ADD_FAILURE() << bad << " accepted";
        } catch (const graspsim::InputError& e) {
            EXPECT_NE(std::string(e.what()).find("--shard: value '" + std::string(bad) + "' is not accepted"), std::string::npos)
                << e.what();
        }
    }
    EXPECT_EQ(parseShard("3/4").index, 3);
    EXPECT_EQ(parseShard("3/4").count, 4);
}
