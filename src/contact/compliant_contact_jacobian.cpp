#include "graspsim/contact/compliant_contact_jacobian.h"

#include "graspsim/integration/point_jacobian.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace graspsim::contact {

namespace {

// a b^T (Simbody's Vec3 * ~Vec3 trips GCC's -Warray-bounds in its own headers).
SimTK::Mat33 outer(const SimTK::Vec3& a, const SimTK::Vec3& b) {
    SimTK::Mat33 m;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) m(r, c) = a[r] * b[c];
    return m;
}

// mu'(v) (s/m), the slope of contact_force_law.h's friction coefficient at slip speed v >= 0.
double calcFrictionSlope(const ContactParameters& p, double v) {
    const double r = v / p.transitionVelocity;
    const double rise = 2 * (p.staticFriction - p.dynamicFriction);
    const double s = 1 + r * r;
    const double slope = r < 1 ? p.dynamicFriction + rise / s - 2 * rise * r * r / (s * s)  // d(r g(r))/dr
                               : -2 * rise * r / (s * s);                                  // dg/dr
    return slope / p.transitionVelocity + p.viscousFriction;
}

// The tangential friction Jacobian -f_n d(mu(v) t)/dv_t, projected on the tangent plane.
SimTK::Mat33 calcFrictionJacobian(const ContactParameters& p, const ContactReport& report) {
    SimTK::Mat33 tangent = -outer(report.n_G.asVec3(), report.n_G.asVec3());
    for (int k = 0; k < 3; ++k) tangent(k, k) += 1;
    const double v = report.slipVelocity_G.norm();
    if (v == 0) return -report.normalForce * std::max(calcFrictionSlope(p, 0), 0.0) * tangent;
    const SimTK::Vec3 t = report.slipVelocity_G / v;
    const SimTK::Mat33 tt = outer(t, t);
    const double mu = calcFrictionCoefficient(p, v);
    return -report.normalForce * ((mu / v) * (tangent - tt) + std::max(calcFrictionSlope(p, v), 0.0) * tt);
}

}  // namespace

ContactForceDerivatives calcContactForceDerivatives(const ContactParameters& p, const ContactReport& report,
                                                    bool withFriction) {
    const SimTK::Vec3 n = report.n_G.asVec3();
    const double hertz = report.normalForce / (1 + 1.5 * p.dissipation * report.depthRate);
    const double dfn_dxdot = 1.5 * p.dissipation * hertz;
    const double dfn_dx = report.depth > 0 ? 1.5 * report.normalForce / report.depth : 0.0;
    SimTK::Vec3 direction = n;  // of the force's change with f_n: n - mu t
    ContactForceDerivatives d;
    d.dF_dv.setToZero();
    if (withFriction) {
        const double v = report.slipVelocity_G.norm();
        if (v > 0) direction -= calcFrictionCoefficient(p, v) * (report.slipVelocity_G / v);
        d.dF_dv = calcFrictionJacobian(p, report);
    }
    d.dF_dv -= dfn_dxdot * outer(direction, n);
    d.dF_dp = -dfn_dx * outer(direction, n);
    return d;
}

CompliantContactJacobian::CompliantContactJacobian(const SimTK::SimbodyMatterSubsystem& matter,
                                                   const CompliantContactForce& contacts, bool withStiffness)
    : matter_(matter), contacts_(contacts), withStiffness_(withStiffness),
      withFriction_(contacts.getFrictionSettings().model == FrictionModel::Regularized) {
    for (int i = 0; i < contacts_.getNumPairs(); ++i) {
        const ContactPair& pair = contacts_.getPair(i);
        parameters_.push_back(pair.parameters);
    }
}

