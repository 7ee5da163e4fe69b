#pragma once
// A node of a scenario file together with where it is (file, line, field path), so that every
// InputError the reader throws names them. Only src/scenario sees yaml-cpp; the public API is
// plain data.

#include "graspsim/model/model_description.h"

#include <yaml-cpp/yaml.h>

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace graspsim::scenario {

// What a number field accepts. It checks a value and says, for the message, what is accepted:
// "mass must be a finite number > 0 kg".
struct NumberRule {
    std::string quantity;  // e.g. "mass"
    std::string unit;      // e.g. "kg"; empty for dimensionless numbers
    double lower = -std::numeric_limits<double>::infinity();
    double upper = std::numeric_limits<double>::infinity();
    bool lowerOpen = false;  // true: value > lower; false: value >= lower
    bool upperOpen = false;  // true: value < upper; false: value <= upper

    static NumberRule any(const std::string& quantity, const std::string& unit);
    static NumberRule positive(const std::string& quantity, const std::string& unit);
    static NumberRule nonNegative(const std::string& quantity, const std::string& unit);
    static NumberRule closed(const std::string& quantity, const std::string& unit, double lower, double upper);

    bool accepts(double value) const;
    // " > 0", " in [0, 1]" or "" when unbounded.
    std::string describeBounds() const;
    // "mass must be a finite number > 0 kg"
    std::string describe() const;
    // "position must be a list of three finite numbers [x, y, z] (m)"
    std::string describeList() const;
};

// "a, b, c": the accepted names an InputError lists.
std::string joinNames(const std::vector<std::string>& names);

class YamlField {
public:
    // The whole document. `source` names the file in messages.
    static YamlField makeRoot(const YAML::Node& document, const std::string& source);

    const std::string& getPath() const { return path_; }  // e.g. "object.mass"; "" for the root
    const std::string& getKey() const { return key_; }    // last path element, e.g. "mass"
    int getLine() const { return line_; }                 // 1-based
    const std::string& getSource() const { return source_; }

    // Checks that this is a map whose keys are all in `accepted`, each given once.
    void requireMap(const std::vector<std::string>& accepted) const;
    // The child `key` of this map, or nothing when the key is absent.
    std::optional<YamlField> find(const std::string& key) const;
    // The child `key`; when it is absent, throws "field '<path>' is missing; <accepted>".
    YamlField require(const std::string& key, const std::string& accepted) const;
    // True for a key written without a value ("contact:" with every line under it commented out).
    bool isEmpty() const { return !node_.IsDefined() || node_.IsNull(); }
    // True for a list value ("[1, 2, 3]").
    bool isSequence() const { return node_.IsSequence(); }
    // The child map `key`, checked against `accepted`; when the file leaves it out or empty, an
    // empty map at its line, so that an optional section reads its defaults like a given one.
    YamlField getSection(const std::string& key, const std::vector<std::string>& accepted) const;
    // Every entry of a map whose keys the user chooses (joint names, goal names), in file order;
    // each key given once.
    std::vector<YamlField> getEntries() const;

    // The items of a sequence, each with its place ("approximation.relaxed_axes[2]"); `accepted`
    // says what the sequence must hold when this is not a sequence.
    std::vector<YamlField> getItems(const std::string& accepted) const;

    double asNumber(const NumberRule& rule) const;
    model::Vec3 asVec3(const NumberRule& rule) const;  // a sequence of three numbers
    std::string asText(const std::string& accepted) const;

    // Shorthands: the required or optional child read as a number, a 3-vector or text.
    double getNumber(const std::string& key, const NumberRule& rule) const;
    double findNumber(const std::string& key, const NumberRule& rule, double fallback) const;
    model::Vec3 getVec3(const std::string& key, const NumberRule& rule) const;
    model::Vec3 findVec3(const std::string& key, const NumberRule& rule, const model::Vec3& fallback) const;

    // Throws "<source>:<line>: field '<path>' value '<value>' is not accepted; <why>".
    [[noreturn]] void reject(const std::string& why) const;
    // "<source>:<line>: field '<path>'", the start of every message about this field.
    std::string describePlace() const;
    // The value as the file writes it ("-0.2", "[0, 1, 2]").
    std::string formatValue() const;

private:
    YamlField(YAML::Node node, std::string source, std::string path, std::string key, int line);
    YamlField makeChild(const YAML::Node& key, const YAML::Node& value) const;

    YAML::Node node_;
    std::string source_;
    std::string path_;
    std::string key_;
    int line_ = 1;
};

}  // namespace graspsim::scenario
