#include "graspsim/simulation/finger_compliance.h"

#include "graspsim/simulation/approximation_context.h"

#include "graspsim/error.h"
#include "graspsim/model/model_description.h"
#include "graspsim/simulation/grasp_scene.h"
#include "graspsim/system/simtk_conversion.h"

#include <Eigen/Dense>

#include <algorithm>
#include <utility>

namespace graspsim::simulation {

FingerCompliance::FingerCompliance(const system::MultibodyModel& model, std::vector<SimTK::MobilizedBodyIndex> fingerMobilizers,
                                   std::vector<system::JointImpedance> jointImpedances, std::vector<std::string> goalEndEffectors)
    : model_(model), fingerMobilizers_(std::move(fingerMobilizers)), jointImpedances_(std::move(jointImpedances)),
      goalEndEffectors_(std::move(goalEndEffectors)) {}

// Columns of the station Jacobian of `body`'s material point at p_G over the finger mobilizers
// (3 x n, in G).
Eigen::MatrixXd FingerCompliance::calcJacobian(const SimTK::State& state, const std::string& body, const SimTK::Vec3& p_G) const {
    const SimTK::SimbodyMatterSubsystem& matter = model_.getMatter();
    const SimTK::MobilizedBody& segment = model_.getMobilizedBody(body);
    SimTK::Matrix J;
    matter.calcStationJacobian(state, segment.getMobilizedBodyIndex(), segment.findStationAtGroundPoint(state, p_G), J);
    Eigen::MatrixXd columns(3, fingerMobilizers_.size());
    for (std::size_t k = 0; k < fingerMobilizers_.size(); ++k) {
        const int u = int(matter.getMobilizedBody(fingerMobilizers_[k]).getFirstUIndex(state));
        columns.col(Eigen::Index(k)) << J(0, u), J(1, u), J(2, u);
    }
    return columns;
}

// The PD gains' joint stiffness where the IK follows the finger in its null space: kp J_E^+ J_E
// over each goal end-effector's chain (file comment).
Eigen::MatrixXd FingerCompliance::calcFollowedPdStiffness(const SimTK::State& state, const Eigen::VectorXd& kp) const {
    const model::ModelDescription& d = model_.getDescription();
    Eigen::MatrixXd stiffness = Eigen::MatrixXd::Zero(kp.size(), kp.size());
    Eigen::VectorXd covered = Eigen::VectorXd::Zero(kp.size());
    for (const std::string& name : goalEndEffectors_) {
        const model::EndEffector& e = *d.findEndEffector(name);
        const SimTK::MobilizedBody& body = model_.getMobilizedBody(e.body);
        const SimTK::Vec3 p_G = body.findStationLocationInGround(state, SimTK::Vec3(e.p_BE[0], e.p_BE[1], e.p_BE[2]));
        const Eigen::MatrixXd J = calcJacobian(state, e.body, p_G);
        const Eigen::MatrixXd projector = J.completeOrthogonalDecomposition().pseudoInverse() * J;
        const Eigen::VectorXd root = kp.cwiseSqrt();
        stiffness += root.asDiagonal() * projector * root.asDiagonal();
        for (Eigen::Index k = 0; k < J.cols(); ++k) covered[k] += J.col(k).norm() > 0 ? 1 : 0;
    }
    for (Eigen::Index k = 0; k < kp.size(); ++k) {
        if (covered[k] == 0) stiffness(k, k) += kp[k];  // a finger without a goal: plain PD
    }
    return stiffness;
}

Eigen::MatrixXd FingerCompliance::calcJointStiffness(const SimTK::State& state, bool ikFollowsNullSpace) const {
    model_.getSystem().realize(state, SimTK::Stage::Position);
    const model::ModelDescription& d = model_.getDescription();
    const Eigen::Index n = Eigen::Index(fingerMobilizers_.size());
    Eigen::VectorXd kp = Eigen::VectorXd::Zero(n), passive = Eigen::VectorXd::Zero(n);
    for (const system::JointImpedance& j : jointImpedances_) {
        const auto it = std::find(fingerMobilizers_.begin(), fingerMobilizers_.end(), j.mobod);
        if (it == fingerMobilizers_.end()) continue;
        const Eigen::Index k = Eigen::Index(it - fingerMobilizers_.begin());
        const SimTK::MobilizedBody& mobod = model_.getMatter().getMobilizedBody(j.mobod);
        for (const model::Joint& joint : d.joints) {
            if (model_.getMobilizedBody(joint.child).getMobilizedBodyIndex() == j.mobod) passive[k] = joint.stiffness;
        }
        kp[k] = j.stiffness - passive[k];
        const double q = mobod.getOneQ(state, 0);
        if (!j.stop.isEmptyHandle() && (q < j.stop.getLowerBound(state) || q > j.stop.getUpperBound(state))) {
            passive[k] += j.stop.getStiffness(state);
        }
    }
    Eigen::MatrixXd pd = ikFollowsNullSpace ? calcFollowedPdStiffness(state, kp) : Eigen::MatrixXd(kp.asDiagonal());
    return pd + Eigen::MatrixXd(passive.asDiagonal());
}

Eigen::Matrix3d FingerCompliance::calcCompliance(const SimTK::State& state, const Eigen::MatrixXd& jointStiffness,
                                                 const std::string& body, const SimTK::Vec3& p_G) const {
    model_.getSystem().realize(state, SimTK::Stage::Position);
    const Eigen::MatrixXd J = calcJacobian(state, body, p_G);
    return J * jointStiffness.ldlt().solve(J.transpose());
}

Eigen::VectorXd FingerCompliance::calcJointDeflection(const SimTK::State& state, const Eigen::MatrixXd& jointStiffness,
                                                      const std::vector<std::string>& bodies, const std::vector<SimTK::Vec3>& points_G,
                                                      const std::vector<Eigen::Vector3d>& forceChanges_G) const {
    if (bodies.size() != points_G.size() || bodies.size() != forceChanges_G.size()) {
        throw InputError("finger joint deflection: " + std::to_string(bodies.size()) + " bodies, " + std::to_string(points_G.size()) +
                         " points and " + std::to_string(forceChanges_G.size()) + " force changes; they must be as many");
    }
    model_.getSystem().realize(state, SimTK::Stage::Position);
    Eigen::VectorXd torque = Eigen::VectorXd::Zero(Eigen::Index(fingerMobilizers_.size()));
    for (std::size_t i = 0; i < bodies.size(); ++i) torque -= calcJacobian(state, bodies[i], points_G[i]).transpose() * forceChanges_G[i];
    return jointStiffness.ldlt().solve(torque);
}

namespace {

// 1 / the radius of a sphere's or capsule's surface; 0 for the other shapes (a box's faces are
// flat) and for a shape the model does not list.
double findPadCurvature(const model::ModelDescription& d, const std::string& body, const std::string& shape) {
    const model::Body* b = d.findBody(body);
    if (!b) return 0;
    for (const model::Geometry& g : b->geometry) {
        const bool round = g.type == model::Geometry::Type::Sphere || g.type == model::Geometry::Type::Capsule;
        if (g.name == shape && round && g.radius > 0) return 1 / g.radius;
    }
    return 0;
}

// The pad's and the object's curvatures (1/m): the object's is what the effective Hertz radius
// 1/R = k_pad + k_object leaves (0 where R is unknown or the pad alone accounts for it).
void setCurvatures(const model::ModelDescription& d, const contact::ContactReport& r, grasp::CompliantContact& c) {
    c.fingerCurvature = findPadCurvature(d, r.bodyA, r.shapeA);
    c.objectCurvature = r.radius > 0 ? std::max(0.0, 1 / r.radius - c.fingerCurvature) : 0.0;
    if (c.objectCurvature < 1e-9 * c.fingerCurvature) c.objectCurvature = 0;
}

}  // namespace

std::vector<grasp::CompliantContact> FingerCompliance::findCompliantContacts(const SimTK::State& state,
                                                                             const std::vector<contact::ContactReport>& reports,
                                                                             const FingerComplianceSettings& settings) const {
    model_.getSystem().realize(state, SimTK::Stage::Velocity);
    const Eigen::MatrixXd jointStiffness = calcJointStiffness(state, settings.ikFollowsNullSpace);
    std::vector<grasp::CompliantContact> contacts;
    for (const contact::ContactReport& r : reports) {
        std::optional<grasp::CompliantContact> c = findPressingContact(r, settings);
        if (!c) continue;
        c->fingerCompliance_G = calcCompliance(state, jointStiffness, r.bodyA, r.p_G);
        if (settings.rolling) setCurvatures(model_.getDescription(), r, *c);
        contacts.push_back(*c);
    }
    if (settings.tangentialByNormalForce) grasp::setTangentialStiffnessByNormalForce(contacts);
    return contacts;
}

std::optional<grasp::CompliantContact> findPressingContact(const contact::ContactReport& r, const FingerComplianceSettings& settings) {
    if (!(r.normalForce > 0) || !(r.depth > 0)) return std::nullopt;
    grasp::CompliantContact c;
    c.p_GC = system::toEigenVector(r.p_G);
    c.n_G = system::toEigenVector(SimTK::Vec3(r.n_G));
    c.force_G = r.normalForce * c.n_G + system::toEigenVector(r.frictionForce_G);
    c.normalStiffness = 1.5 * r.normalForce / r.depth;
    c.tangentialStiffness = settings.tangentialStiffnessRatio * c.normalStiffness;
    return c;
}

FingerCompliance makeFingerCompliance(const GraspScene& scene) {
    return FingerCompliance(scene.getModel(), scene.getFingerMobilizers(), scene.findJointImpedances(), scene.getGoalEndEffectors());
}

FingerCompliance makeFingerCompliance(const ApproximationContext& context) {
    return FingerCompliance(context.model, context.fingerMobilizers, context.jointImpedances, context.goals.getEndEffectors());
}

}  // namespace graspsim::simulation
