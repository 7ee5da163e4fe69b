#include "graspsim/results/result_files.h"

#include "graspsim/io/atomic_file.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <sstream>

namespace graspsim::results {

namespace {

// Shortest text that reads back to the same double, so files compare byte for byte across runs.
void put(std::ostringstream& out, double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    out << ',' << buffer;
}

void putVec3(std::ostringstream& out, const SimTK::Vec3& v) {
    for (int k = 0; k < 3; ++k) put(out, v[k]);
}

}  // namespace

std::string formatTrajectoryCsv(const simulation::SimulationResult& result) {
    std::ostringstream out;
    out << "time_s,object_x_m,object_y_m,object_z_m,object_qw,object_qx,object_qy,object_qz,grasp_quality_n";
    for (const std::string& joint : result.jointNames) out << ',' << joint << "_rad";
    out << '\n';
    for (const simulation::TrajectorySample& s : result.trajectory) {
        std::ostringstream row;
        putVec3(row, s.p_GO);
        for (int k = 0; k < 4; ++k) put(row, s.q_GO[k]);
        put(row, s.graspQuality);
        for (double q : s.jointAngles) put(row, q);
        char time[32];
        std::snprintf(time, sizeof time, "%.17g", s.time);
        out << time << row.str() << '\n';
    }
    return out.str();
}

std::string formatContactsCsv(const simulation::SimulationResult& result) {
    std::ostringstream out;
    out << "time_s,body_a,shape_a,body_b,shape_b,point_x_m,point_y_m,point_z_m,normal_x,normal_y,normal_z,"
           "normal_force_n,friction_x_n,friction_y_n,friction_z_n,penetration_m\n";
    for (const simulation::ContactSample& sample : result.contacts) {
        for (const contact::ContactReport& c : sample.contacts) {
            std::ostringstream row;
            putVec3(row, c.p_G);
            putVec3(row, SimTK::Vec3(c.n_G));
            put(row, c.normalForce);
            putVec3(row, c.frictionForce_G);
            put(row, c.depth);
            char time[32];
            std::snprintf(time, sizeof time, "%.17g", sample.time);
            out << time << ',' << c.bodyA << ',' << c.shapeA << ',' << c.bodyB << ',' << c.shapeB << row.str() << '\n';
        }
    }
    return out.str();
}

namespace {

// The integrator's own counts; -1 where it does not report one.
nlohmann::ordered_json formatIntegratorStatistics(const integration::IntegrationStatistics& s) {
    nlohmann::ordered_json j;
    j["steps"] = s.steps;
    j["rhs_evaluations"] = s.rhsEvaluations;
    j["jacobian_evaluations"] = s.jacobianEvaluations;
    j["linear_solver_setups"] = s.linearSolverSetups;
    j["error_test_failures"] = s.errorTestFailures;
    j["convergence_failures"] = s.convergenceFailures;
    j["projections"] = s.projections;
    j["root_evaluations"] = s.rootEvaluations;
    j["triggered_events"] = s.triggeredEvents;
    j["scheduled_events"] = s.scheduledEvents;
    j["restarts"] = s.restarts;
    return j;
}

}  // namespace

std::string formatSummaryJson(const simulation::SimulationSummary& s) {
    nlohmann::ordered_json j;
    j["scenario"] = s.scenario;
    j["contact"] = simulation::toString(s.contact);
    j["mode"] = simulation::toString(s.mode);
    j["perturbation"] = s.perturbation;
    j["complete"] = s.complete;
    if (!s.complete) j["failure"] = s.failure;
    j["sim_time_s"] = s.simTime;
    j["wall_time_s"] = s.wallTime;
    j["plan_time_s"] = s.planTime;
    j["steps"] = s.steps;
    j["mean_step_us"] = s.meanStepUs;
    j["ik_us_per_step"] = s.ikUsPerStep;
    j["dynamics_us_per_step"] = s.dynamicsUsPerStep;
    j["ik_solves"] = s.ikSolves;
    j["settle_time_s"] = s.settleTime;
    j["object_displacement_m"] = s.objectDisplacement;
    j["max_penetration_m"] = s.maxPenetration;
    j["initial_penetration_m"] = s.initialPenetration;
    j["max_grasp_quality_n"] = s.maxGraspQuality;
    j["held"] = s.held;
    j["max_fingertip_goal_distance_m"] = s.maxFingertipGoalDistance;
    j["full_step_us"] = s.fullStepUs;
    j["full_steps"] = s.fullSteps;
    j["full_wall_s_per_sim_s"] = s.fullWallPerSimSecond;
    j["integrator"] = s.integrator;
    j["integrator_statistics"] = formatIntegratorStatistics(s.integratorStatistics);
    if (s.mode != simulation::SimulationMode::Approx) return j.dump(2) + "\n";
    j["constraint"] = simulation::toString(s.constraint);
    j["engaged"] = s.engaged;
    j["engage_time_s"] = s.engaged ? nlohmann::ordered_json(s.engageTime) : nlohmann::ordered_json(nullptr);
    j["release_time_s"] = s.releaseTime >= 0 ? nlohmann::ordered_json(s.releaseTime) : nlohmann::ordered_json(nullptr);
    j["q_at_engage_n"] = s.qAtEngage;
    j["engage_obstacle_at_end"] = s.engageObstacleAtEnd.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(s.engageObstacleAtEnd);
    j["q_threshold_n"] = s.qThreshold;
    j["q_minimum_n"] = s.qMinimum;
    j["min_engaged_grasp_quality_n"] = s.minEngagedGraspQuality;
    j["engaged_penetration_at_engage_m"] = s.engagedPenetrationAtEngage;
    j["max_engaged_penetration_m"] = s.maxEngagedPenetration;
    j["max_engaged_penetration_growth_m"] = s.maxEngagedPenetrationGrowth;
    j["max_release_velocity_jump_m_s"] = s.maxReleaseVelocityJump;
    j["approx_step_us"] = s.approxStepUs;
    j["approx_steps"] = s.approxSteps;
    j["approx_wall_s_per_sim_s"] = s.approxWallPerSimSecond;
    return j.dump(2) + "\n";
}

std::string formatEventsCsv(const simulation::SimulationResult& result) {
    std::ostringstream out;
    out << "time_s,event,grasp_quality_n,velocity_jump_m_s,reason\n";
    for (const simulation::GraspEvent& e : result.events) {
        std::ostringstream row;
        put(row, e.quality);
        put(row, e.velocityJump);
        char time[32];
        std::snprintf(time, sizeof time, "%.17g", e.time);
        // The reason is free text with commas: quote it (RFC 4180; it contains no quotes).
        out << time << ',' << simulation::toString(e.kind) << row.str() << ",\"" << e.reason << "\"\n";
    }
    return out.str();
}

std::string formatConstraintCsv(const simulation::SimulationResult& result) {
    static const char* const kAxes[6] = {"rx", "ry", "rz", "x", "y", "z"};
    std::ostringstream out;
    out << "time_s,origin_x_m,origin_y_m,origin_z_m,qw,qx,qy,qz";
    for (const char* axis : kAxes) out << ",limit_" << axis;
    for (const char* axis : kAxes) out << ",reaction_" << axis;
    for (const char* axis : kAxes) out << ",lower_limit_" << axis;
    out << '\n';
    for (const simulation::ConstraintSample& c : result.constraint) {
        std::ostringstream row;
        putVec3(row, c.X_GM.p());
        const SimTK::Quaternion q = c.X_GM.R().convertRotationToQuaternion();
        for (int k = 0; k < 4; ++k) put(row, q[k]);
        for (int k = 0; k < 6; ++k) put(row, c.limits[k]);
        for (int k = 0; k < 6; ++k) put(row, c.reaction[k]);
        for (int k = 0; k < 6; ++k) put(row, c.lowerLimits[k]);
        char time[32];
        std::snprintf(time, sizeof time, "%.17g", c.time);
        out << time << row.str() << '\n';
    }
    return out.str();
}

void writeResultFiles(const std::string& folder, const simulation::SimulationResult& result) {
    io::writeFileAtomically(folder + "/trajectory.csv", formatTrajectoryCsv(result));
    io::writeFileAtomically(folder + "/contacts.csv", formatContactsCsv(result));
    io::writeFileAtomically(folder + "/summary.json", formatSummaryJson(result.summary));
    if (result.summary.mode != simulation::SimulationMode::Approx) {
        for (const char* name : {"/events.csv", "/constraint.csv"}) io::removeStaleFile(folder + name);
        return;
    }
    io::writeFileAtomically(folder + "/events.csv", formatEventsCsv(result));
    io::writeFileAtomically(folder + "/constraint.csv", formatConstraintCsv(result));
}

}  // namespace graspsim::results
