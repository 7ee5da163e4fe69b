#include "graspsim/contact/compliant_contact_jacobian.h"

#include <algorithm>

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
        parameters_.push_back(combineMaterials(pair.a.material, pair.b.material));
    }
}

namespace {

// A += J^T B J for a 3 x nu J and a 3x3 B.
void addProjected(const SimTK::Matrix& J, const SimTK::Mat33& B, SimTK::Matrix& A) {
    const int nu = J.ncol();
    SimTK::Matrix BJ(3, nu);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < nu; ++c) BJ(r, c) = B(r, 0) * J(0, c) + B(r, 1) * J(1, c) + B(r, 2) * J(2, c);
    for (int r = 0; r < nu; ++r) {
        if (J(0, r) == 0 && J(1, r) == 0 && J(2, r) == 0) continue;  // mobilities off both bodies' paths
        for (int c = 0; c < nu; ++c) A(r, c) += J(0, r) * BJ(0, c) + J(1, r) * BJ(1, c) + J(2, r) * BJ(2, c);
    }
}

}  // namespace

void CompliantContactJacobian::addForceJacobians(const SimTK::State& state, SimTK::Matrix& D, SimTK::Matrix& K) const {
    SimTK::Matrix JS, J(3, state.getNU());
    for (const ContactReport& report : contacts_.findContactReports(state)) {
        if (report.normalForce <= 0) continue;
        const ContactPair& pair = contacts_.getPair(report.pairIndex);
        const SimTK::Array_<SimTK::MobilizedBodyIndex> bodies{pair.b.body.getMobilizedBodyIndex(),
                                                              pair.a.body.getMobilizedBodyIndex()};
        const SimTK::Array_<SimTK::Vec3> stations{pair.b.body.findStationAtGroundPoint(state, report.p_G),
                                                  pair.a.body.findStationAtGroundPoint(state, report.p_G)};
        matter_.calcStationJacobian(state, bodies, stations, JS);
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < J.ncol(); ++c) J(r, c) = JS(r, c) - JS(r + 3, c);
        const ContactForceDerivatives d = calcContactForceDerivatives(parameters_[report.pairIndex], report, withFriction_);
        addProjected(J, d.dF_dv, D);
        if (withStiffness_) addProjected(J, d.dF_dp, K);
    }
}

}  // namespace graspsim::contact
