#include "grasp_objective.h"

#include "object_extents.h"

#include "graspsim/contact/shape_contact.h"
#include "graspsim/contact/surface_point.h"
#include "graspsim/grasp/grasp_quality.h"
#include "graspsim/model/body_model.h"
#include "graspsim/model/hand_model.h"

#include <algorithm>
#include <cmath>

namespace graspsim::planning {

namespace {

// Cost weights. A 1 mm gap error costs 1; a pad turned by 10 deg from the surface costs about
// 0.3; a segment 1 mm within clearance of the object costs 10; leaving the start pose by 0.3 rad
// costs 0.01 per joint (it only picks among equally good poses).
constexpr double kMillimetre = 1e-3;
constexpr double kAlignWeight = 20;
constexpr double kPenetrationWeight = 10;
constexpr double kStartWeight = 1.0;
constexpr double kOppositionWeight = 20;
constexpr double kCouplingWeight = 5;
constexpr double kCentreWeight = 0.005;
constexpr double kGravityWeight = 50;
constexpr double kReleaseWeight = 10;
// Segments are kept this far off the object (m), so a planned pose touches it only with the pads.
constexpr double kClearance = 0.001;
// Friction coefficient of the closure check: the default skin-plastic dynamic friction.
constexpr double kFriction = 0.7;

// Two contacts hold an object by friction when the line between them lies inside both friction
// cones (force closure). Q, the grasp matrix's smallest singular value, is round-off for any two
// point contacts (nothing resists a turn about their line), so the planner checks this instead
// and reports by how much it passes. n_G points into the object.
void checkAntipodal(const grasp::GraspContact& a, const grasp::GraspContact& b, PlanDiagnostics& d) {
    const Eigen::Vector3d line = (b.p_GC - a.p_GC).normalized();
    const double cosA = line.dot(a.n_G), cosB = -line.dot(b.n_G), cone = std::cos(std::atan(kFriction));
    d.antipodal = cosA > cone && cosB > cone;
    d.antipodalAngle = std::acos(std::clamp(std::min(cosA, cosB), -1.0, 1.0));
    d.frictionConeAngle = std::atan(kFriction);
}

contact::ContactShape inflate(contact::ContactShape shape, double by) {
    if (shape.type == contact::ContactShape::Type::Box) {
        shape.halfLengths += SimTK::Vec3(by);
    } else {
        shape.radius += by;
    }
    return shape;
}

// The movable joints from the palm out to `body`: the joints the controller's IK moves for a goal
// on it (goal_reach.cpp).
std::vector<int> findDigitJoints(const ArmKinematics& arm, std::string body) {
    const model::ModelDescription& d = arm.getModel();
    std::vector<int> joints;
    while (d.findBody(body) && d.findBody(body)->role != model::BodyRole::Palm) {
        const model::Joint* j = d.findParentJoint(body);
        if (!j) break;
        if (j->getDofCount() > 0) joints.push_back(arm.findJointIndex(j->name));
        body = j->parent;
    }
    return joints;
}

Pad findPad(const ArmKinematics& arm, const std::string& effector) {
    const model::EndEffector* e = arm.getModel().findEndEffector(effector);
    if (!e) throw InputError("the arm model has no end-effector '" + effector + "'");
    const int body = arm.findBodyIndex(e->body);
    const SimTK::Vec3 p_BE(e->p_BE[0], e->p_BE[1], e->p_BE[2]);
    // The pad faces away from the distal capsule's axis.
    const auto& shapes = arm.getSegmentShapes();
    for (std::size_t k = 0; k < shapes.size(); ++k) {
        const SegmentShape& s = shapes[k];
        if (s.body != body || s.shape.type != contact::ContactShape::Type::Capsule) continue;
        const SimTK::Vec3 p_SE = ~s.X_BS * p_BE;
        const double z = std::clamp(p_SE[2], -s.shape.length / 2, s.shape.length / 2);
        const SimTK::Vec3 n_S = p_SE - SimTK::Vec3(0, 0, z);
        return {effector, body, p_BE, SimTK::UnitVec3(s.X_BS.R() * n_S), static_cast<int>(k), findDigitJoints(arm, e->body)};
    }
    throw InputError("end-effector '" + effector + "' is not on a capsule segment");
}

// Built element by element: GCC 12 misreads Simbody's diagonal fill (Mat33(1)) as out of bounds.
SimTK::Mat33 makeDiagonal(double d) { return SimTK::Mat33(d, 0, 0, 0, d, 0, 0, 0, d); }

// The point nearest (least squares) to every pad's normal line, pulled slightly toward the
// pads' centroid so that antiparallel normals (a pinch) still give one point.
SimTK::Vec3 findNormalsMeet(const std::vector<SimTK::Vec3>& p, const std::vector<SimTK::UnitVec3>& n) {
    SimTK::Mat33 A = makeDiagonal(0);
    SimTK::Vec3 b(0), centroid(0);
    for (size_t i = 0; i < p.size(); ++i) centroid += p[i] / double(p.size());
    for (size_t i = 0; i < p.size(); ++i) {
        const SimTK::Mat33 P = makeDiagonal(1) - SimTK::Vec3(n[i]) * ~SimTK::Vec3(n[i]);
        A += P;
        b += P * p[i];
    }
    const double pull = 0.05;
    A += makeDiagonal(pull);
    b += pull * centroid;
    return A.invert() * b;
}

// S's orientation in G with its thinnest axis (of `halfExtents`) along the squeeze and its
// longest along `out` (made perpendicular to the squeeze), right-handed.
SimTK::Rotation alignThinnestWithSqueeze(const SimTK::Vec3& halfExtents, const SimTK::UnitVec3& squeeze,
                                         const SimTK::Vec3& out) {
    std::array<int, 3> axis{0, 1, 2};
    std::sort(axis.begin(), axis.end(), [&](int a, int b) { return halfExtents[a] < halfExtents[b]; });
    const SimTK::UnitVec3 longest(out - dot(out, squeeze) * squeeze);
    std::array<SimTK::Vec3, 3> axes_G;  // S's axes in G
    axes_G[axis[0]] = SimTK::Vec3(squeeze);
    axes_G[axis[2]] = SimTK::Vec3(longest);
    axes_G[axis[1]] = cross(longest, squeeze);
    if (dot(cross(axes_G[0], axes_G[1]), axes_G[2]) < 0) axes_G[axis[1]] *= -1;
    const SimTK::Mat33 R_SG(~axes_G[0], ~axes_G[1], ~axes_G[2]);
    return SimTK::Rotation(~R_SG, true);
}

}  // namespace

GraspObjective::GraspObjective(const GraspRequest& request, const GraspTemplate& graspTemplate)
    : m_request(request), m_template(graspTemplate), m_arm(model::buildBodyModel(request.bodyOptions)),
      m_palm(m_arm.findBodyIndex(m_arm.getModel().findPalm().name)) {
    for (const std::string& effector : graspTemplate.goalEffectors) m_pads.push_back(findPad(m_arm, effector));
    m_targetGaps.assign(m_pads.size(), request.targetGap);
    for (const SegmentShape& s : m_arm.getSegmentShapes()) m_inflated.push_back(inflate(s.shape, kClearance));
    setUpVariables(graspTemplate);
    m_objectWidth = calcObjectWidth(request.shape);
    placeObjectAtStart();
    calcHandSpan(request.type);
}

void GraspObjective::setUpVariables(const GraspTemplate& graspTemplate) {
    const auto& joints = m_arm.getModel().joints;
    m_baseAngles.assign(joints.size(), 0.0);
    for (const auto& [name, angle] : graspTemplate.startPose) m_baseAngles[m_arm.findJointIndex(name)] = angle;
    for (int j = 0; j < static_cast<int>(joints.size()); ++j) {
        if (joints[j].getDofCount() == 0 || !isFingerJoint(joints[j].name)) continue;
        m_freeJoints.push_back(j);
        const double margin = std::min(graspTemplate.jointMargin, (joints[j].upper - joints[j].lower) / 4);
        m_lower.push_back(joints[j].lower + margin);
        m_upper.push_back(joints[j].upper - margin);
        m_start.push_back(std::clamp(m_baseAngles[j], m_lower.back(), m_upper.back()));
        m_steps.push_back(0.1);
    }
    for (size_t k = 0; k < m_freeJoints.size(); ++k) {
        const std::string& name = joints[m_freeJoints[k]].name;
        if (name.size() < 11 || name.compare(name.size() - 11, 11, "pip_flexion") != 0) continue;
        const std::string dipName = name.substr(0, name.size() - 11) + "dip_flexion";
        for (size_t m = 0; m < m_freeJoints.size(); ++m) {
            if (joints[m_freeJoints[m]].name == dipName) m_coupledJoints.push_back({int(k), int(m)});
        }
    }
    m_rotates = m_request.shape.type != contact::ContactShape::Type::Sphere;
    const int placement = m_rotates ? 6 : 3;
    for (int i = 0; i < placement; ++i) {
        const bool position = i < 3;
        m_start.push_back(0);
        m_lower.push_back(position ? -0.08 : -SimTK::Pi / 2);
        m_upper.push_back(position ? 0.08 : SimTK::Pi / 2);
        m_steps.push_back(position ? 0.005 : 0.1);
    }
}

SimTK::Vec3 GraspObjective::findThesisBallCentre() const {
    const model::BuildOptions thesisOptions = scenario::Scenario::makeDefaultBodyOptions();
    const ArmKinematics thesisArm(model::buildBodyModel(thesisOptions));
    std::vector<double> q(thesisArm.getModel().joints.size(), 0.0);
    for (const auto& [name, angle] : m_template.startPose) q[thesisArm.findJointIndex(name)] = angle;
    std::vector<SimTK::Transform> X_GB;
    thesisArm.calcBodyPoses(q, X_GB);
    const SimTK::Transform& X_GH0 = X_GB[thesisArm.findBodyIndex(thesisArm.getModel().findPalm().name)];
    const SimTK::Vec3 p_GO(m_template.ballPosition[0], m_template.ballPosition[1], m_template.ballPosition[2]);
    const double scale = model::calcHandLength(m_request.bodyOptions.subject) / model::calcHandLength(thesisOptions.subject);
    const SimTK::Vec3 p_HO = scale * (~X_GH0 * p_GO) + SimTK::Vec3(m_objectWidth / 2 - m_template.ballRadius, 0, 0);
    return m_X_GB[m_palm] * p_HO;  // x_H is palmar
}

void GraspObjective::placeObjectAtStart() {
    m_arm.calcBodyPoses(m_baseAngles, m_X_GB);
    std::vector<SimTK::Vec3> p;
    std::vector<SimTK::UnitVec3> n;
    for (const Pad& pad : m_pads) {
        p.push_back(m_X_GB[pad.body] * pad.p_BE);
        n.push_back(m_X_GB[pad.body].R() * pad.n_B);
    }
    const SimTK::Vec3 p_GC = m_template.startUnderPalm ? findThesisBallCentre() : findNormalsMeet(p, n);
    SimTK::Rotation R_GS(makeDiagonal(1), true);  // identity: a sphere's orientation does not matter
    const contact::ContactShape& shape = m_request.shape;
    const SimTK::Rotation& R_GH = m_X_GB[m_palm].R();
    if (shape.type == contact::ContactShape::Type::Capsule || shape.type == contact::ContactShape::Type::Cylinder) {
        // the long axis across the fingers, along the hand's radial axis z_H
        R_GS.setRotationFromOneAxis(R_GH.z(), SimTK::ZAxis);
    } else if (const SimTK::Vec3 halfExtents = findObjectExtents(shape).halfExtents; halfExtents != SimTK::Vec3(0)) {
        // thinnest axis along the squeeze (thumb pad to the other pads), longest out of the hand.
        // A mesh and an ellipsoid too: left unturned, a mesh of the phone started edge-on to the
        // pads and its optimum put both pads on edges, where a press along the edge normal goes
        // nowhere; a flat ellipsoid thin along y was refused (thumb pad 0.04 mm outside).
        SimTK::Vec3 others(0);
        for (size_t i = 1; i < p.size(); ++i) others += p[i] / double(p.size() - 1);
        const SimTK::UnitVec3 squeeze(others - p[0]);
        R_GS = alignThinnestWithSqueeze(halfExtents, squeeze, p_GC - m_X_GB[m_palm].p());
    }
    const SimTK::Transform X_GS(R_GS, p_GC);
    m_X_GO0 = X_GS * ~m_request.X_OS;
}

void GraspObjective::calcHandSpan(GraspType type) {
    // The open hand: fingers extended, thumb fully abducted. Span = thumb pad to the pad of the
    // finger that opposes it (index for precision grasps, little for power grasps).
    std::vector<double> open(m_arm.getModel().joints.size(), 0.0);
    const int abduction = m_arm.findJointIndex("thumb_cmc_abduction");
    open[abduction] = m_arm.getModel().joints[abduction].upper;
    m_arm.calcBodyPoses(open, m_X_GB);
    const bool power = type == GraspType::PowerSphere || type == GraspType::PowerCylinder;
    m_spanName = power ? "thumb-little" : "thumb-index";
    const Pad thumb = findPad(m_arm, "thumb_tip"), finger = findPad(m_arm, power ? "little_tip" : "index_tip");
    m_handSpan = (m_X_GB[thumb.body] * thumb.p_BE - m_X_GB[finger.body] * finger.p_BE).norm();
}

std::vector<double> GraspObjective::findJointAngles(const double* x) const {
    std::vector<double> q = m_baseAngles;
    for (size_t k = 0; k < m_freeJoints.size(); ++k) q[m_freeJoints[k]] = x[k];
    return q;
}

SimTK::Transform GraspObjective::findObjectPose(const double* x) const {
    const double* placement = x + m_freeJoints.size();
    SimTK::Transform X_GO = m_X_GO0;
    X_GO.updP() += SimTK::Vec3(placement[0], placement[1], placement[2]);
    if (m_rotates) {
        const SimTK::Vec3 w(placement[3], placement[4], placement[5]);
        if (w.norm() > 0) X_GO.updR() = SimTK::Rotation(w.norm(), SimTK::UnitVec3(w)) * X_GO.R();
    }
    return X_GO;
}

// The thumb must oppose the fingers: its surface normal against theirs (mean), and the line from
// its contact to theirs along its inward normal, so the squeeze lies inside the friction cones.
double GraspObjective::calcOppositionCost(const SimTK::Vec3& p_thumb, const SimTK::Vec3& n_thumb,
                                          const SimTK::Vec3& p_fingers, const SimTK::Vec3& n_fingers) const {
    const SimTK::Vec3 squeeze = p_fingers - p_thumb;
    const double length = squeeze.norm();
    const double offAxis = length > 0 ? (cross(squeeze / length, n_thumb)).normSqr() : 0;
    // The squeeze should pass near the centre of mass, so gravity twists the grasp little.
    const SimTK::Vec3 p_SO = ~m_request.X_OS * SimTK::Vec3(0);
    const double offCentre = ((p_thumb + p_fingers) / 2 - p_SO).norm() / kMillimetre;
    return kOppositionWeight * ((n_thumb + n_fingers).normSqr() + offAxis) + kCentreWeight * offCentre * offCentre;
}

// The pads together must not push the object along gravity (contacts above its equator, the
// fingers on top of a ball): the mean inward normal's component along gravity is penalized.
double GraspObjective::calcGravityCost(const SimTK::Transform& X_GS, const SimTK::Vec3& sumOutward_S) const {
    const double g = m_request.gravity.norm();
    if (g == 0) return 0;
    const SimTK::Vec3 down_S = ~X_GS.R() * (m_request.gravity / g);
    const double push = -dot(sumOutward_S, down_S) / double(m_pads.size());
    const double deficit = push + m_template.minSupport;  // > 0: less support than the template asks
    return deficit > 0 ? kGravityWeight * deficit * deficit : 0;
}

// Distal and proximal interphalangeal joints of a finger move together, DIP about 2/3 of PIP
// (tendon coupling), so the fingers curl as hands do.
double GraspObjective::calcCouplingCost(const double* x) const {
    double cost = 0;
    for (const auto& [pip, dip] : m_coupledJoints) {
        const double d = x[dip] - 2.0 / 3.0 * x[pip];
        cost += kCouplingWeight * d * d;
    }
    return cost;
}

double GraspObjective::evaluate(const double* x) {
    const std::vector<double> q = findJointAngles(x);
    m_arm.calcBodyPoses(q, m_X_GB);
    const SimTK::Transform X_GS = findObjectPose(x) * m_request.X_OS;
    double cost = 0;
    SimTK::Vec3 p_thumb(0), n_thumb(0), p_fingers(0), n_fingers(0);  // surface points and outward normals, in S
    for (size_t i = 0; i < m_pads.size(); ++i) {
        const Pad& pad = m_pads[i];
        const SimTK::Vec3 p_SE = ~X_GS * (m_X_GB[pad.body] * pad.p_BE);
        const contact::SurfacePoint surface = contact::findSurfacePoint(m_request.shape, p_SE);
        const SimTK::Vec3 n_S = ~X_GS.R() * (m_X_GB[pad.body].R() * pad.n_B);
        const double gapError = (surface.distance - m_targetGaps[i]) / kMillimetre;
        cost += gapError * gapError + kAlignWeight * (1 + dot(n_S, surface.n_S));
        const double share = i == 0 ? 1.0 : 1.0 / double(m_pads.size() - 1);
        (i == 0 ? p_thumb : p_fingers) += share * surface.p_SP;
        (i == 0 ? n_thumb : n_fingers) += share * SimTK::Vec3(surface.n_S);
    }
    cost += calcOppositionCost(p_thumb, n_thumb, p_fingers, n_fingers);
    cost += calcGravityCost(X_GS, n_thumb + double(m_pads.size() - 1) * n_fingers);
    cost += calcCouplingCost(x);
    cost += calcReleaseCost(q, X_GS);
    const auto& shapes = m_arm.getSegmentShapes();
    for (size_t i = 0; i < shapes.size(); ++i) {
        for (const contact::ContactPoint& c :
             contact::findContacts(m_inflated[i], m_X_GB[shapes[i].body] * shapes[i].X_BS, m_request.shape, X_GS)) {
            cost += kPenetrationWeight * (c.depth / kMillimetre) * (c.depth / kMillimetre);
        }
    }
    for (size_t k = 0; k < m_freeJoints.size(); ++k) {
        const double d = x[k] - m_start[k];
        cost += kStartWeight * d * d;
    }
    return cost;
}

// The controller's steady state, linearized at the planned pose: the IK moves the pad along the
// inward normal to the goal pressed pressDepth in (damped least squares over the digit's joints,
// as FingertipIk), each joint then settles where kp and its passive spring balance
// (goal_reach.h), and the capsule under the pad, which an oblique pad touches beside the pad
// point first, is that much deeper than it is now. The finger's stiffness along the normal is
// that of its joints (kp + spring) through the same Jacobian.
FingerPress GraspObjective::calcFingerPress(std::size_t i, const std::vector<double>& q,
                                            const std::vector<SimTK::Transform>& X_GB, const SimTK::Transform& X_GS) const {
    const Pad& pad = m_pads[i];
    const SimTK::Vec3 p_GE = X_GB[pad.body] * pad.p_BE;
    const contact::SurfacePoint surface = contact::findSurfacePoint(m_request.shape, ~X_GS * p_GE);
    const SimTK::Vec3 n_G = X_GS.R() * surface.n_S;  // outward
    const auto& joints = m_arm.getModel().joints;
    std::vector<SimTK::Vec3> columns;
    SimTK::Mat33 JJt = makeDiagonal(0);
    for (int j : pad.joints) {
        SimTK::Vec3 p_GJ, a_G;
        m_arm.findJointAxis(j, X_GB, p_GJ, a_G);
        columns.push_back(a_G % (p_GE - p_GJ));
        JJt += columns.back() * ~columns.back();
    }
    const double damping = 1e-8;  // m^2: keeps a straight finger's solve finite
    for (int k = 0; k < 3; ++k) JJt(k, k) += damping;
    const SimTK::Vec3 lambda = JJt.invert() * (-(surface.distance + m_request.pressDepth) * n_G);
    const double kp = m_template.kp;
    SimTK::Vec3 moved(0);
    double compliance = 0;
    for (std::size_t k = 0; k < pad.joints.size(); ++k) {
        const model::Joint& joint = joints[pad.joints[k]];
        const double toGoal = dot(columns[k], lambda);
        const double steady = (kp * (q[pad.joints[k]] + toGoal) + joint.stiffness * joint.restAngle) / (kp + joint.stiffness);
        moved += (steady - q[pad.joints[k]]) * columns[k];
        const double along = dot(columns[k], n_G);
        compliance += along * along / (kp + joint.stiffness);
    }
    const SegmentShape& capsule = m_arm.getSegmentShapes()[pad.capsule];
    const SimTK::Transform X_GC = X_GB[capsule.body] * capsule.X_BS;
    double capsuleDistance = SimTK::Infinity;
    for (int k = 0; k <= 8; ++k) {
        const SimTK::Vec3 p_GA = X_GC * SimTK::Vec3(0, 0, capsule.shape.length * (k / 8.0 - 0.5));
        capsuleDistance = std::min(capsuleDistance, contact::findSurfacePoint(m_request.shape, ~X_GS * p_GA).distance);
    }
    FingerPress press;
    press.p_GC = X_GS * surface.p_SP;
    press.n_G = -n_G;
    press.depth = capsule.shape.radius - capsuleDistance - dot(n_G, moved);
    press.stiffness = 1 / std::max(compliance, 1e-12);
    return press;
}

std::vector<double> GraspObjective::predictReleasedPress(const std::vector<double>& q, const std::vector<SimTK::Transform>& X_GB,
                                                         const SimTK::Transform& X_GS) const {
    std::vector<FingerPress> fingers;
    for (std::size_t i = 0; i < m_pads.size(); ++i) fingers.push_back(calcFingerPress(i, q, X_GB, X_GS));
    const SimTK::Vec3 p_GCm = X_GS * (~m_request.X_OS * SimTK::Vec3(0));  // O's origin: the centre of mass
    return calcPressAfterRelease(fingers, p_GCm, m_request.mass, m_request.gravity);
}

// Once the object is released and the fingers' forces have balanced its weight and one another,
// every goal finger must still press at least half the press depth (release_press.h). Only a
// grasp of three or more contacts: two opposed pads squeeze the object between them with one
// force, so neither can push it off the other (the press depth, findPressForWeakestFinger in
// grasp_planner.cpp, sees to how hard).
double GraspObjective::calcReleaseCost(const std::vector<double>& q, const SimTK::Transform& X_GS) const {
    if (!m_balanceRelease || m_pads.size() < 3) return 0;
    double cost = 0;
    const double least = m_request.pressDepth / 2;
    for (double press : predictReleasedPress(q, m_X_GB, X_GS)) {
        const double missing = std::max(0.0, least - press) / kMillimetre;
        cost += kReleaseWeight * missing * missing;
    }
    return cost;
}

std::vector<double> GraspObjective::calcReleasedPress(const std::map<std::string, double>& angles,
                                                      const SimTK::Transform& X_GO) const {
    std::vector<double> q(m_arm.getModel().joints.size(), 0.0);
    for (const auto& [name, angle] : angles) q[m_arm.findJointIndex(name)] = angle;
    return predictReleasedPress(q, calcBodyPoses(angles), X_GO * m_request.X_OS);
}

GraspPlan GraspObjective::makePlan(const double* x) const {
    GraspPlan plan;
    plan.type = m_request.type;
    const std::vector<double> q = findJointAngles(x);
    const auto& joints = m_arm.getModel().joints;
    for (size_t j = 0; j < joints.size(); ++j) {
        if (joints[j].getDofCount() > 0) plan.jointAngles[joints[j].name] = q[j];
    }
    plan.X_GO = findObjectPose(x);
    for (const Pad& pad : m_pads) plan.goalEffectors.push_back(pad.effector);
    return plan;
}

std::vector<double> GraspObjective::findVariables(const std::map<std::string, double>& angles,
                                                 const SimTK::Transform& X_GO) const {
    std::vector<double> x = m_start;
    const auto& joints = m_arm.getModel().joints;
    for (size_t k = 0; k < m_freeJoints.size(); ++k) {
        const auto angle = angles.find(joints[m_freeJoints[k]].name);
        if (angle != angles.end()) x[k] = angle->second;
    }
    // findObjectPose's inverse: X_GO = (R(w) R_GO0, p_GO0 + offset).
    double* placement = x.data() + m_freeJoints.size();
    const SimTK::Vec3 offset = X_GO.p() - m_X_GO0.p();
    for (int i = 0; i < 3; ++i) placement[i] = offset[i];
    if (m_rotates) {
        const SimTK::Vec4 angleAxis = (X_GO.R() * ~m_X_GO0.R()).convertRotationToAngleAxis();
        for (int i = 0; i < 3; ++i) placement[3 + i] = angleAxis[0] * angleAxis[1 + i];
    }
    for (size_t k = 0; k < x.size(); ++k) x[k] = std::clamp(x[k], m_lower[k], m_upper[k]);
    return x;
}

std::vector<SimTK::Transform> GraspObjective::calcBodyPoses(const std::map<std::string, double>& angles) const {
    std::vector<double> q(m_arm.getModel().joints.size(), 0.0);
    for (const auto& [name, angle] : angles) q[m_arm.findJointIndex(name)] = angle;
    std::vector<SimTK::Transform> X_GB;
    m_arm.calcBodyPoses(q, X_GB);
    return X_GB;
}

std::map<std::string, SimTK::Vec3> GraspObjective::findGoals(const std::map<std::string, double>& angles,
                                                             const SimTK::Transform& X_GO) const {
    const std::vector<SimTK::Transform> X_GB = calcBodyPoses(angles);
    const SimTK::Transform X_GS = X_GO * m_request.X_OS;
    std::map<std::string, SimTK::Vec3> goals;
    for (const Pad& pad : m_pads) {
        const SimTK::Vec3 p_SE = ~X_GS * (X_GB[pad.body] * pad.p_BE);
        SimTK::Vec3 p_OP = m_request.X_OS * contact::findSurfacePoint(m_request.shape, p_SE).p_SP;
        for (int i = 0; i < 3; ++i) p_OP[i] = std::round(p_OP[i] / 1e-4) * 1e-4;
        goals[pad.effector] = p_OP;
    }
    return goals;
}

double GraspObjective::calcEffectorBodyDepth(const std::map<std::string, double>& angles, const SimTK::Transform& X_GO,
                                             const std::string& effector) const {
    const std::vector<SimTK::Transform> X_GB = calcBodyPoses(angles);
    const SimTK::Transform X_GS = X_GO * m_request.X_OS;
    const int body = findPad(m_arm, effector).body;
    double depth = 0;
    for (const SegmentShape& s : m_arm.getSegmentShapes()) {
        if (s.body != body) continue;
        for (const contact::ContactPoint& c : contact::findContacts(s.shape, X_GB[s.body] * s.X_BS, m_request.shape, X_GS)) {
            depth = std::max(depth, c.depth);
        }
    }
    return depth;
}

PlanDiagnostics GraspObjective::calcDiagnostics(const std::map<std::string, double>& angles,
                                                const SimTK::Transform& X_GO) const {
    const std::vector<SimTK::Transform> X_GB = calcBodyPoses(angles);
    const SimTK::Transform X_GS = X_GO * m_request.X_OS;
    PlanDiagnostics d;
    d.objectWidth = m_objectWidth;
    d.handSpan = m_handSpan;
    std::vector<grasp::GraspContact> contacts;
    for (const Pad& pad : m_pads) {
        const SimTK::Vec3 p_SE = ~X_GS * (X_GB[pad.body] * pad.p_BE);
        const contact::SurfacePoint surface = contact::findSurfacePoint(m_request.shape, p_SE);
        const SimTK::Vec3 n_S = ~X_GS.R() * (X_GB[pad.body].R() * pad.n_B);
        const double facing = std::clamp(-dot(n_S, surface.n_S), -1.0, 1.0);
        d.goals.push_back({pad.effector, surface.distance, std::acos(facing)});
        grasp::GraspContact c;
        const SimTK::Vec3 p_GC = X_GS * surface.p_SP, n_G = -(X_GS.R() * surface.n_S);
        c.p_GC = Eigen::Vector3d(p_GC[0], p_GC[1], p_GC[2]);
        c.n_G = Eigen::Vector3d(n_G[0], n_G[1], n_G[2]);
        contacts.push_back(c);
    }
    const auto& shapes = m_arm.getSegmentShapes();
    for (const SegmentShape& s : shapes) {
        for (const contact::ContactPoint& c :
             contact::findContacts(s.shape, X_GB[s.body] * s.X_BS, m_request.shape, X_GS)) {
            if (c.depth > d.maxPenetration) {
                d.maxPenetration = c.depth;
                d.deepestSegment = s.name;
            }
        }
    }
    grasp::ObjectFrame frame;
    for (int i = 0; i < 3; ++i) {
        frame.p_GO[i] = X_GO.p()[i];
        for (int k = 0; k < 3; ++k) frame.R_GO(i, k) = X_GO.R()[i][k];
    }
    grasp::QualityOptions options;
    options.mu = kFriction;
    d.quality = grasp::calcGraspQuality(contacts, frame, options);
    if (contacts.size() == 2) checkAntipodal(contacts[0], contacts[1], d);
    return d;
}

}  // namespace graspsim::planning