namespace {

// A += J^T B J for a 3 x nu J and a 3x3 B, on column-major storage (J[r + 3 c], A[r + nu c]),
// over J's nonzero columns only: SimTK::Matrix's element access costs more than the arithmetic.
void addProjected(const double* J, int nu, const std::vector<int>& columns, const SimTK::Mat33& B, double* A) {
    thread_local std::vector<double> BJ;
    BJ.resize(3 * columns.size());
    for (std::size_t k = 0; k < columns.size(); ++k) {
        const double* Jc = J + 3 * columns[k];
        for (int r = 0; r < 3; ++r) BJ[r + 3 * k] = B(r, 0) * Jc[0] + B(r, 1) * Jc[1] + B(r, 2) * Jc[2];
    }
    for (int r : columns) {
        const double* Jr = J + 3 * r;
        for (std::size_t k = 0; k < columns.size(); ++k) {
            A[r + nu * columns[k]] += Jr[0] * BJ[3 * k] + Jr[1] * BJ[1 + 3 * k] + Jr[2] * BJ[2 + 3 * k];
        }
    }
}

}  // namespace

// J = J_b(P) - J_a(P); the mobilities both paths share cancel.
void CompliantContactJacobian::fillRelativeJacobian(const ContactPair& pair, const SimTK::Vec3& p_G,
                                                    const SimTK::State& state, std::vector<double>& J) const {
    std::fill(J.begin(), J.end(), 0.0);
    integration::addPointJacobian(matter_, state, pair.b.body.getMobilizedBodyIndex(), p_G, 1, 3, J);
    integration::addPointJacobian(matter_, state, pair.a.body.getMobilizedBodyIndex(), p_G, -1, 3, J);
}

// The contact points come from the force element's own evaluation (its cache), not a second
// geometry pass.
void CompliantContactJacobian::addForceJacobians(const SimTK::State& state, SimTK::Matrix& D, SimTK::Matrix& K) const {
    const int nu = state.getNU();
    std::vector<double> J(3 * static_cast<std::size_t>(nu));
    std::vector<int> columns;
    for (const ContactReport& report : contacts_.getEvaluatedContacts(state)) {
        if (report.normalForce <= 0) continue;
        const ContactPair& pair = contacts_.getPair(report.pairIndex);
        fillRelativeJacobian(pair, report.p_G, state, J);
        integration::findNonzeroColumns(J, 3, nu, columns);
        const ContactForceDerivatives d = calcContactForceDerivatives(parameters_[report.pairIndex], report, withFriction_);
        addProjected(J.data(), nu, columns, d.dF_dv, D.updContiguousScalarData());
        if (withStiffness_) addProjected(J.data(), nu, columns, d.dF_dp, K.updContiguousScalarData());
    }
}

// Per pushing contact point, its pair and whether it sticks (slip below the transition velocity):
// the friction slope there is about f_n mu_s / v_t, far above the sliding one, so a point that
// starts or stops sliding changes D by orders of magnitude.
void CompliantContactJacobian::appendActiveSet(const SimTK::State& state, std::vector<int>& active) const {
    for (const ContactReport& report : contacts_.getEvaluatedContacts(state)) {
        if (report.normalForce <= 0) continue;
        const bool sticking = report.slipVelocity_G.norm() < parameters_[report.pairIndex].transitionVelocity;
        active.push_back(2 * report.pairIndex);
        if (sticking) active.push_back(2 * report.pairIndex + 1);
    }
}

// The fastest point, so that the margin is positive only while every pushing point of the pair
// sticks: a pair whose points disagree at a step's start gives no estimate (the stepper bisects).
// A point letting go has no smooth margin here (its force is clamped at zero), hence NaN.
double CompliantContactJacobian::findTermMargin(const SimTK::State& state, int id) const {
    if (id % 2 != 1) return SimTK::NaN;
    const int pair = id / 2;
    double margin = SimTK::NaN;
    for (const ContactReport& report : contacts_.getEvaluatedContacts(state)) {
        if (report.pairIndex != pair || report.normalForce <= 0) continue;
        const double m = parameters_[pair].transitionVelocity - report.slipVelocity_G.norm();
        margin = std::isnan(margin) ? m : std::min(margin, m);
    }
    return margin;
}

}  // namespace graspsim::contact
