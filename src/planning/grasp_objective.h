#pragma once
// The planner's objective: the arm model in a grasp template's posture and the object as a
// contact shape, the optimization variables (finger and thumb joint angles, the object's
// position offset and, unless it is a sphere, a rotation vector) and the cost the planner
// minimizes. Private to the planning layer.

#include "graspsim/planning/arm_kinematics.h"
#include "graspsim/planning/grasp_planner.h"
#include "graspsim/planning/grasp_template.h"
#include "graspsim/planning/release_press.h"

#include <map>
#include <string>
#include <vector>

namespace graspsim::planning {

// An end-effector's pad: the point and its outward normal in its body frame, the capsule it sits
// on (index into ArmKinematics::getSegmentShapes) and the movable joints from the palm out to it.
struct Pad {
    std::string effector;
    int body = 0;
    SimTK::Vec3 p_BE{0, 0, 0};
    SimTK::UnitVec3 n_B;
    int capsule = -1;
    std::vector<int> joints;
};

class GraspObjective {
public:
    GraspObjective(const GraspRequest& request, const GraspTemplate& graspTemplate);

    const std::vector<double>& getStart() const { return m_start; }
    const std::vector<double>& getLowerBounds() const { return m_lower; }
    const std::vector<double>& getUpperBounds() const { return m_upper; }
    const std::vector<double>& getInitialSteps() const { return m_steps; }
    // The wanted pad-to-surface distance of goal pad `pad` (m; all start at the request's targetGap).
    double getTargetGap(std::size_t pad) const { return m_targetGaps.at(pad); }
    void setTargetGap(std::size_t pad, double gap) { m_targetGaps.at(pad) = gap; }
    // Whether the cost asks every goal finger to keep pressing once the object is released (a
    // grasp of three or more pads; release_press.h).
    void setReleaseBalanced(bool on) { m_balanceRelease = on; }
    // The controller's press depth the plan is made for (m): the pads' goals are pressed this far in.
    void setPressDepth(double depth) { m_request.pressDepth = depth; }
    double getObjectWidth() const { return m_objectWidth; }
    double getHandSpan() const { return m_handSpan; }
    const std::string& getSpanName() const { return m_spanName; }

    // The cost at variables x (dimensionless; a 1 mm gap error costs 1).
    double evaluate(const double* x);
    // The plan at variables x: joint angles, object pose, goals (not rounded, no diagnostics).
    GraspPlan makePlan(const double* x) const;
    // The variables of joint angles (rad, by name; a finger joint not named keeps its start) and
    // object pose X_GO: makePlan's inverse, clamped to the bounds. A plan made for another shape of
    // the same object (its smooth stand-in) as a start for this one.
    std::vector<double> findVariables(const std::map<std::string, double>& angles, const SimTK::Transform& X_GO) const;
    // The checks' numbers for joint angles (rad, by name; missing = 0) and object pose X_GO.
    PlanDiagnostics calcDiagnostics(const std::map<std::string, double>& angles, const SimTK::Transform& X_GO) const;
    // The surface point (in O) nearest each goal pad, rounded to 0.1 mm, for joint angles and X_GO.
    std::map<std::string, SimTK::Vec3> findGoals(const std::map<std::string, double>& angles,
                                                 const SimTK::Transform& X_GO) const;

    // The deepest overlap (m, 0 if none) of the shapes of the body carrying `effector` with the
    // object, for joint angles (rad, by name) and object pose X_GO.
    double calcEffectorBodyDepth(const std::map<std::string, double>& angles, const SimTK::Transform& X_GO,
                                 const std::string& effector) const;
    // Per goal pad, what it still presses once the object is released (m; release_press.h), for
    // joint angles (rad, by name) and object pose X_GO.
    std::vector<double> calcReleasedPress(const std::map<std::string, double>& angles, const SimTK::Transform& X_GO) const;

private:
    void setUpVariables(const GraspTemplate& graspTemplate);
    void placeObjectAtStart();
    void calcHandSpan(GraspType type);
    SimTK::Transform findObjectPose(const double* x) const;
    std::vector<double> findJointAngles(const double* x) const;
    double calcOppositionCost(const SimTK::Vec3& p_thumb, const SimTK::Vec3& n_thumb, const SimTK::Vec3& p_fingers,
                              const SimTK::Vec3& n_fingers) const;
    double calcCouplingCost(const double* x) const;
    double calcGravityCost(const SimTK::Transform& X_GS, const SimTK::Vec3& sumOutward_S) const;
    FingerPress calcFingerPress(std::size_t pad, const std::vector<double>& q, const std::vector<SimTK::Transform>& X_GB,
                                const SimTK::Transform& X_GS) const;
    std::vector<double> predictReleasedPress(const std::vector<double>& q, const std::vector<SimTK::Transform>& X_GB,
                                             const SimTK::Transform& X_GS) const;
    double calcReleaseCost(const std::vector<double>& q, const SimTK::Transform& X_GS) const;
    std::vector<SimTK::Transform> calcBodyPoses(const std::map<std::string, double>& angles) const;

    SimTK::Vec3 findThesisBallCentre() const;

    GraspRequest m_request;
    GraspTemplate m_template;
    ArmKinematics m_arm;
    int m_palm = -1;  // the palm's body index in m_arm (the builder's palm role)
    std::vector<Pad> m_pads;
    std::vector<double> m_targetGaps;               // per pad (m)
    std::vector<contact::ContactShape> m_inflated;  // segment shapes grown by the clearance
    std::vector<double> m_baseAngles;               // per joint: the template posture
    std::vector<int> m_freeJoints;                  // joint indices the optimizer moves
    std::vector<std::pair<int, int>> m_coupledJoints; // (PIP, DIP) variable indices per finger
    bool m_rotates = false;                         // the object's orientation is a variable
    bool m_balanceRelease = false;                  // the cost has the release term
    SimTK::Transform m_X_GO0;                       // object pose at the start
    std::vector<double> m_start, m_lower, m_upper, m_steps;
    double m_objectWidth = 0, m_handSpan = 0;
    std::string m_spanName;
    std::vector<SimTK::Transform> m_X_GB;           // scratch
};

}  // namespace graspsim::planning
