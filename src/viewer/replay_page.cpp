#include "graspsim/viewer/replay_page.h"

#include "graspsim/error.h"
#include "graspsim/io/atomic_file.h"
#include "graspsim/io/embedded_file.h"
#include "graspsim/viewer/body_poses.h"
#include "embedded_page.h"

#include <nlohmann/json.hpp>
#include <simbody/Simbody.h>

#include <cmath>
#include <cstdio>

namespace graspsim::viewer {

namespace {

using Json = nlohmann::ordered_json;

// Six significant digits: a micrometre at arm's length, and a third of the page's size.
double round6(double value) {
    if (!std::isfinite(value)) return value;
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", value);
    return std::strtod(buffer, nullptr);
}

Json toJson(const model::Vec3& v) { return Json::array({round6(v[0]), round6(v[1]), round6(v[2])}); }

std::array<double, 4> findQuaternion(const model::Transform& X) {
    SimTK::Mat33 R;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) R(i, j) = X.R[static_cast<std::size_t>(3 * i + j)];
    const SimTK::Quaternion q = SimTK::Rotation(R, true).convertRotationToQuaternion();
    return {q[0], q[1], q[2], q[3]};
}

void appendPose(Json& out, const model::Vec3& p, const std::array<double, 4>& q) {
    for (double v : p) out.push_back(round6(v));
    for (double v : q) out.push_back(round6(v));
}

Json toJson(const model::Geometry& g) {
    Json j;
    j["type"] = model::toString(g.type);
    j["r"] = round6(g.radius);
    j["len"] = round6(g.length);
    j["half"] = toJson(g.halfLengths);
    // Only the shapes that need them carry these, so sphere and box entries stay as they were.
    if (g.type == model::Geometry::Type::Ellipsoid) j["semi"] = toJson(g.semiAxes);
    if (g.type == model::Geometry::Type::Mesh && g.mesh) {
        // The triangles themselves: the page is self-contained and loads no files.
        Json vertices = Json::array(), triangles = Json::array();
        for (const model::Vec3& v : g.mesh->vertices)
            for (double c : v) vertices.push_back(round6(c));
        for (const std::array<int, 3>& t : g.mesh->triangles)
            for (int k : t) triangles.push_back(k);
        j["verts"] = vertices;
        j["tris"] = triangles;
    }
    Json pose = Json::array();
    appendPose(pose, g.X_BG.p, findQuaternion(g.X_BG));
    j["pose"] = pose;
    return j;
}

// "index" for "index_distal": the finger a hand body belongs to, or "" (palm, arm).
std::string findFinger(const std::string& body) {
    for (const char* finger : {"thumb", "index", "middle", "ring", "little"}) {
        if (body.rfind(std::string(finger) + "_", 0) == 0) return finger;
    }
    return "";
}

// Bodies drawn: every hand/arm body with geometry, then the object (last).
Json makeBodies(const ResultRecord& record, std::vector<std::size_t>& drawn) {
    Json bodies = Json::array();
    for (std::size_t b = 0; b < record.model.bodies.size(); ++b) {
        const model::Body& body = record.model.bodies[b];
        if (body.geometry.empty()) continue;
        Json geoms = Json::array();
        for (const model::Geometry& g : body.geometry) geoms.push_back(toJson(g));
        bodies.push_back({{"name", body.name}, {"finger", findFinger(body.name)}, {"geoms", geoms}});
        drawn.push_back(b);
    }
    const model::Body object = scenario::buildObjectModel(record.scenario.object).bodies.at(0);
    bodies.push_back({{"name", object.name}, {"finger", "object"}, {"geoms", Json::array({toJson(object.geometry.at(0))})}});
    return bodies;
}

// Per frame, [x, y, z, qw, qx, qy, qz] of every drawn body (the object last), flattened.
Json makePoses(const ResultRecord& record, const std::vector<std::size_t>& drawn) {
    Json frames = Json::array();
    for (const TrajectoryRow& row : record.trajectory) {
        const std::vector<model::Transform> X_GB = calcBodyPoses(record.model, row.jointAngles);
        Json pose = Json::array();
        for (std::size_t b : drawn) appendPose(pose, X_GB[b].p, findQuaternion(X_GB[b]));
        appendPose(pose, row.p_GO, row.q_GO);
        frames.push_back(pose);
    }
    return frames;
}

// Per frame, every contact as [x, y, z, force on the object x, y, z, finger] (ground, m, N).
Json makeContacts(const ResultRecord& record) {
    Json frames = Json::array();
    std::size_t c = 0;
    for (const TrajectoryRow& row : record.trajectory) {
        Json contacts = Json::array();
        for (; c < record.contacts.size() && record.contacts[c].time <= row.time; ++c) {
            const ContactRow& k = record.contacts[c];
            if (k.time < row.time) continue;
            // contacts.csv gives the force on b; the arrows show the force on the object. The object is
            // the side that is not a body of model.urdf, so folders that named it otherwise (before it
            // was "object" in every scenario) still show it the right way round.
            const bool objectIsB = record.model.findBody(k.bodyB) == nullptr;
            const double sign = objectIsB ? 1.0 : -1.0;
            model::Vec3 f;
            for (int i = 0; i < 3; ++i) f[i] = sign * (k.normalForce * k.n_G[i] + k.friction_G[i]);
            Json entry = toJson(k.p_G);
            for (double v : f) entry.push_back(round6(v));
            entry.push_back(findFinger(objectIsB ? k.bodyA : k.bodyB));
            contacts.push_back(entry);
        }
        frames.push_back(contacts);
    }
    return frames;
}

// Per frame, the constraint sample recorded at that time, or null.
Json makeConstraint(const ResultRecord& record) {
    Json frames = Json::array();
    std::size_t c = 0;
    for (const TrajectoryRow& row : record.trajectory) {
        while (c < record.constraint.size() && record.constraint[c].time < row.time) ++c;
        if (c >= record.constraint.size() || record.constraint[c].time != row.time) {
            frames.push_back(nullptr);
            continue;
        }
        const ConstraintRow& k = record.constraint[c];
        Json pose = Json::array();
        appendPose(pose, k.p_GM, k.q_GM);
        Json limits = Json::array(), reaction = Json::array();
        // JSON has no infinity: a locked axis's limit is null.
        for (double v : k.limits) limits.push_back(std::isfinite(v) ? Json(round6(v)) : Json(nullptr));
        for (double v : k.reaction) reaction.push_back(round6(v));
        frames.push_back({{"pose", pose}, {"limits", limits}, {"reaction", reaction}});
    }
    return frames;
}

// [start, end] of every engagement (end: the release, or the end of the run).
Json makeEngagedIntervals(const ResultRecord& record) {
    Json intervals = Json::array();
    double start = -1;
    for (const EventRow& e : record.events) {
        if (e.kind == simulation::GraspEventKind::Engage && start < 0) start = e.time;
        if (e.kind == simulation::GraspEventKind::Release && start >= 0) {
            intervals.push_back({start, e.time});
            start = -1;
        }
    }
    if (start >= 0) intervals.push_back({start, record.simTime});
    return intervals;
}

}  // namespace

