#include "graspsim/viewer/result_reader.h"

#include "graspsim/error.h"
#include "graspsim/model/urdf_import.h"
#include "graspsim/results/provenance.h"
#include "graspsim/scenario/scenario_file.h"
#include "csv_table.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace graspsim::viewer {

namespace {

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot be read");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

nlohmann::json parseJson(const std::string& path, const std::string& text) {
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        throw InputError(path + ": is not valid JSON (" + std::string(e.what()) + ")");
    }
}

// The folder must be a result of this format; say which of the three ways it is not.
void checkFolder(const std::string& folder) {
    namespace fs = std::filesystem;
    if (!fs::is_directory(folder)) throw InputError("'" + folder + "' is not a folder; give the folder of a graspsim result (simulate --out)");
    const bool hasProvenance = fs::exists(folder + "/provenance.json");
    if (!hasProvenance && !fs::exists(folder + "/trajectory.csv")) {
        throw InputError("'" + folder + "' is not a graspsim result folder (no provenance.json, no trajectory.csv)");
    }
    if (!hasProvenance) {
        throw InputError("'" + folder + "' is a result of an older graspsim (no provenance.json); run graspsim simulate again to view it");
    }
    const std::string path = folder + "/provenance.json";
    const nlohmann::json provenance = parseJson(path, readText(path));
    // A hand-edited or foreign file: a JSON object whose "format", if given, is a whole number.
    const auto found = provenance.is_object() ? provenance.find("format") : provenance.end();
    if (!provenance.is_object() || (found != provenance.end() && !found->is_number_integer())) {
        const std::string value = provenance.is_object() ? found->dump() : provenance.dump();
        throw InputError(path + ": " + (provenance.is_object() ? "field 'format' " : "") + "value '" + value.substr(0, 80) +
                         "' is not accepted; a graspsim provenance.json is a JSON object with \"format\": " +
                         std::to_string(results::kResultFormat));
    }
    const int format = found == provenance.end() ? 0 : found->get<int>();
    if (format != results::kResultFormat) {
        throw InputError(path + ": result format " + std::to_string(format) + " is not supported (this graspsim reads format " +
                         std::to_string(results::kResultFormat) + "); run graspsim simulate again to view it");
    }
    for (const char* file : {"scenario.yaml", "model.urdf", "summary.json", "trajectory.csv", "contacts.csv"}) {
        if (!fs::exists(folder + "/" + file)) throw InputError("'" + folder + "' is an incomplete result: " + file + " is missing");
    }
}

std::vector<TrajectoryRow> readTrajectory(const std::string& path, const model::ModelDescription& model) {
    const CsvTable table = readCsvTable(path, readText(path));
    table.requireColumns({"time_s", "object_x_m", "object_y_m", "object_z_m", "object_qw", "object_qx", "object_qy",
                          "object_qz", "grasp_quality_n"});
    std::vector<std::pair<std::string, std::size_t>> joints;
    for (std::size_t c = 9; c < table.header.size(); ++c) {
        const std::string& column = table.header[c];
        const std::string joint = column.size() > 4 ? column.substr(0, column.size() - 4) : "";
        if (column.size() <= 4 || column.compare(column.size() - 4, 4, "_rad") != 0 || !model.findJoint(joint)) {
            throw InputError(path + ": column '" + column + "' is not a joint angle of model.urdf (<joint>_rad)");
        }
        joints.emplace_back(joint, c);
    }
    std::vector<TrajectoryRow> rows;
    for (std::size_t r = 0; r < table.rows.size(); ++r) {
        TrajectoryRow row;
        row.time = table.getNumber(r, 0);
        // The replay interpolates between samples by time: NaN or a step back would show nonsense.
        if (!std::isfinite(row.time) || (!rows.empty() && row.time < rows.back().time)) {
            throw InputError(path + ":" + std::to_string(r + 2) + ": field 'time_s' value '" + table.rows[r][0] +
                             "' is not accepted; sample times are finite and in increasing order");
        }
        for (int k = 0; k < 3; ++k) row.p_GO[k] = table.getNumber(r, 1 + k);
        for (int k = 0; k < 4; ++k) row.q_GO[k] = table.getNumber(r, 4 + k);
        row.graspQuality = table.getNumber(r, 8);
        for (const auto& [joint, c] : joints) row.jointAngles[joint] = table.getNumber(r, c);
        rows.push_back(std::move(row));
    }
    if (rows.empty()) throw InputError(path + ": has no samples");
    return rows;
}

