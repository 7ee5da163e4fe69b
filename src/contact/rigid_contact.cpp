#include "graspsim/contact/rigid_contact.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "graspsim/contact/rigid_contact_constraint.h"
#include "graspsim/error.h"

namespace graspsim::contact {
namespace {

[[noreturn]] void throwBadField(const std::string& source, const char* field, double value,
                                const char* accepted) {
    std::ostringstream message;
    message << source << ": " << field << " (" << value << ") must be " << accepted;
    throw InputError(message.str());
}

// Distance (m) from point p_G to the solid box of half-lengths h centred on S's origin, posed
// at X_GS; 0 inside.
double findDistanceToBox(const SimTK::Transform& X_GS, const SimTK::Vec3& h, const SimTK::Vec3& p_G) {
    const SimTK::Vec3 p_S = ~X_GS * p_G;
    SimTK::Vec3 outside;
    for (int i = 0; i < 3; ++i) outside[i] = std::max(0.0, std::abs(p_S[i]) - h[i]);
    return outside.norm();
}

}  // namespace

void RigidContactOptions::validate(const std::string& source) const {
    if (!(minRestitution >= 0 && minRestitution <= 1))
        throwBadField(source, "minRestitution", minRestitution, "in [0, 1]");
    if (!(std::isfinite(searchMargin) && searchMargin > 0))
        throwBadField(source, "searchMargin", searchMargin, "finite and > 0 m");
}

RigidContact::RigidContact(SimTK::SimbodyMatterSubsystem& matter, const ContactPair& pair,
                           const RigidContactOptions& options)
    : UnilateralContact(1), m_a(pair.a), m_b(pair.b), m_parameters(pair.parameters), m_options(options) {
    const std::string name = "rigid contact " + pair.describe();
    pair.parameters.validate(name);
    options.validate(name);
    const ContactSurface& a = pair.a;
    const ContactSurface& b = pair.b;
    a.shape.validate(name + " shape A");
    b.shape.validate(name + " shape B");
    if (!isRigidContactSupported(a.shape, b.shape))
        throw InputError(name +
                         ": the pair needs a sphere or a capsule on at least one side (box-box "
                         "and box-half-space pairs are not supported by the rigid model)");
    m_constraint = SimTK::Constraint::Custom(new RigidContactConstraint(
        matter, a.body, a.shape, a.X_BS, b.body, b.shape, b.X_BS, options.searchMargin));
    m_constraint.setIsConditional(true);
    m_constraint.setDisabledByDefault(true);
}

SimTK::UnilateralContactIndex RigidContact::add(SimTK::SimbodyMatterSubsystem& matter,
                                                const ContactPair& pair,
                                                const RigidContactOptions& options) {
    return matter.adoptUnilateralContact(new RigidContact(matter, pair, options));
}

RigidContactGeometry RigidContact::findGeometryInGround(const SimTK::State& state) const {
    return findRigidContactGeometry(m_a.shape, m_a.body.getBodyTransform(state) * m_a.X_BS,
                                    m_b.shape, m_b.body.getBodyTransform(state) * m_b.X_BS,
                                    m_options.searchMargin);
}

SimTK::Vec3 RigidContact::findSlipVelocityInGround(const SimTK::State& state,
                                                   RigidContactGeometry& geometry) const {
    geometry = findGeometryInGround(state);
    return m_b.body.findStationVelocityInGround(
               state, m_b.body.findStationAtGroundPoint(state, geometry.p_F)) -
           m_a.body.findStationVelocityInGround(
               state, m_a.body.findStationAtGroundPoint(state, geometry.p_F));
}

bool RigidContact::disable(SimTK::State& state) const {
    if (m_constraint.isDisabled(state)) return false;
    m_constraint.disable(state);
    return true;
}

bool RigidContact::enable(SimTK::State& state) const {
    if (!m_constraint.isDisabled(state)) return false;
    m_constraint.enable(state);
    return true;
}

bool RigidContact::isEnabled(const SimTK::State& state) const {
    return !m_constraint.isDisabled(state);
}

SimTK::Vec3 RigidContact::whereToDisplay(const SimTK::State& state) const {
    return findGeometryInGround(state).p_F;
}

SimTK::Real RigidContact::calcEffectiveCOR(const SimTK::State&, SimTK::Real defaultCaptureSpeed,
                                           SimTK::Real defaultMinCORSpeed,
                                           SimTK::Real impactSpeed) const {
    return SimTK::ConditionalConstraint::calcEffectiveCOR(
        m_options.minRestitution, defaultCaptureSpeed, defaultMinCORSpeed, impactSpeed);
}

SimTK::Real RigidContact::getPerr(const SimTK::State& state) const {
    return findGeometryInGround(state).separation;
}

// The stepper asks every pair at every step, and most are far apart: the bound costs a fraction
// of the exact search. The slack keeps rounding in the bound from ever deciding a pair near ptol.
bool RigidContact::isProximal(const SimTK::State& state, SimTK::Real ptol) const {
    constexpr double kBoundSlack = 1e-6;  // m
    if (findGapLowerBound(state) > ptol + kBoundSlack) return false;
    return SimTK::UnilateralContact::isProximal(state, ptol);
}

// A box's rounded corners lie inside its half-lengths, and every shape inside its bounding sphere.
double RigidContact::findGapLowerBound(const SimTK::State& state) const {
    const SimTK::Transform X_GA = m_a.body.getBodyTransform(state) * m_a.X_BS;
    const SimTK::Transform X_GB = m_b.body.getBodyTransform(state) * m_b.X_BS;
    if (m_a.shape.type == ContactShape::Type::Box)
        return findDistanceToBox(X_GA, m_a.shape.halfLengths, X_GB.p()) - m_b.shape.calcBoundingRadius();
    if (m_b.shape.type == ContactShape::Type::Box)
        return findDistanceToBox(X_GB, m_b.shape.halfLengths, X_GA.p()) - m_a.shape.calcBoundingRadius();
    return (X_GB.p() - X_GA.p()).norm() - m_a.shape.calcBoundingRadius() - m_b.shape.calcBoundingRadius();
}

SimTK::Real RigidContact::getVerr(const SimTK::State& state) const {
    RigidContactGeometry g;
    const SimTK::Vec3 v = findSlipVelocityInGround(state, g);
    return ~g.n_F * v;
}

SimTK::Real RigidContact::getAerr(const SimTK::State& state) const {
    RigidContactGeometry g;
    const SimTK::Vec3 v = findSlipVelocityInGround(state, g);
    const SimTK::Vec3 p_A = m_a.body.findStationAtGroundPoint(state, g.p_F);
    const SimTK::Vec3 p_B = m_b.body.findStationAtGroundPoint(state, g.p_F);
    const SimTK::Vec3 a = m_b.body.findStationAccelerationInGround(state, p_B) -
                          m_a.body.findStationAccelerationInGround(state, p_A) -
                          2 * (m_a.body.getBodyAngularVelocity(state) % v);
    return ~g.n_F * a;
}

SimTK::MultiplierIndex RigidContact::getContactMultiplierIndex(const SimTK::State& state) const {
    SimTK::MultiplierIndex px0, vx0, ax0;
    m_constraint.getIndexOfMultipliersInUse(state, px0, vx0, ax0);
    return px0;  // invalid when disabled
}

void RigidContact::getFrictionMultiplierIndices(const SimTK::State& state,
                                                SimTK::MultiplierIndex& ix_x,
                                                SimTK::MultiplierIndex& ix_y) const {
    ix_x.invalidate();
    ix_y.invalidate();
    SimTK::MultiplierIndex px0, vx0, ax0;
    m_constraint.getIndexOfMultipliersInUse(state, px0, vx0, ax0);
    if (!vx0.isValid()) return;
    ix_x = vx0;
    ix_y = SimTK::MultiplierIndex(vx0 + 1);
}

SimTK::Real RigidContact::calcEffectiveCOF(const SimTK::State&, SimTK::Real defaultTransitionSpeed,
                                           SimTK::Real slipSpeed) const {
    return SimTK::ConditionalConstraint::calcEffectiveCOF(
        m_parameters.staticFriction, m_parameters.dynamicFriction, m_parameters.viscousFriction,
        defaultTransitionSpeed, slipSpeed);
}

SimTK::Vec2 RigidContact::getSlipVelocity(const SimTK::State& state) const {
    RigidContactGeometry g;
    const SimTK::Vec3 v = findSlipVelocityInGround(state, g);
    const SimTK::UnitVec3 tx = g.n_F.perp();
    return SimTK::Vec2(~tx * v, ~(g.n_F % tx) * v);
}

}  // namespace graspsim::contact
