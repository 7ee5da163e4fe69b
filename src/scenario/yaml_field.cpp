#include "yaml_field.h"

#include "graspsim/error.h"

#include <cmath>
#include <map>
#include <sstream>

namespace graspsim::scenario {

namespace {

std::string formatNumber(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

// yaml-cpp's marks count from 0; people count lines from 1. A node without a mark (rare:
// nodes that yaml-cpp makes up) reports the line of its parent.
int toLine(const YAML::Mark& mark, int fallback) {
    return mark.is_null() ? fallback : mark.line + 1;
}

}  // namespace

std::string joinNames(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
}

NumberRule NumberRule::any(const std::string& quantity, const std::string& unit) {
    return {quantity, unit};
}

NumberRule NumberRule::positive(const std::string& quantity, const std::string& unit) {
    NumberRule rule{quantity, unit};
    rule.lower = 0;
    rule.lowerOpen = true;
    return rule;
}

NumberRule NumberRule::nonNegative(const std::string& quantity, const std::string& unit) {
    NumberRule rule{quantity, unit};
    rule.lower = 0;
    return rule;
}

NumberRule NumberRule::closed(const std::string& quantity, const std::string& unit, double lower, double upper) {
    NumberRule rule{quantity, unit};
    rule.lower = lower;
    rule.upper = upper;
    return rule;
}

bool NumberRule::accepts(double value) const {
    if (!std::isfinite(value)) return false;
    const bool aboveLower = lowerOpen ? value > lower : value >= lower;
    const bool belowUpper = upperOpen ? value < upper : value <= upper;
    return aboveLower && belowUpper;
}

std::string NumberRule::describeBounds() const {
    const bool hasLower = std::isfinite(lower), hasUpper = std::isfinite(upper);
    if (hasLower && hasUpper) {
        return std::string(" in ") + (lowerOpen ? "(" : "[") + formatNumber(lower) + ", " + formatNumber(upper) +
               (upperOpen ? ")" : "]");
    }
    if (hasLower) return (lowerOpen ? " > " : " >= ") + formatNumber(lower);
    if (hasUpper) return (upperOpen ? " < " : " <= ") + formatNumber(upper);
    return "";
}

std::string NumberRule::describe() const {
    return quantity + " must be a finite number" + describeBounds() + (unit.empty() ? "" : " " + unit);
}

std::string NumberRule::describeList() const {
    const std::string bounds = describeBounds();
    return quantity + " must be a list of three finite numbers [x, y, z]" + (bounds.empty() ? "" : ", each" + bounds) +
           (unit.empty() ? "" : " (" + unit + ")");
}

YamlField::YamlField(YAML::Node node, std::string source, std::string path, std::string key, int line)
    : node_(std::move(node)), source_(std::move(source)), path_(std::move(path)), key_(std::move(key)), line_(line) {}

YamlField YamlField::makeRoot(const YAML::Node& document, const std::string& source) {
    return YamlField(document, source, "", "", toLine(document.Mark(), 1));
}

YamlField YamlField::makeChild(const YAML::Node& key, const YAML::Node& value) const {
    const std::string name = key.IsScalar() ? key.Scalar() : YamlField(key, source_, "", "", line_).formatValue();
    // The key's line, not the value's: a block sequence or map starts on the next line.
    return YamlField(value, source_, path_.empty() ? name : path_ + "." + name, name, toLine(key.Mark(), line_));
}

std::string YamlField::describePlace() const {
    const std::string place = source_ + ":" + std::to_string(line_) + ": ";
    return path_.empty() ? place + "the document" : place + "field '" + path_ + "'";
}

void YamlField::reject(const std::string& why) const {
    throw InputError(describePlace() + " value '" + formatValue() + "' is not accepted; " + why);
}

std::string YamlField::formatValue() const {
    if (isEmpty()) return "(empty)";
    if (node_.IsScalar()) return node_.Scalar();
    std::string text;
    const bool isMap = node_.IsMap();
    for (auto it = node_.begin(); it != node_.end(); ++it) {
        text += text.empty() ? "" : ", ";
        if (isMap) {
            const YamlField child = makeChild(it->first, it->second);
            text += child.key_ + ": " + child.formatValue();
        } else {
            text += YamlField(*it, source_, path_, key_, line_).formatValue();
        }
    }
    return isMap ? "{" + text + "}" : "[" + text + "]";
}

std::vector<YamlField> YamlField::getEntries() const {
    if (!node_.IsMap()) reject((key_.empty() ? "the document" : key_) + " must be a map of names to values");
    std::vector<YamlField> entries;
    std::map<std::string, int> firstLine;
    for (auto it = node_.begin(); it != node_.end(); ++it) {
        YamlField child = makeChild(it->first, it->second);
        const auto [seen, isNew] = firstLine.emplace(child.key_, child.line_);
        if (!isNew) {
            throw InputError(child.describePlace() + " is given twice (also on line " +
                             std::to_string(seen->second) + "); give each field once");
        }
        entries.push_back(std::move(child));
    }
    return entries;
}

std::vector<YamlField> YamlField::getItems(const std::string& accepted) const {
    if (!node_.IsSequence()) reject(accepted);
    std::vector<YamlField> items;
    for (std::size_t i = 0; i < node_.size(); ++i) {
        const YAML::Node item = node_[i];
        const std::string key = key_ + "[" + std::to_string(i) + "]";
        const std::string path = path_.empty() ? key : path_ + "[" + std::to_string(i) + "]";
        items.push_back(YamlField(item, source_, path, key, toLine(item.Mark(), line_)));
    }
    return items;
}

void YamlField::requireMap(const std::vector<std::string>& accepted) const {
    const std::string owner = path_.empty() ? "a scenario file" : "'" + path_ + "'";
    if (!node_.IsMap()) reject(owner + " must be a map with the keys: " + joinNames(accepted));
    for (const YamlField& entry : getEntries()) {
        bool known = false;
        for (const std::string& key : accepted) known = known || key == entry.key_;
        if (!known) {
            throw InputError(entry.describePlace() + " is not accepted; " + owner + " accepts the keys: " +
                             joinNames(accepted));
        }
    }
}

std::optional<YamlField> YamlField::find(const std::string& key) const {
    if (!node_.IsMap()) return std::nullopt;
    for (auto it = node_.begin(); it != node_.end(); ++it) {
        if (it->first.IsScalar() && it->first.Scalar() == key) return makeChild(it->first, it->second);
    }
    return std::nullopt;
}

YamlField YamlField::require(const std::string& key, const std::string& accepted) const {
    if (std::optional<YamlField> child = find(key)) return *child;
    const std::string path = path_.empty() ? key : path_ + "." + key;
    throw InputError(source_ + ":" + std::to_string(line_) + ": field '" + path + "' is missing; " + accepted);
}

YamlField YamlField::getSection(const std::string& key, const std::vector<std::string>& accepted) const {
    const std::optional<YamlField> child = find(key);
    if (child && !child->isEmpty()) {
        child->requireMap(accepted);
        return *child;
    }
    return YamlField(YAML::Node(YAML::NodeType::Map), source_, path_.empty() ? key : path_ + "." + key, key,
                     child ? child->line_ : line_);
}

double YamlField::asNumber(const NumberRule& rule) const {
    if (!node_.IsScalar()) reject(rule.describe());
    double value = 0;
    try {
        value = node_.as<double>();
    } catch (const YAML::Exception&) {
        reject(rule.describe());
    }
    if (!rule.accepts(value)) reject(rule.describe());
    return value;
}

model::Vec3 YamlField::asVec3(const NumberRule& rule) const {
    const std::string why = rule.describeList();
    if (!node_.IsSequence() || node_.size() != 3) reject(why);
    model::Vec3 value{};
    for (std::size_t i = 0; i < 3; ++i) {
        const YAML::Node element = node_[i];
        double number = 0;
        try {
            number = element.IsScalar() ? element.as<double>() : NAN;
        } catch (const YAML::Exception&) {
            number = NAN;
        }
        if (!rule.accepts(number)) reject(why);
        value[i] = number;
    }
    return value;
}

std::string YamlField::asText(const std::string& accepted) const {
    if (!node_.IsScalar()) reject(accepted);
    return node_.Scalar();
}

double YamlField::getNumber(const std::string& key, const NumberRule& rule) const {
    return require(key, rule.describe()).asNumber(rule);
}

double YamlField::findNumber(const std::string& key, const NumberRule& rule, double fallback) const {
    const std::optional<YamlField> child = find(key);
    return child ? child->asNumber(rule) : fallback;
}

model::Vec3 YamlField::getVec3(const std::string& key, const NumberRule& rule) const {
    return require(key, rule.describeList()).asVec3(rule);
}

model::Vec3 YamlField::findVec3(const std::string& key, const NumberRule& rule, const model::Vec3& fallback) const {
    const std::optional<YamlField> child = find(key);
    return child ? child->asVec3(rule) : fallback;
}

}  // namespace graspsim::scenario
