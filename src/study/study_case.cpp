#include "graspsim/study/study_case.h"

#include "graspsim/error.h"

#include <algorithm>
#include <cstdio>
#include <random>

namespace graspsim::study {

namespace {

std::string formatNumber(double value, int digits) {
    char text[40];
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    return text;
}

// A grid axis's values: its list, or `steps` evenly spaced numbers of its range.
std::vector<std::string> listGridValues(const StudyAxis& axis) {
    if (!axis.isRange) return axis.values;
    std::vector<std::string> values;
    const ValueRange& r = axis.range;
    for (int i = 0; i < r.steps; ++i) values.push_back(formatNumber(r.from + (r.to - r.from) * i / (r.steps - 1), 12));
    return values;
}

std::vector<StudyCase> expandGrid(const StudySpec& spec) {
    std::vector<std::vector<std::string>> values;
    std::size_t total = 1;
    for (const StudyAxis& axis : spec.axes) {
        values.push_back(listGridValues(axis));
        total *= values.back().size();
    }
    std::vector<StudyCase> cases(total);
    for (std::size_t c = 0; c < total; ++c) {
        cases[c].index = static_cast<int>(c);
        cases[c].values.resize(values.size());
        std::size_t rest = c;  // mixed-radix digits, the last axis fastest
        for (std::size_t a = values.size(); a-- > 0;) {
            cases[c].values[a] = values[a][rest % values[a].size()];
            rest /= values[a].size();
        }
    }
    return cases;
}

// A uniform number in [0, 1) from 53 bits of the generator: std::mt19937_64's sequence is fixed
// by the standard, the library's distributions are not, and the cases must not depend on it.
double drawUnit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// The axis's value at position u in [0, 1): a point of its range or an item of its list.
std::string pickValue(const StudyAxis& axis, double u) {
    if (axis.isRange) return formatNumber(axis.range.from + u * (axis.range.to - axis.range.from), 6);
    const std::size_t n = axis.values.size();
    return axis.values[std::min(n - 1, static_cast<std::size_t>(u * static_cast<double>(n)))];
}

// Fisher-Yates with drawUnit, for the same reason.
std::vector<int> drawPermutation(int n, std::mt19937_64& rng) {
    std::vector<int> order(n);
    for (int i = 0; i < n; ++i) order[i] = i;
    for (int i = n - 1; i > 0; --i) std::swap(order[i], order[static_cast<int>(drawUnit(rng) * (i + 1))]);
    return order;
}

std::vector<StudyCase> expandSample(const StudySpec& spec) {
    std::mt19937_64 rng(spec.seed);
    std::vector<StudyCase> cases(spec.samples);
    for (int c = 0; c < spec.samples; ++c) {
        cases[c].index = c;
        cases[c].values.resize(spec.axes.size());
    }
    for (std::size_t a = 0; a < spec.axes.size(); ++a) {
        // Latin hypercube: case c takes a point of stratum order[c] of this axis.
        const std::vector<int> order = spec.sampling == Sampling::Latin ? drawPermutation(spec.samples, rng) : std::vector<int>{};
        for (int c = 0; c < spec.samples; ++c) {
            const double u = order.empty() ? drawUnit(rng) : (order[c] + drawUnit(rng)) / spec.samples;
            cases[c].values[a] = pickValue(spec.axes[a], u);
        }
    }
    return cases;
}

bool parseWhole(const std::string& text, int& value) {
    if (text.empty() || text.size() > 9) return false;
    for (char c : text) {
        if (c < '0' || c > '9') return false;
    }
    value = std::stoi(text);
    return true;
}

}  // namespace

std::vector<StudyCase> expandCases(const StudySpec& spec) {
    return spec.sampling == Sampling::Grid ? expandGrid(spec) : expandSample(spec);
}

Shard parseShard(const std::string& text) {
    const std::size_t slash = text.find('/');
    Shard shard;
    const bool ok = slash != std::string::npos && parseWhole(text.substr(0, slash), shard.index) &&
                    parseWhole(text.substr(slash + 1), shard.count) && shard.count >= 1 && shard.index < shard.count;
    if (!ok) {
        throw InputError("--shard: value '" + text + "' is not accepted; give i/K with whole numbers 0 <= i < K (task i of K, e.g. 0/4)");
    }
    return shard;
}

std::vector<StudyCase> selectShard(const std::vector<StudyCase>& cases, const Shard& shard) {
    std::vector<StudyCase> selected;
    for (const StudyCase& c : cases) {
        if (shard.holds(c.index)) selected.push_back(c);
    }
    return selected;
}

}  // namespace graspsim::study
