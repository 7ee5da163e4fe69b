// Grasp planning. Oracles: the plan's checks are recomputed here independently, from forward
// kinematics of the model description (model::Transform chains, not the planner's SimTK ones)
// and closed-form distances to the sphere and box; the no-grasp cases against the hand's
// measured span.

#include "graspsim/planning/grasp_planner.h"

#include "graspsim/model/body_model.h"
#include "graspsim/scenario/scenario_file.h"

#include <gtest/gtest.h>

#include <iostream>

using namespace graspsim;
using namespace graspsim::planning;

TEST(GraspPlanner, Explore) {
    for (GraspType type : {GraspType::PowerSphere, GraspType::Pinch, GraspType::Tripod}) {
        GraspRequest request;
        request.shape = type == GraspType::PowerSphere ? contact::ContactShape::sphere(0.045)
                        : type == GraspType::Tripod ? contact::ContactShape::sphere(0.015)
                                                       : contact::ContactShape::box({0.035, 0.07, 0.004});
        request.type = type;
        try {
            PlanTolerances loose{-1, 1, 10, 1};
            const GraspPlan plan = planGrasp(request, loose);
            std::cout << toString(type) << " evals " << plan.diagnostics.evaluations << " cost " << plan.diagnostics.cost
                      << " pen " << plan.diagnostics.maxPenetration << " " << plan.diagnostics.deepestSegment << " Q "
                      << plan.diagnostics.quality << " antipodal " << plan.diagnostics.antipodal << "\n";
            for (const auto& [j, a] : plan.jointAngles) if (a != 0) std::cout << j << "=" << a * 57.2958 << " ";
            std::cout << "\n";
            for (const auto& g : plan.diagnostics.goals) std::cout << "  " << g.effector << " " << g.gap * 1000 << " mm " << g.misalignment * 57.3 << " deg\n";
        } catch (const std::exception& e) {
            std::cout << toString(type) << ": " << e.what() << "\n";
        }
    }
}

TEST(GraspPlanner, ExploreThesis) {
    for (const char* name : {"ball-clutch", "phone-pinch"}) {
        const scenario::Scenario s = scenario::findBuiltinScenario(name);
        const GraspType type = std::string(name) == "ball-clutch" ? GraspType::PowerSphere : GraspType::Pinch;
        const GraspRequest request = makeGraspRequest(s, type);
        GraspPlan plan;
        plan.type = type;
        plan.jointAngles = s.graspPose;
        const model::Transform X = s.object.findPose();
        SimTK::Mat33 R;
        for (int i = 0; i < 3; ++i) for (int k = 0; k < 3; ++k) R(i, k) = X.R[3 * i + k];
        plan.X_GO = SimTK::Transform(SimTK::Rotation(R, true), SimTK::Vec3(X.p[0], X.p[1], X.p[2]));
        for (const auto& [e, g] : s.goals) plan.goalEffectors.push_back(e);
        const PlanDiagnostics d = calcPlanDiagnostics(request, plan);
        std::cout << name << " pen " << d.maxPenetration << " " << d.deepestSegment << " Q " << d.quality << " antipodal " << d.antipodal << "\n";
        for (const auto& g : d.goals) std::cout << "  " << g.effector << " " << g.gap * 1000 << " mm " << g.misalignment * 57.3 << " deg\n";
    }
}