std::string formatReplayJson(const ResultRecord& record) {
    Json j;
    j["scenario"] = record.scenario.name;
    j["mode"] = simulation::toString(record.mode);
    j["contact"] = record.contactModel;
    j["perturbation"] = record.perturbation;
    j["constraint"] = record.realization;
    j["simTime"] = record.simTime;
    j["provenance"] = Json::parse(record.provenanceJson);
    // A run that stopped early says so on the page (a complete run's data is as it was).
    const Json summary = Json::parse(record.summaryJson);
    if (!summary.value("complete", true)) j["failure"] = summary.value("failure", std::string("stopped early"));
    std::vector<std::size_t> drawn;
    j["bodies"] = makeBodies(record, drawn);
    Json times = Json::array(), quality = Json::array();
    for (const TrajectoryRow& row : record.trajectory) {
        times.push_back(row.time);
        quality.push_back(round6(row.graspQuality));
    }
    j["times"] = times;
    j["quality"] = quality;
    j["poses"] = makePoses(record, drawn);
    j["contacts"] = makeContacts(record);
    j["constraintSamples"] = makeConstraint(record);
    j["engaged"] = makeEngagedIntervals(record);
    Json events = Json::array();
    for (const EventRow& e : record.events) events.push_back({{"t", e.time}, {"kind", simulation::toString(e.kind)}, {"reason", e.reason}});
    j["events"] = events;
    std::string text = j.dump();
    // Inside <script>, "</" could close the element: JSON allows "<\/" for the same text.
    for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3)) text.replace(at, 2, "<\\/");
    return text;
}

namespace {

void replacePlaceholder(std::string& page, const std::string& placeholder, std::string_view text) {
    const std::size_t at = page.find(placeholder);
    if (at == std::string::npos) throw Error("replay page template lacks " + placeholder);
    page.replace(at, placeholder.size(), text);
}

}  // namespace

std::string makeReplayPage(const ResultRecord& record) {
    std::string page(io::findEmbeddedFile(kEmbeddedFiles, kEmbeddedFileCount, "replay.html"));
    // The largest last: no later search runs through three.js.
    replacePlaceholder(page, "/*GRASPSIM_DATA*/", formatReplayJson(record));
    replacePlaceholder(page, "/*GRASPSIM_SCRIPT*/", io::findEmbeddedFile(kEmbeddedFiles, kEmbeddedFileCount, "replay.js"));
    replacePlaceholder(page, "/*GRASPSIM_ORBIT*/", io::findEmbeddedFile(kEmbeddedFiles, kEmbeddedFileCount, "OrbitControls.js"));
    replacePlaceholder(page, "/*GRASPSIM_THREE*/", io::findEmbeddedFile(kEmbeddedFiles, kEmbeddedFileCount, "three.min.js"));
    return page;
}

std::string writeReplayPage(const std::string& folder) {
    const ResultRecord record = readResultFolder(folder);
    const std::string path = folder + "/replay.html";
    io::writeFileAtomically(path, makeReplayPage(record));
    return path;
}

}  // namespace graspsim::viewer