std::vector<ContactRow> readContacts(const std::string& path) {
    const CsvTable table = readCsvTable(path, readText(path));
    table.requireColumns({"time_s", "body_a", "shape_a", "body_b", "shape_b", "point_x_m", "point_y_m", "point_z_m",
                          "normal_x", "normal_y", "normal_z", "normal_force_n", "friction_x_n", "friction_y_n",
                          "friction_z_n", "penetration_m"});
    std::vector<ContactRow> rows;
    for (std::size_t r = 0; r < table.rows.size(); ++r) {
        ContactRow row;
        row.time = table.getNumber(r, 0);
        row.bodyA = table.rows[r][1];
        row.bodyB = table.rows[r][3];
        for (int k = 0; k < 3; ++k) {
            row.p_G[k] = table.getNumber(r, 5 + k);
            row.n_G[k] = table.getNumber(r, 8 + k);
            row.friction_G[k] = table.getNumber(r, 12 + k);
        }
        row.normalForce = table.getNumber(r, 11);
        rows.push_back(std::move(row));
    }
    return rows;
}

simulation::GraspEventKind parseEventKind(const std::string& text, const std::string& path) {
    for (auto kind : {simulation::GraspEventKind::Engage, simulation::GraspEventKind::Release, simulation::GraspEventKind::Detach}) {
        if (simulation::toString(kind) == text) return kind;
    }
    throw InputError(path + ": event '" + text + "' is not engage, release or detach");
}

std::vector<EventRow> readEvents(const std::string& path) {
    const CsvTable table = readCsvTable(path, readText(path));
    table.requireColumns({"time_s", "event", "grasp_quality_n", "velocity_jump_m_s", "reason"});
    std::vector<EventRow> rows;
    for (std::size_t r = 0; r < table.rows.size(); ++r) rows.push_back({table.getNumber(r, 0), parseEventKind(table.rows[r][1], path), table.rows[r][4]});
    return rows;
}

std::vector<ConstraintRow> readConstraint(const std::string& path) {
    const CsvTable table = readCsvTable(path, readText(path));
    table.requireColumns({"time_s", "origin_x_m", "origin_y_m", "origin_z_m", "qw", "qx", "qy", "qz", "limit_rx", "limit_ry",
                          "limit_rz", "limit_x", "limit_y", "limit_z", "reaction_rx", "reaction_ry", "reaction_rz",
                          "reaction_x", "reaction_y", "reaction_z"});
    std::vector<ConstraintRow> rows;
    for (std::size_t r = 0; r < table.rows.size(); ++r) {
        ConstraintRow row;
        row.time = table.getNumber(r, 0);
        for (int k = 0; k < 3; ++k) row.p_GM[k] = table.getNumber(r, 1 + k);
        for (int k = 0; k < 4; ++k) row.q_GM[k] = table.getNumber(r, 4 + k);
        for (int k = 0; k < 6; ++k) row.limits[k] = table.getNumber(r, 8 + k);
        for (int k = 0; k < 6; ++k) row.reaction[k] = table.getNumber(r, 14 + k);
        rows.push_back(row);
    }
    return rows;
}

void readSummary(ResultRecord& record) {
    const std::string path = record.folder + "/summary.json";
    record.summaryJson = readText(path);
    const nlohmann::json summary = parseJson(path, record.summaryJson);
    try {
        record.mode = simulation::parseSimulationMode(summary.at("mode").get<std::string>(), path + " mode");
        record.contactModel = summary.at("contact").get<std::string>();
        record.perturbation = summary.at("perturbation").get<std::string>();
        record.simTime = summary.at("sim_time_s").get<double>();
        record.realization = summary.value("constraint", "");
    } catch (const nlohmann::json::exception& e) {
        throw InputError(path + ": is not a graspsim summary (" + std::string(e.what()) + ")");
    }
}

}  // namespace

ResultRecord readResultFolder(const std::string& folder) {
    checkFolder(folder);
    ResultRecord record;
    record.folder = folder;
    record.provenanceJson = readText(folder + "/provenance.json");
    record.scenario = scenario::loadScenarioFile(folder + "/scenario.yaml");
    record.model = model::importUrdf(folder + "/model.urdf");
    readSummary(record);
    record.trajectory = readTrajectory(folder + "/trajectory.csv", record.model);
    record.contacts = readContacts(folder + "/contacts.csv");
    if (record.mode == simulation::SimulationMode::Approx) {
        for (const char* file : {"events.csv", "constraint.csv"}) {
            if (!std::filesystem::exists(folder + "/" + file)) {
                throw InputError("'" + folder + "' is an incomplete approx result: " + file + " is missing");
            }
        }
        record.events = readEvents(folder + "/events.csv");
        record.constraint = readConstraint(folder + "/constraint.csv");
    }
    return record;
}

}  // namespace graspsim::viewer
