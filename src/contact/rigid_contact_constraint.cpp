#include "graspsim/contact/rigid_contact_constraint.h"

#include "graspsim/error.h"

#include <tuple>
#include <utility>

namespace graspsim::contact {

using SimTK::Array_;
using SimTK::ConstrainedBodyIndex;
using SimTK::SpatialVec;
using SimTK::Transform;
using SimTK::Vec3;

namespace {

// The two friction directions; the velocity errors, their derivatives and the applied forces
// must all use this one basis, or the friction multipliers would act along other directions.
std::pair<Vec3, Vec3> findFrictionDirections(const SimTK::UnitVec3& n_F) {
    const SimTK::UnitVec3 tx = n_F.perp();
    return {Vec3(tx), n_F % tx};
}

}  // namespace

RigidContactConstraint::RigidContactConstraint(SimTK::SimbodyMatterSubsystem& matter,
                                               const SimTK::MobilizedBody& bodyA,
                                               const ContactShape& shapeA, const Transform& X_BS_A,
                                               const SimTK::MobilizedBody& bodyB,
                                               const ContactShape& shapeB, const Transform& X_BS_B,
                                               double searchMargin)
    : Implementation(matter, 1, 2, 0),
      m_shapeA(shapeA),
      m_shapeB(shapeB),
      m_X_BS_A(X_BS_A),
      m_X_BS_B(X_BS_B),
      m_searchMargin(searchMargin) {
    if (!isRigidContactSupported(shapeA, shapeB))
        throw InputError(
            "rigid contact: the pair needs a sphere or a capsule on at least one side "
            "(box-box and box-half-space pairs are not supported by the rigid model)");
    if (bodyA.getMobilizedBodyIndex() == bodyB.getMobilizedBodyIndex())
        throw InputError("rigid contact: both shapes are on the same body");
    m_bodyA = addConstrainedBody(bodyA);
    m_bodyB = addConstrainedBody(bodyB);
}

RigidContactGeometry RigidContactConstraint::findGeometry(const Transform& X_FA,
                                                          const Transform& X_FB) const {
    return findRigidContactGeometry(m_shapeA, X_FA * m_X_BS_A, m_shapeB, X_FB * m_X_BS_B,
                                    m_searchMargin);
}

void RigidContactConstraint::realizeTopology(SimTK::State& state) const {
    const SimTK::SimbodyMatterSubsystem& matter = getMatterSubsystem();
    m_matter = &matter;
    m_poseIndex = matter.allocateLazyCacheEntry(state, SimTK::Stage::Position, new SimTK::Value<PoseTerms>());
    m_velocityIndex = matter.allocateLazyCacheEntry(state, SimTK::Stage::Velocity, new SimTK::Value<VelocityTerms>());
}

// The stations re-expressed in A (R_AX p_X) are what Simbody's findStationVelocity(),
// findStationAcceleration() and addInStationForce() compute first; keeping them, and their
// expressions below, gives the same numbers.
RigidContactConstraint::PoseTerms RigidContactConstraint::calcPoseTerms(const SimTK::State& state) const {
    const Transform& X_AA = getBodyTransformFromState(state, m_bodyA);  // body A's frame in ancestor A
    const Transform& X_AB = getBodyTransformFromState(state, m_bodyB);
    PoseTerms pose;
    pose.geometry = findGeometry(X_AA, X_AB);
    std::tie(pose.tx, pose.ty) = findFrictionDirections(pose.geometry.n_F);
    pose.r_A = X_AA.R() * (~X_AA * pose.geometry.p_F);
    pose.r_B = X_AB.R() * (~X_AB * pose.geometry.p_F);
    return pose;
}

RigidContactConstraint::VelocityTerms RigidContactConstraint::calcVelocityTerms(const SimTK::State& state) const {
    const PoseTerms& pose = findPoseTerms(state);
    const SpatialVec& V_A = getBodyVelocityFromState(state, m_bodyA);
    const SpatialVec& V_B = getBodyVelocityFromState(state, m_bodyB);
    const Vec3 v = (V_B[1] + (V_B[0] % pose.r_B)) - (V_A[1] + (V_A[0] % pose.r_A));
    VelocityTerms terms;
    terms.centripetal_A = V_A[0] % (V_A[0] % pose.r_A);  // % is not associative
    terms.centripetal_B = V_B[0] % (V_B[0] % pose.r_B);
    terms.coriolis = 2 * (V_A[0] % v);
    return terms;
}

const RigidContactConstraint::PoseTerms& RigidContactConstraint::findPoseTerms(const SimTK::State& state) const {
    // The entry is ours (realizeTopology()): a static cast, and the subsystem kept from there,
    // spare the dynamic casts of Value::updDowncast() and getMatterSubsystem(), which cost more
    // than the lookup itself at one call per constraint row and G M^-1 G^T column.
    auto& cached = static_cast<SimTK::Value<PoseTerms>&>(m_matter->updCacheEntry(state, m_poseIndex));
    if (!m_matter->isCacheValueRealized(state, m_poseIndex)) {
        cached.upd() = calcPoseTerms(state);
        m_matter->markCacheValueRealized(state, m_poseIndex);
    }
    return cached.get();
}

const RigidContactConstraint::VelocityTerms& RigidContactConstraint::findVelocityTerms(const SimTK::State& state) const {
    // The entry is ours (realizeTopology()): a static cast, and the subsystem kept from there,
    // spare the dynamic casts of Value::updDowncast() and getMatterSubsystem(), which cost more
    // than the lookup itself at one call per constraint row and G M^-1 G^T column.
    auto& cached = static_cast<SimTK::Value<VelocityTerms>&>(m_matter->updCacheEntry(state, m_velocityIndex));
    if (!m_matter->isCacheValueRealized(state, m_velocityIndex)) {
        cached.upd() = calcVelocityTerms(state);
        m_matter->markCacheValueRealized(state, m_velocityIndex);
    }
    return cached.get();
}

Vec3 RigidContactConstraint::findSlipVelocity(const PoseTerms& pose,
                                              const Array_<SpatialVec, ConstrainedBodyIndex>& V_AB) const {
    const SpatialVec& V_A = V_AB[m_bodyA];
    const SpatialVec& V_B = V_AB[m_bodyB];
    return (V_B[1] + (V_B[0] % pose.r_B)) - (V_A[1] + (V_A[0] % pose.r_A));
}

Vec3 RigidContactConstraint::findRelativeAcceleration(const SimTK::State& state, const PoseTerms& pose,
                                                      const Array_<SpatialVec, ConstrainedBodyIndex>& A_AB) const {
    const VelocityTerms& terms = findVelocityTerms(state);
    const SpatialVec& A_A = A_AB[m_bodyA];
    const SpatialVec& A_B = A_AB[m_bodyB];
    const Vec3 a_B = A_B[1] + (A_B[0] % pose.r_B) + terms.centripetal_B;
    const Vec3 a_A = A_A[1] + (A_A[0] % pose.r_A) + terms.centripetal_A;
    return a_B - a_A - terms.coriolis;
}

void RigidContactConstraint::addInContactForce(const PoseTerms& pose, const Vec3& f,
                                               Array_<SpatialVec, ConstrainedBodyIndex>& bodyForcesInA) const {
    const Vec3 minusF = -f;
    bodyForcesInA[m_bodyB] += SpatialVec(pose.r_B % f, f);
    bodyForcesInA[m_bodyA] += SpatialVec(pose.r_A % minusF, minusF);
}

void RigidContactConstraint::calcPositionErrors(
    const SimTK::State&, const Array_<Transform, ConstrainedBodyIndex>& X_AB,
    const Array_<SimTK::Real, SimTK::ConstrainedQIndex>&, Array_<SimTK::Real>& perr) const {
    perr[0] = findGeometry(X_AB[m_bodyA], X_AB[m_bodyB]).separation;
}

void RigidContactConstraint::calcPositionDotErrors(
    const SimTK::State& state, const Array_<SpatialVec, ConstrainedBodyIndex>& V_AB,
    const Array_<SimTK::Real, SimTK::ConstrainedQIndex>&, Array_<SimTK::Real>& pverr) const {
    const PoseTerms& pose = findPoseTerms(state);
    pverr[0] = ~pose.geometry.n_F * findSlipVelocity(pose, V_AB);
}

void RigidContactConstraint::calcPositionDotDotErrors(
    const SimTK::State& state, const Array_<SpatialVec, ConstrainedBodyIndex>& A_AB,
    const Array_<SimTK::Real, SimTK::ConstrainedQIndex>&, Array_<SimTK::Real>& paerr) const {
    const PoseTerms& pose = findPoseTerms(state);
    paerr[0] = ~pose.geometry.n_F * findRelativeAcceleration(state, pose, A_AB);
}

void RigidContactConstraint::addInPositionConstraintForces(
    const SimTK::State& state, const Array_<SimTK::Real>& multipliers,
    Array_<SpatialVec, ConstrainedBodyIndex>& bodyForcesInA,
    Array_<SimTK::Real, SimTK::ConstrainedQIndex>&) const {
    const PoseTerms& pose = findPoseTerms(state);
    addInContactForce(pose, multipliers[0] * Vec3(pose.geometry.n_F), bodyForcesInA);
}

void RigidContactConstraint::calcVelocityErrors(
    const SimTK::State& state, const Array_<SpatialVec, ConstrainedBodyIndex>& V_AB,
    const Array_<SimTK::Real, SimTK::ConstrainedUIndex>&, Array_<SimTK::Real>& verr) const {
    const PoseTerms& pose = findPoseTerms(state);
    const Vec3 v = findSlipVelocity(pose, V_AB);
    verr[0] = ~pose.tx * v;
    verr[1] = ~pose.ty * v;
}

void RigidContactConstraint::calcVelocityDotErrors(
    const SimTK::State& state, const Array_<SpatialVec, ConstrainedBodyIndex>& A_AB,
    const Array_<SimTK::Real, SimTK::ConstrainedUIndex>&, Array_<SimTK::Real>& vaerr) const {
    const PoseTerms& pose = findPoseTerms(state);
    const Vec3 a = findRelativeAcceleration(state, pose, A_AB);
    vaerr[0] = ~pose.tx * a;
    vaerr[1] = ~pose.ty * a;
}

void RigidContactConstraint::addInVelocityConstraintForces(
    const SimTK::State& state, const Array_<SimTK::Real>& multipliers,
    Array_<SpatialVec, ConstrainedBodyIndex>& bodyForcesInA,
    Array_<SimTK::Real, SimTK::ConstrainedUIndex>&) const {
    const PoseTerms& pose = findPoseTerms(state);
    addInContactForce(pose, multipliers[0] * pose.tx + multipliers[1] * pose.ty, bodyForcesInA);
}

}  // namespace graspsim::contact
