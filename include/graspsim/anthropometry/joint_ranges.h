#pragma once
/// @file
/// Joint ranges of motion of the arm, hand and humanoid joints.
///
/// Embedded from anthropometry/joint_ranges.csv (degrees there, radians here). Average adult
/// ranges of the American Academy of Orthopaedic Surgeons (1965) "Joint Motion: Method of
/// Measuring and Recording" where available; the source column marks model assumptions.
/// Signs: flexion (ankle dorsiflexion), abduction, internal rotation, forearm pronation, wrist
/// radial deviation and ankle inversion are positive; zero is the anatomical position.

#include <string>
#include <utility>
#include <vector>

namespace graspsim::anthropometry {

/// Limits of one joint coordinate (rad), lower < upper.
struct JointRange {
    double lower = 0.0;  ///< most negative angle, e.g. full extension (rad)
    double upper = 0.0;  ///< most positive angle, e.g. full flexion (rad)
};

/// Ranges by joint name, e.g. "elbow_flexion", "mcp_abduction", "hip_rotation".
class JointRanges {
public:
    /// The embedded anthropometry/joint_ranges.csv.
    static JointRanges loadDefault();

    /// Parses a table with columns joint, lower_deg, upper_deg, source (degrees, lower <
    /// upper, both within [-360, 360]). `source` names the text in InputError messages.
    static JointRanges parseCsv(const std::string& csvText, const std::string& source);

    /// The range of `joint`; throws InputError listing the known joints otherwise.
    const JointRange& get(const std::string& joint) const;

    /// All joint names, in file order.
    std::vector<std::string> getJointNames() const;

private:
    explicit JointRanges(std::string source) : m_source(std::move(source)) {}

    std::string m_source;
    std::vector<std::pair<std::string, JointRange>> m_ranges;
};

}  // namespace graspsim::anthropometry
