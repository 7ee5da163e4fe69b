#include "graspsim/opensim/opensim_storage.h"

#include "graspsim/io/atomic_file.h"

#include <tinyxml.h>

#include <cstdio>
#include <map>
#include <sstream>
#include <utility>

namespace graspsim::opensim {

namespace {

constexpr double kDegreesPerRadian = 57.295779513082320876798154814105;

void put(std::ostringstream& out, double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    out << '\t' << buffer;
}

std::string formatTime(double time) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", time);
    return buffer;
}

// OpenSim's Storage header: name, version, table size (time column included), angle unit.
std::string formatHeader(const std::string& name, std::size_t rows, std::size_t columns, bool inDegrees) {
    return name + "\nversion=1\nnRows=" + std::to_string(rows) + "\nnColumns=" + std::to_string(columns) +
           "\ninDegrees=" + (inDegrees ? "yes" : "no") + "\nendheader\n";
}

// One contact channel: the k-th point of one hand-object pair in a sample.
struct Channel {
    std::string label;     // <hand body>_<hand shape>[_k]
    std::string handBody;  // the body the reaction acts on
};

using ChannelKey = std::pair<std::string, int>;  // (pair, occurrence within the sample)

std::string getPairName(const contact::ContactReport& c) { return c.bodyA + "_" + c.shapeA; }

// Every channel that ever touches, in order of first appearance, and each report's channel index.
class ChannelTable {
public:
    explicit ChannelTable(const simulation::SimulationResult& result) {
        for (const simulation::ContactSample& sample : result.contacts) {
            std::map<std::string, int> seen;
            for (const contact::ContactReport& c : sample.contacts) {
                const std::string pair = getPairName(c);
                const ChannelKey key{pair, seen[pair]++};
                if (index_.count(key)) continue;
                index_[key] = static_cast<int>(channels_.size());
                channels_.push_back({key.second == 0 ? pair : pair + "_" + std::to_string(key.second + 1), c.bodyA});
            }
        }
    }
    const std::vector<Channel>& getChannels() const { return channels_; }
    // Channel index of each report of `sample`, in report order.
    std::vector<int> findIndices(const simulation::ContactSample& sample) const {
        std::vector<int> indices;
        std::map<std::string, int> seen;
        for (const contact::ContactReport& c : sample.contacts) {
            const std::string pair = getPairName(c);
            indices.push_back(index_.at({pair, seen[pair]++}));
        }
        return indices;
    }

private:
    std::vector<Channel> channels_;
    std::map<ChannelKey, int> index_;
};

// Each channel's first contact point, where its point column starts before it first touches.
std::vector<SimTK::Vec3> findFirstPoints(const simulation::SimulationResult& result, const ChannelTable& table) {
    std::vector<SimTK::Vec3> points(table.getChannels().size(), SimTK::Vec3(0));
    std::vector<bool> found(points.size(), false);
    for (const simulation::ContactSample& sample : result.contacts) {
        const std::vector<int> indices = table.findIndices(sample);
        for (std::size_t i = 0; i < indices.size(); ++i) {
            if (found[indices[i]]) continue;
            points[indices[i]] = sample.contacts[i].p_G;
            found[indices[i]] = true;
        }
    }
    return points;
}

std::string formatForceRow(const simulation::ContactSample& sample, const ChannelTable& table,
                           std::vector<SimTK::Vec3>& lastPoints) {
    std::vector<SimTK::Vec3> forces(lastPoints.size(), SimTK::Vec3(0));
    const std::vector<int> indices = table.findIndices(sample);
    for (std::size_t i = 0; i < indices.size(); ++i) {
        const contact::ContactReport& c = sample.contacts[i];
        forces[indices[i]] = c.normalForce * SimTK::Vec3(c.n_G) + c.frictionForce_G;  // on b, the object
        lastPoints[indices[i]] = c.p_G;
    }
    std::ostringstream row;
    row << formatTime(sample.time);
    for (std::size_t k = 0; k < forces.size(); ++k) {
        for (int i = 0; i < 3; ++i) put(row, forces[k][i]);
        for (int i = 0; i < 3; ++i) put(row, -forces[k][i]);
        for (int i = 0; i < 3; ++i) put(row, lastPoints[k][i]);
    }
    row << '\n';
    return row.str();
}

void appendText(TiXmlElement& parent, const char* tag, const std::string& text) {
    auto* element = new TiXmlElement(tag);
    element->LinkEndChild(new TiXmlText(text));
    parent.LinkEndChild(element);
}

}  // namespace

std::string formatMotionMot(const simulation::SimulationResult& result) {
    std::ostringstream out;
    out << formatHeader("motion", result.trajectory.size(), result.jointNames.size() + 1, true) << "time";
    for (const std::string& joint : result.jointNames) out << '\t' << joint;
    out << '\n';
    for (const simulation::TrajectorySample& s : result.trajectory) {
        out << formatTime(s.time);
        for (double q : s.jointAngles) put(out, q * kDegreesPerRadian);
        out << '\n';
    }
    return out.str();
}

std::string formatObjectForcesSto(const simulation::SimulationResult& result) {
    const ChannelTable table(result);
    std::ostringstream out;
    out << formatHeader("object_forces", result.contacts.size(), 9 * table.getChannels().size() + 1, false) << "time";
    for (const Channel& c : table.getChannels()) {
        for (const char* part : {"_on_object_v", "_on_hand_v", "_p"}) {
            for (const char* axis : {"x", "y", "z"}) out << '\t' << c.label << part << axis;
        }
    }
    out << '\n';
    std::vector<SimTK::Vec3> lastPoints = findFirstPoints(result, table);
    for (const simulation::ContactSample& sample : result.contacts) out << formatForceRow(sample, table, lastPoints);
    return out.str();
}

std::string formatExternalLoadsXml(const simulation::SimulationResult& result, const std::string& dataFile) {
    TiXmlDocument document;
    document.LinkEndChild(new TiXmlDeclaration("1.0", "UTF-8", ""));
    auto* root = new TiXmlElement("OpenSimDocument");
    root->SetAttribute("Version", "40000");
    document.LinkEndChild(root);
    auto* loads = new TiXmlElement("ExternalLoads");
    loads->SetAttribute("name", "object_contacts");
    root->LinkEndChild(loads);
    auto* objects = new TiXmlElement("objects");
    loads->LinkEndChild(objects);
    const ChannelTable table(result);
    for (const Channel& c : table.getChannels()) {
        auto* force = new TiXmlElement("ExternalForce");
        force->SetAttribute("name", c.label);
        objects->LinkEndChild(force);
        appendText(*force, "applied_to_body", c.handBody);
        appendText(*force, "force_expressed_in_body", "ground");
        appendText(*force, "point_expressed_in_body", "ground");
        appendText(*force, "force_identifier", c.label + "_on_hand_v");
        appendText(*force, "point_identifier", c.label + "_p");
        appendText(*force, "data_source_name", "object_forces");
    }
    appendText(*loads, "datafile", dataFile);
    TiXmlPrinter printer;
    printer.SetIndent("  ");
    document.Accept(&printer);
    return printer.Str();
}

void writeOpenSimResultFiles(const std::string& folder, const simulation::SimulationResult& result) {
    io::writeFileAtomically(folder + "/motion.mot", formatMotionMot(result));
    io::writeFileAtomically(folder + "/object_forces.sto", formatObjectForcesSto(result));
    io::writeFileAtomically(folder + "/external_loads.xml", formatExternalLoadsXml(result, "object_forces.sto"));
}

}  // namespace graspsim::opensim
