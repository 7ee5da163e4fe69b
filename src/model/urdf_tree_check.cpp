#include "urdf_tree_check.h"

#include <tinyxml.h>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace graspsim::model {

namespace {

struct JointEdge {
    std::string name;
    std::string parent;
    std::string child;
    int line = 0;
};

std::string getAttribute(const TiXmlElement& element, const char* name) {
    const char* value = element.Attribute(name);
    return value ? value : "";
}

// Link name -> line of its definition.
std::map<std::string, int> collectLinks(const TiXmlElement& robot, const UrdfSource& source) {
    std::map<std::string, int> links;
    for (const TiXmlElement* e = robot.FirstChildElement("link"); e; e = e->NextSiblingElement("link")) {
        const std::string name = getAttribute(*e, "name");
        if (name.empty()) source.reject(e->Row(), "<link> name", "(missing)", "every link needs a non-empty name");
        const auto [it, added] = links.emplace(name, e->Row());
        if (!added) {
            source.reject(e->Row(), "link name", quoted(name),
                          "link names must be unique (first defined at line " + std::to_string(it->second) + ")");
        }
    }
    if (links.empty()) source.reject(robot.Row(), "<link> elements", "none", "a robot needs at least one link");
    return links;
}

std::string getLinkReference(const TiXmlElement& joint, const char* role, const std::string& jointName,
                             const std::map<std::string, int>& links, const UrdfSource& source) {
    const TiXmlElement* element = joint.FirstChildElement(role);
    const std::string link = element ? getAttribute(*element, "link") : "";
    const std::string field = "joint " + quoted(jointName) + " " + role + " link";
    if (link.empty()) source.reject(joint.Row(), field, "(missing)", std::string("every joint needs <") + role + " link=\"...\"/>");
    if (!links.count(link)) source.reject(joint.Row(), field, quoted(link), "must name a <link> defined in the file");
    return link;
}

JointEdge readJointEdge(const TiXmlElement& e, const std::map<std::string, int>& links, const UrdfSource& source) {
    JointEdge edge;
    edge.name = getAttribute(e, "name");
    edge.line = e.Row();
    if (edge.name.empty()) source.reject(edge.line, "<joint> name", "(missing)", "every joint needs a non-empty name");
    const char* type = e.Attribute("type");
    const std::string typeText = type ? quoted(type) : "(missing)";
    const std::set<std::string> accepted{"revolute", "continuous", "prismatic", "fixed"};
    if (!type || !accepted.count(type)) source.reject(edge.line, "joint " + quoted(edge.name) + " type", typeText, kAcceptedJointTypes);
    edge.parent = getLinkReference(e, "parent", edge.name, links, source);
    edge.child = getLinkReference(e, "child", edge.name, links, source);
    if (edge.parent == edge.child) {
        source.reject(edge.line, "joint " + quoted(edge.name) + " child link", quoted(edge.child),
                      "a joint must connect two different links");
    }
    return edge;
}

// Child link name -> the joint that has it as child.
std::map<std::string, JointEdge> collectParentJoints(const TiXmlElement& robot, const std::map<std::string, int>& links,
                                                      const UrdfSource& source) {
    std::map<std::string, JointEdge> parentJointOf;
    std::set<std::string> jointNames;
    for (const TiXmlElement* e = robot.FirstChildElement("joint"); e; e = e->NextSiblingElement("joint")) {
        JointEdge edge = readJointEdge(*e, links, source);
        if (!jointNames.insert(edge.name).second) source.reject(edge.line, "joint name", quoted(edge.name), "joint names must be unique");
        const auto [it, added] = parentJointOf.emplace(edge.child, edge);
        if (!added) {
            source.reject(edge.line, "link " + quoted(edge.child) + " parent joints",
                          quoted(it->second.name) + " (line " + std::to_string(it->second.line) + ") and " + quoted(edge.name),
                          "each link is the child of at most one joint");
        }
    }
    return parentJointOf;
}

// Follows parent joints up from `start`; with at most one parent per link, the walk either
// reaches a root or comes back to a link already on the path, which is then a cycle.
void checkNoCycleAbove(const std::string& start, const std::map<std::string, JointEdge>& parentJointOf,
                       const UrdfSource& source) {
    std::vector<std::string> path{start};
    std::set<std::string> onPath{start};
    for (auto it = parentJointOf.find(start); it != parentJointOf.end(); it = parentJointOf.find(path.back())) {
        const std::string& parent = it->second.parent;
        if (onPath.count(parent)) {
            std::string cycle = quoted(parent);
            for (auto link = path.rbegin(); link != path.rend() && *link != parent; ++link) cycle = quoted(*link) + " -> " + cycle;
            source.reject(it->second.line, "joint " + quoted(it->second.name) + " parent link", quoted(parent),
                          "it closes the cycle " + quoted(parent) + " -> " + cycle +
                              " (child -> parent); joints must form a tree");
        }
        path.push_back(parent);
        onPath.insert(parent);
    }
}

}  // namespace

void checkUrdfTree(const TiXmlElement& robot, const UrdfSource& source) {
    const std::map<std::string, int> links = collectLinks(robot, source);
    const std::map<std::string, JointEdge> parentJointOf = collectParentJoints(robot, links, source);
    for (const auto& link : links) checkNoCycleAbove(link.first, parentJointOf, source);
    std::vector<std::string> roots;
    for (const auto& link : links) {
        if (!parentJointOf.count(link.first)) roots.push_back(quoted(link.first) + " (line " + std::to_string(link.second) + ")");
    }
    if (roots.size() > 1) {
        std::string list = roots[0];
        for (std::size_t i = 1; i < roots.size(); ++i) list += (i + 1 == roots.size() ? " and " : ", ") + roots[i];
        source.reject(robot.Row(), "root links (links that are no joint's child)", list,
                      "exactly one root; connect the others with joints");
    }
}

}  // namespace graspsim::model
