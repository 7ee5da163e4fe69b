#include "urdf_extensions.h"

#include "urdf_number.h"

#include <tinyxml.h>

#include <cmath>
#include <set>
#include <string>

namespace graspsim::model {

namespace {

const std::string kPrefix = std::string(kGraspsimPrefix) + ":";

// Reads one extension element: its attributes by name, each checked against the allowed set.
class ExtensionElement {
public:
    ExtensionElement(const TiXmlElement& element, const std::string& tag, std::set<std::string> allowed,
                     const UrdfSource& source)
        : element_(element), tag_(tag), source_(source) {
        for (const TiXmlAttribute* a = element.FirstAttribute(); a; a = a->Next()) {
            if (!allowed.count(a->Name())) {
                source.reject(element.Row(), "<" + tag + "> attribute", quoted(a->Name()),
                              "accepted: " + describeAllowed(allowed));
            }
        }
    }

    std::string getText(const char* name) const {
        const char* value = element_.Attribute(name);
        if (!value) source_.reject(getLine(), "<" + tag_ + "> " + name, "(missing)", "the attribute is required");
        return value;
    }

    std::string getOptionalText(const char* name, const std::string& defaultValue) const {
        const char* value = element_.Attribute(name);
        return value ? value : defaultValue;
    }

    double getNumber(const char* name, double defaultValue, bool nonNegative) const {
        if (!element_.Attribute(name)) return defaultValue;
        const std::string text = getText(name);
        const std::optional<double> value = parseUrdfNumber(text);
        if (!value || !std::isfinite(*value) || (nonNegative && *value < 0)) {
            source_.reject(getLine(), "<" + tag_ + " name=" + quoted(getText("name")) + "> " + name, quoted(text),
                           nonNegative ? "a finite number >= 0" : "a finite number");
        }
        return *value;
    }

    Vec3 getTriple(const char* name) const {
        const std::string text = getText(name);
        const std::optional<Vec3> value = parseUrdfTriple(text);
        if (!value || !std::isfinite((*value)[0]) || !std::isfinite((*value)[1]) || !std::isfinite((*value)[2])) {
            source_.reject(getLine(), "<" + tag_ + " name=" + quoted(getText("name")) + "> " + name, quoted(text),
                           "three finite numbers separated by spaces (m)");
        }
        return *value;
    }

    int getLine() const { return element_.Row(); }
    const std::string& getTag() const { return tag_; }

private:
    static std::string describeAllowed(const std::set<std::string>& allowed) {
        std::string list;
        for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
        return list;
    }

    const TiXmlElement& element_;
    std::string tag_;
    const UrdfSource& source_;
};

// The prefix bound to our namespace on <robot>, so a file that renames it still reads.
std::string findPrefix(const TiXmlElement& robot) {
    for (const TiXmlAttribute* a = robot.FirstAttribute(); a; a = a->Next()) {
        const std::string name = a->Name();
        if (name.rfind("xmlns:", 0) == 0 && a->ValueStr() == kGraspsimNamespaceUri) return name.substr(6) + ":";
    }
    return kPrefix;
}

void checkFirstEntry(std::set<std::string>& seen, const std::string& name, const ExtensionElement& e,
                     const UrdfSource& source) {
    if (!seen.insert(name).second) source.reject(e.getLine(), "<" + e.getTag() + "> name", quoted(name), "one entry per name");
}

void applyLink(const ExtensionElement& e, std::set<std::string>& seen, const UrdfSource& source, ModelDescription& model) {
    const std::string name = e.getText("name");
    Body* body = model.updBody(name);
    if (!body) source.reject(e.getLine(), "<" + e.getTag() + "> name", quoted(name), "must name a <link> of the file");
    checkFirstEntry(seen, name, e, source);
    body->segment = e.getText("segment");
    const std::string role = e.getOptionalText("role", "other");
    if (role == "palm") body->role = BodyRole::Palm;
    else if (role == "digit") body->role = BodyRole::Digit;
    else if (role != "other") source.reject(e.getLine(), "<" + e.getTag() + " name=" + quoted(name) + "> role", quoted(role), "palm, digit or other");
}

void applyJoint(const ExtensionElement& e, std::set<std::string>& seen, const UrdfSource& source, ModelDescription& model) {
    const std::string name = e.getText("name");
    Joint* joint = model.updJoint(name);
    if (!joint) source.reject(e.getLine(), "<" + e.getTag() + "> name", quoted(name), "must name a <joint> of the file");
    checkFirstEntry(seen, name, e, source);
    joint->stiffness = e.getNumber("stiffness", 0, true);
    joint->restAngle = e.getNumber("rest_angle", 0, false);
}

void applyEndEffector(const ExtensionElement& e, std::set<std::string>& seen, const UrdfSource& source,
                      ModelDescription& model) {
    EndEffector effector{e.getText("name"), e.getText("link"), e.getTriple("xyz")};
    if (!model.findBody(effector.body)) {
        source.reject(e.getLine(), "<" + e.getTag() + " name=" + quoted(effector.name) + "> link", quoted(effector.body),
                      "must name a <link> of the file");
    }
    checkFirstEntry(seen, effector.name, e, source);
    model.endEffectors.push_back(effector);
}

}  // namespace

void appendGraspsimExtensions(const ModelDescription& model, TiXmlElement& robot) {
    for (const Body& body : model.bodies) {
        if (body.segment.empty()) continue;
        auto* e = new TiXmlElement(kPrefix + "link");
        e->SetAttribute("name", body.name);
        e->SetAttribute("segment", body.segment);
        if (body.role != BodyRole::Other) e->SetAttribute("role", toString(body.role));
        robot.LinkEndChild(e);
    }
    for (const Joint& joint : model.joints) {
        if (joint.stiffness == 0 && joint.restAngle == 0) continue;
        auto* e = new TiXmlElement(kPrefix + "joint");
        e->SetAttribute("name", joint.name);
        e->SetAttribute("stiffness", formatUrdfNumber(joint.stiffness));
        e->SetAttribute("rest_angle", formatUrdfNumber(joint.restAngle));
        robot.LinkEndChild(e);
    }
    for (const EndEffector& effector : model.endEffectors) {
        auto* e = new TiXmlElement(kPrefix + "end_effector");
        e->SetAttribute("name", effector.name);
        e->SetAttribute("link", effector.body);
        e->SetAttribute("xyz", formatUrdfTriple(effector.p_BE));
        robot.LinkEndChild(e);
    }
}

void applyGraspsimExtensions(const TiXmlElement& robot, const UrdfSource& source, ModelDescription& model) {
    const std::string prefix = findPrefix(robot);
    std::set<std::string> links, joints, endEffectors;
    for (const TiXmlElement* child = robot.FirstChildElement(); child; child = child->NextSiblingElement()) {
        const std::string tag = child->ValueStr();
        if (tag.rfind(prefix, 0) != 0) continue;
        const std::string local = tag.substr(prefix.size());
        if (local == "link") {
            applyLink(ExtensionElement(*child, tag, {"name", "segment", "role"}, source), links, source, model);
        } else if (local == "joint") {
            applyJoint(ExtensionElement(*child, tag, {"name", "stiffness", "rest_angle"}, source), joints, source, model);
        } else if (local == "end_effector") {
            applyEndEffector(ExtensionElement(*child, tag, {"name", "link", "xyz"}, source), endEffectors, source, model);
        } else {
            source.reject(child->Row(), "extension element", "<" + tag + ">",
                          "accepted: <" + prefix + "link>, <" + prefix + "joint>, <" + prefix + "end_effector>");
        }
    }
}

}  // namespace graspsim::model
