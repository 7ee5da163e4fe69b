#include "graspsim/contact/rigid_contact_constraint.h"

#include "graspsim/error.h"

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
    m_geometryIndex = getMatterSubsystem().allocateLazyCacheEntry(
        state, SimTK::Stage::Position, new SimTK::Value<RigidContactGeometry>());
}

const RigidContactGeometry& RigidContactConstraint::findGeometryFromState(
    const SimTK::State& state) const {
    const SimTK::SimbodyMatterSubsystem& matter = getMatterSubsystem();
    auto& cached = SimTK::Value<RigidContactGeometry>::updDowncast(matter.updCacheEntry(state, m_geometryIndex));
    if (!matter.isCacheValueRealized(state, m_geometryIndex)) {
        cached.upd() = findGeometry(getBodyTransformFromState(state, m_bodyA),
                                    getBodyTransformFromState(state, m_bodyB));
        matter.markCacheValueRealized(state, m_geometryIndex);
    }
    return cached.get();
}

Vec3 RigidContactConstraint::findSlipVelocity(const SimTK::State& state,
                                              const Array_<SpatialVec, ConstrainedBodyIndex>& V_AB,
                                              const Vec3& p) const {
    const Vec3 p_A = ~getBodyTransformFromState(state, m_bodyA) * p;  // station on A at P
    const Vec3 p_B = ~getBodyTransformFromState(state, m_bodyB) * p;  // station on B at P
    return findStationVelocity(state, V_AB, m_bodyB, p_B) -
           findStationVelocity(state, V_AB, m_bodyA, p_A);
}

Vec3 RigidContactConstraint::findRelativeAcceleration(
    const SimTK::State& state, const Array_<SpatialVec, ConstrainedBodyIndex>& A_AB,
    const Vec3& p) const {
    const Vec3 p_A = ~getBodyTransformFromState(state, m_bodyA) * p;
    const Vec3 p_B = ~getBodyTransformFromState(state, m_bodyB) * p;
    const Vec3 v = findStationVelocityFromState(state, m_bodyB, p_B) -
                   findStationVelocityFromState(state, m_bodyA, p_A);
    const Vec3& w_A = getBodyAngularVelocityFromState(state, m_bodyA);
    return findStationAcceleration(state, A_AB, m_bodyB, p_B) -
           findStationAcceleration(state, A_AB, m_bodyA, p_A) - 2 * (w_A % v);
}

void RigidContactConstraint::addInContactForce(
    const SimTK::State& state, const Vec3& p, const Vec3& f,
    Array_<SpatialVec, ConstrainedBodyIndex>& bodyForcesInA) const {
    const Vec3 p_A = ~getBodyTransformFromState(state, m_bodyA) * p;
    const Vec3 p_B = ~getBodyTransformFromState(state, m_bodyB) * p;
    addInStationForce(state, m_bodyB, p_B, f, bodyForcesInA);
    addInStationForce(state, m_bodyA, p_A, -f, bodyForcesInA);
}

void RigidContactConstraint::calcPositionErrors(
    const SimTK::State&, const Array_<Transform, ConstrainedBodyIndex>& X_AB,
    const Array_<SimTK::Real, SimTK::ConstrainedQIndex>&, Array_<SimTK::Real>& perr) const {
    perr[0] = findGeometry(X_AB[m_bodyA], X_AB[m_bodyB]).separation;
}

void RigidContactConstraint::calcPositionDotErrors(
    const SimTK::State& state, const Array_<SpatialVec, ConstrainedBodyIndex>& V_AB,
    const Array_<SimTK::Real, SimTK::ConstrainedQIndex>&, Array_<SimTK::Real>& pverr) const {
    const RigidContactGeometry& g = findGeometryFromState(state);
    pverr[0] = ~g.n_F * findSlipVelocity(state, V_AB, g.p_F);
}

void RigidContactConstraint::calcPositionDotDotErrors(
    const SimTK::State& state, const Array_<SpatialVec, ConstrainedBodyIndex>& A_AB,
    const Array_<SimTK::Real, SimTK::ConstrainedQIndex>&, Array_<SimTK::Real>& paerr) const {
    const RigidContactGeometry& g = findGeometryFromState(state);
    paerr[0] = ~g.n_F * findRelativeAcceleration(state, A_AB, g.p_F);
}

void RigidContactConstraint::addInPositionConstraintForces(
    const SimTK::State& state, const Array_<SimTK::Real>& multipliers,
    Array_<SpatialVec, ConstrainedBodyIndex>& bodyForcesInA,
    Array_<SimTK::Real, SimTK::ConstrainedQIndex>&) const {
    const RigidContactGeometry& g = findGeometryFromState(state);
    addInContactForce(state, g.p_F, multipliers[0] * Vec3(g.n_F), bodyForcesInA);
}

void RigidContactConstraint::calcVelocityErrors(
    const SimTK::State& state, const Array_<SpatialVec, ConstrainedBodyIndex>& V_AB,
    const Array_<SimTK::Real, SimTK::ConstrainedUIndex>&, Array_<SimTK::Real>& verr) const {
    const RigidContactGeometry& g = findGeometryFromState(state);
    const auto [tx, ty] = findFrictionDirections(g.n_F);
    const Vec3 v = findSlipVelocity(state, V_AB, g.p_F);
    verr[0] = ~tx * v;
    verr[1] = ~ty * v;
}

void RigidContactConstraint::calcVelocityDotErrors(
    const SimTK::State& state, const Array_<SpatialVec, ConstrainedBodyIndex>& A_AB,
    const Array_<SimTK::Real, SimTK::ConstrainedUIndex>&, Array_<SimTK::Real>& vaerr) const {
    const RigidContactGeometry& g = findGeometryFromState(state);
    const auto [tx, ty] = findFrictionDirections(g.n_F);
    const Vec3 a = findRelativeAcceleration(state, A_AB, g.p_F);
    vaerr[0] = ~tx * a;
    vaerr[1] = ~ty * a;
}

void RigidContactConstraint::addInVelocityConstraintForces(
    const SimTK::State& state, const Array_<SimTK::Real>& multipliers,
    Array_<SpatialVec, ConstrainedBodyIndex>& bodyForcesInA,
    Array_<SimTK::Real, SimTK::ConstrainedUIndex>&) const {
    const RigidContactGeometry& g = findGeometryFromState(state);
    const auto [tx, ty] = findFrictionDirections(g.n_F);
    addInContactForce(state, g.p_F, multipliers[0] * tx + multipliers[1] * ty, bodyForcesInA);
}

}  // namespace graspsim::contact
