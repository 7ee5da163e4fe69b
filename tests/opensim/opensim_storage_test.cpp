// OpenSim storage files: the header of motion.mot and object_forces.sto field by field as
// OpenSim documents its Storage format (name; version=1; nRows; nColumns, time included;
// inDegrees; endheader; then tab-separated labels and rows), values against a hand-made result,
// and external_loads.xml's ExternalForce fields.

#include "graspsim/opensim/opensim_storage.h"

#include <gtest/gtest.h>
#include <tinyxml.h>

#include <sstream>
#include <string>
#include <vector>

namespace graspsim::opensim {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::vector<std::string> splitTabs(const std::string& line) {
    std::vector<std::string> fields;
    std::istringstream in(line);
    for (std::string field; std::getline(in, field, '\t');) fields.push_back(field);
    return fields;
}

std::vector<double> parseRow(const std::string& line) {
    std::vector<double> values;
    for (const std::string& field : splitTabs(line)) values.push_back(std::stod(field));
    return values;
}

contact::ContactReport makeContact(const std::string& body, const std::string& shape, SimTK::Vec3 p, SimTK::Vec3 n,
                                   double fn, SimTK::Vec3 ft) {
    contact::ContactReport c;
    c.bodyA = body;
    c.shapeA = shape;
    c.bodyB = "ball";
    c.shapeB = "ball";
    c.p_G = p;
    c.n_G = SimTK::UnitVec3(n);
    c.normalForce = fn;
    c.frictionForce_G = ft;
    return c;
}

// Two joints, three samples; the thumb touches from the second sample, the index at two points
// in the second sample only.
simulation::SimulationResult makeResult() {
    simulation::SimulationResult r;
    r.jointNames = {"index_mcp_flexion", "thumb_ip"};
    for (int i = 0; i < 3; ++i) {
        simulation::TrajectorySample s;
        s.time = 0.01 * i;
        s.jointAngles = {0.1 * i, -kPi / 4};
        r.trajectory.push_back(s);
    }
    simulation::ContactSample first{0.0, {makeContact("index_distal", "pad", {0.1, 0.2, 0.3}, {0, 0, 1}, 2, {0.5, 0, 0})}};
    simulation::ContactSample second{0.01,
                                     {makeContact("thumb_distal", "pad", {0.4, 0.5, 0.6}, {0, 1, 0}, 3, {0, 0, 0.25}),
                                      makeContact("index_distal", "pad", {0.11, 0.2, 0.3}, {0, 0, 1}, 1, {0, 0, 0}),
                                      makeContact("index_distal", "pad", {0.12, 0.2, 0.3}, {1, 0, 0}, 4, {0, 0, 0})}};
    simulation::ContactSample third{0.02, {}};
    r.contacts = {first, second, third};
    return r;
}

void expectHeader(const std::vector<std::string>& lines, const std::string& name, int rows, int columns, const char* inDegrees) {
    ASSERT_GE(lines.size(), 7u);
    EXPECT_EQ(lines[0], name);
    EXPECT_EQ(lines[1], "version=1");
    EXPECT_EQ(lines[2], "nRows=" + std::to_string(rows));
    EXPECT_EQ(lines[3], "nColumns=" + std::to_string(columns));
    EXPECT_EQ(lines[4], std::string("inDegrees=") + inDegrees);
    EXPECT_EQ(lines[5], "endheader");
    EXPECT_EQ(splitTabs(lines[6]).size(), static_cast<std::size_t>(columns));
    EXPECT_EQ(lines.size(), 7u + rows);
    for (std::size_t i = 7; i < lines.size(); ++i) EXPECT_EQ(splitTabs(lines[i]).size(), static_cast<std::size_t>(columns));
}

TEST(OpenSimStorage, MotionHasOpenSimsHeaderAndAnglesInDegrees) {
    const auto lines = splitLines(formatMotionMot(makeResult()));
    expectHeader(lines, "motion", 3, 3, "yes");
    EXPECT_EQ(splitTabs(lines[6]), (std::vector<std::string>{"time", "index_mcp_flexion", "thumb_ip"}));
    const std::vector<double> row = parseRow(lines[9]);
    EXPECT_EQ(row[0], 0.02);
    EXPECT_NEAR(row[1], 0.2 * 180 / kPi, 1e-13);
    EXPECT_NEAR(row[2], -45.0, 1e-13);
}

TEST(OpenSimStorage, ObjectForcesHaveOneForceTripleEachWayAndAPointPerContact) {
    const auto lines = splitLines(formatObjectForcesSto(makeResult()));
    // Channels in order of first appearance: index pad, thumb pad, index pad's second point.
    expectHeader(lines, "object_forces", 3, 1 + 3 * 9, "no");
    const std::vector<std::string> labels = splitTabs(lines[6]);
    EXPECT_EQ(labels[1], "index_distal_pad_on_object_vx");
    EXPECT_EQ(labels[4], "index_distal_pad_on_hand_vx");
    EXPECT_EQ(labels[7], "index_distal_pad_px");
    EXPECT_EQ(labels[10], "thumb_distal_pad_on_object_vx");
    EXPECT_EQ(labels[27], "index_distal_pad_2_pz");
    const std::vector<double> first = parseRow(lines[7]), second = parseRow(lines[8]), third = parseRow(lines[9]);
    // f = fn n + ft on the object, -f on the hand.
    EXPECT_EQ(std::vector<double>(first.begin() + 1, first.begin() + 10), (std::vector<double>{0.5, 0, 2, -0.5, 0, -2, 0.1, 0.2, 0.3}));
    // The thumb does not touch yet: no force, its point is where it first touches.
    EXPECT_EQ(std::vector<double>(first.begin() + 10, first.begin() + 19), (std::vector<double>{0, 0, 0, 0, 0, 0, 0.4, 0.5, 0.6}));
    EXPECT_EQ(std::vector<double>(second.begin() + 10, second.begin() + 13), (std::vector<double>{0, 3, 0.25}));
    EXPECT_EQ(std::vector<double>(second.begin() + 19, second.begin() + 22), (std::vector<double>{4, 0, 0}));
    // Nothing touches at the end: zero forces, last points kept.
    EXPECT_EQ(std::vector<double>(third.begin() + 1, third.begin() + 10), (std::vector<double>{0, 0, 0, 0, 0, 0, 0.11, 0.2, 0.3}));
}

TEST(OpenSimStorage, ExternalLoadsApplyTheReactionsToTheHandBodies) {
    TiXmlDocument doc;
    doc.Parse(formatExternalLoadsXml(makeResult(), "object_forces.sto").c_str());
    ASSERT_FALSE(doc.Error()) << doc.ErrorDesc();
    const TiXmlElement* loads = doc.RootElement()->FirstChildElement("ExternalLoads");
    ASSERT_NE(loads, nullptr);
    EXPECT_STREQ(loads->FirstChildElement("datafile")->GetText(), "object_forces.sto");
    std::vector<std::string> names, bodies;
    for (const TiXmlElement* f = loads->FirstChildElement("objects")->FirstChildElement("ExternalForce"); f;
         f = f->NextSiblingElement("ExternalForce")) {
        names.push_back(f->Attribute("name"));
        bodies.push_back(f->FirstChildElement("applied_to_body")->GetText());
        EXPECT_STREQ(f->FirstChildElement("force_expressed_in_body")->GetText(), "ground");
        EXPECT_STREQ(f->FirstChildElement("point_expressed_in_body")->GetText(), "ground");
        EXPECT_EQ(f->FirstChildElement("force_identifier")->GetText(), names.back() + "_on_hand_v");
        EXPECT_EQ(f->FirstChildElement("point_identifier")->GetText(), names.back() + "_p");
    }
    EXPECT_EQ(names, (std::vector<std::string>{"index_distal_pad", "thumb_distal_pad", "index_distal_pad_2"}));
    EXPECT_EQ(bodies, (std::vector<std::string>{"index_distal", "thumb_distal", "index_distal"}));
}

}  // namespace
}  // namespace graspsim::opensim
