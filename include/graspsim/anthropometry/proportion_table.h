#pragma once
/// @file
/// Model design parameters that no single table provides, each a dimensionless ratio: the hand's
/// (hand breadth, capsule radii, joint positions in the palm; anthropometry/hand_proportions.csv)
/// and the whole body's (shoulder and hip joint positions; anthropometry/body_proportions.csv).
///
/// Both files are embedded; their source column says for every value whether it is cited (e.g.
/// hand_length_per_stature, Drillis & Contini 1966) or a model assumption, and
/// anthropometry/README.md explains the names and reference points.

#include <string>
#include <utility>
#include <vector>

namespace graspsim::anthropometry {

/// Named dimensionless ratios; a name ends with the length it is a fraction of, e.g.
/// "finger_distal_radius_per_hand_length" (capsule radius / hand length).
class ProportionTable {
public:
    /// The embedded anthropometry/hand_proportions.csv.
    static ProportionTable loadHand();
    /// The embedded anthropometry/body_proportions.csv.
    static ProportionTable loadBody();

    /// Parses a table with columns name, value, unit, source; unit must be "ratio" and every
    /// value finite and positive. `source` names the text in InputError messages.
    static ProportionTable parseCsv(const std::string& csvText, const std::string& source);

    /// The ratio called `name`; throws InputError listing the known names otherwise.
    double get(const std::string& name) const;

    /// All names, in file order.
    std::vector<std::string> getNames() const;

private:
    explicit ProportionTable(std::string source) : m_source(std::move(source)) {}

    std::string m_source;
    std::vector<std::pair<std::string, double>> m_values;
};

}  // namespace graspsim::anthropometry
