#include "graspsim/control/grasp_controller.h"

#include "graspsim/error.h"

#include <algorithm>

namespace graspsim::control {

GraspController::GraspController(const JointPdController& pd, FingertipIk& ik, std::vector<std::string> ikJoints,
                                 const SimTK::MobilizedBody& goalFrame, double ikInterval, IkTiming& timing)
    : SimTK::PeriodicEventHandler(ikInterval), pd_(pd), ik_(ik), goalFrame_(goalFrame), timing_(timing) {
    const std::vector<std::string>& pdJoints = pd.getJointNames();
    for (const std::string& joint : ikJoints) {
        const auto it = std::find(pdJoints.begin(), pdJoints.end(), joint);
        if (it == pdJoints.end()) throw Error("grasp controller: IK joint '" + joint + "' has no PD controller");
        targetSlots_.push_back(static_cast<int>(it - pdJoints.begin()));
    }
}

void GraspController::updateTargets(SimTK::State& state) const {
    const auto start = std::chrono::steady_clock::now();
    const SimTK::Transform& X_GF = goalFrame_.getBodyTransform(state);
    std::vector<SimTK::Vec3> goals_G;
    goals_G.reserve(goals_.size());
    for (const FingertipGoal& g : goals_) goals_G.push_back(X_GF * g.p_FG);
    const SimTK::Vector q = ik_.solve(state, goals_G);
    SimTK::Vector targets = pd_.getTargets(state);
    for (std::size_t k = 0; k < targetSlots_.size(); ++k) targets[targetSlots_[k]] = q[static_cast<int>(k)];
    // Ramped over one interval, one interval from now, rather than set: the torques stay
    // continuous, and an integrator that has stepped up to an interval past this instant need
    // not restart (joint_pd_controller.h).
    pd_.rampTargets(state, targets, getEventInterval(), getEventInterval());
    timing_.solves += 1;
    timing_.totalSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    timing_.lastError = ik_.getLastError();
}

void GraspController::handleEvent(SimTK::State& state, SimTK::Real, bool& shouldTerminate) const {
    shouldTerminate = false;
    // The goal frame's pose needs Stage::Position; Simbody hands event handlers a state realized that far.
    updateTargets(state);
}

}  // namespace graspsim::control
