#pragma once
/// @file
/// Reading a result folder that `graspsim simulate` wrote (results/result_folder.h) back, for the
/// replay viewer.
///
/// The folder must hold provenance.json of format results::kResultFormat, scenario.yaml,
/// model.urdf, summary.json, trajectory.csv and contacts.csv; approx runs also events.csv and
/// constraint.csv. Anything else (not a folder, a folder of something else, a result from an older
/// graspsim without provenance.json, a file whose columns are not the expected ones) is one
/// InputError line naming the folder or file and what is wrong.

#include "graspsim/model/model_description.h"
#include "graspsim/scenario/scenario.h"
#include "graspsim/simulation/grasp_switch.h"
#include "graspsim/simulation/simulation_options.h"

#include <array>
#include <map>
#include <string>
#include <vector>

namespace graspsim::viewer {

/// One row of trajectory.csv.
struct TrajectoryRow {
    double time = 0;                            ///< s
    model::Vec3 p_GO{0, 0, 0};                  ///< object centre of mass in ground (m)
    std::array<double, 4> q_GO{1, 0, 0, 0};     ///< object orientation quaternion w, x, y, z
    double graspQuality = 0;                    ///< N
    std::map<std::string, double> jointAngles;  ///< rad, by joint name
};

/// One row of contacts.csv.
struct ContactRow {
    double time = 0;                 ///< s
    std::string bodyA, bodyB;        ///< the hand body and the object body (or the other way round)
    model::Vec3 p_G{0, 0, 0};        ///< contact point in ground (m)
    model::Vec3 n_G{0, 0, 0};        ///< unit normal from a toward b
    double normalForce = 0;          ///< N
    model::Vec3 friction_G{0, 0, 0}; ///< friction force on b (N, ground)
};

/// One row of events.csv.
struct EventRow {
    double time = 0;     ///< s
    simulation::GraspEventKind kind = simulation::GraspEventKind::Engage;
    std::string reason;
};

/// One row of constraint.csv.
struct ConstraintRow {
    double time = 0;                          ///< s
    model::Vec3 p_GM{0, 0, 0};                ///< constraint frame origin in ground (m)
    std::array<double, 4> q_GM{1, 0, 0, 0};   ///< its orientation quaternion w, x, y, z
    std::array<double, 6> limits{};           ///< N m, N; +inf on locked axes
    std::array<double, 6> reaction{};         ///< N m, N, along M's axes
};

/// A whole result folder.
struct ResultRecord {
    std::string folder;
    scenario::Scenario scenario;     ///< scenario.yaml
    model::ModelDescription model;   ///< model.urdf
    std::string summaryJson;         ///< summary.json as written
    std::string provenanceJson;      ///< provenance.json as written
    simulation::SimulationMode mode = simulation::SimulationMode::Full;
    std::string contactModel, perturbation, realization;  ///< from summary.json (realization: the approximation's constraint, bushing or weld)
    double simTime = 0;              ///< simulated time reached (s), from summary.json
    std::vector<TrajectoryRow> trajectory;
    std::vector<ContactRow> contacts;
    std::vector<EventRow> events;          ///< empty unless approx
    std::vector<ConstraintRow> constraint; ///< empty unless approx (merged)
};

/// Reads the result folder `folder`.
/// @throws graspsim::InputError as described in the file comment.
ResultRecord readResultFolder(const std::string& folder);

}  // namespace graspsim::viewer
