#pragma once
/// @file
/// de Leva's (1996) body segment inertia parameters, as fractions ready for scaling.
///
/// Source: de Leva P. (1996) "Adjustments to Zatsiorsky-Seluyanov's segment inertia
/// parameters", J Biomech 29(9):1223-1230, Table 4 (main segment definitions), embedded from
/// anthropometry/de_leva_1996_table4.csv. Radii of gyration are about the segment's centre of
/// mass: sagittal = about the antero-posterior axis (body x), transverse = about the
/// medio-lateral axis (body z), longitudinal = about the segment's long axis (body y).

#include <graspsim/anthropometry/sex.h>

#include <string>
#include <utility>
#include <vector>

namespace graspsim::anthropometry {

/// One row of de Leva's Table 4, in SI units and fractions.
struct SegmentParameters {
    std::string name;              ///< e.g. "upper_arm", "hand", "upper_trunk"
    std::string proximalLandmark;  ///< de Leva's origin endpoint, e.g. "SJC"; VERT for head
    std::string distalLandmark;    ///< the other endpoint, e.g. "EJC"
    double length = 0.0;           ///< segment length of the reference subject (m)
    double massFraction = 0.0;     ///< segment mass / body mass (0..1)
    double comFraction = 0.0;      ///< centre of mass from proximalLandmark / length (0..1)
    double gyrationSagittal = 0.0;      ///< radius of gyration about body x / length
    double gyrationTransverse = 0.0;    ///< radius of gyration about body z / length
    double gyrationLongitudinal = 0.0;  ///< radius of gyration about body y / length
};

/// The segments of one sex. Besides the whole-body set (head, trunk, upper_arm, forearm,
/// hand, thigh, shank, foot) it holds upper_trunk, middle_trunk and lower_trunk, which are
/// an alternative split of trunk and must not be added to it.
class SegmentTable {
public:
    /// The embedded de Leva (1996) Table 4 for `sex`.
    static SegmentTable loadDeLeva(Sex sex);

    /// Parses a table in the format of anthropometry/de_leva_1996_table4.csv (columns sex,
    /// segment, proximal_landmark, distal_landmark, length_mm, mass_pct, com_pct,
    /// r_sagittal_pct, r_transverse_pct, r_longitudinal_pct) and keeps the rows of `sex`.
    /// `source` names the text in InputError messages ("<source>:<line>: field ...").
    static SegmentTable parseCsv(const std::string& csvText, Sex sex, const std::string& source);

    /// The segment called `name`; throws InputError listing the known names otherwise.
    const SegmentParameters& getSegment(const std::string& name) const;
    const std::vector<SegmentParameters>& getSegments() const { return m_segments; }
    Sex getSex() const { return m_sex; }

    /// head + trunk + 2 x (upper_arm + forearm + hand + thigh + shank + foot): 1 up to the
    /// rounding of the published two-decimal percentages.
    double calcWholeBodyMassFractionSum() const;
    /// upper_trunk + middle_trunk + lower_trunk: equals trunk up to rounding.
    double calcTrunkPartsMassFractionSum() const;

private:
    SegmentTable(Sex sex, std::string source) : m_sex(sex), m_source(std::move(source)) {}

    Sex m_sex;
    std::string m_source;
    std::vector<SegmentParameters> m_segments;
};

}  // namespace graspsim::anthropometry
