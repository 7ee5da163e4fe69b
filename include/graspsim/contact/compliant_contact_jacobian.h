#pragma once
/// @file
/// The force Jacobians (integration/force_jacobian.h) of the compliant contact element
/// (compliant_contact_force.h), analytic, per active contact point, for the linearly implicit
/// stepper (integration/linearly_implicit_stepper.h).
///
/// Per contact point P with normal n (a toward b), depth x, penetration rate xdot, slip v_t
/// (speed v, direction t), normal force f_n > 0 and Hertz force f_H = f_n / (1 + 1.5 c xdot),
/// the force on b, F = f_n n - f_n mu(v) t, has with respect to the relative velocity v_b - v_a
/// of the two bodies' material points at P
///
///     dF/dv = -1.5 c f_H (n n^T) + 1.5 c f_H mu t n^T - f_n [mu/v (P_n - t t^T) + mu' t t^T]
///
/// (P_n = I - n n^T; at v = 0 the friction term is f_n mu'(0) P_n; a falling branch of the
/// Stribeck curve, mu' < 0, is taken as 0 so the step's matrix stays dissipative), and with
/// respect to the relative displacement, through the depth only (the normal's turning is left
/// out), dF/dp = -(1.5 f_n / x) (n - mu t) n^T. Mapped to generalized coordinates with the relative
/// station Jacobian J = J_b(P) - J_a(P): D += J^T (dF/dv) J, K += J^T (dF/dp) J.
/// With the elastic-anchor friction law only the normal terms are given (friction explicit).

#include "graspsim/contact/compliant_contact_force.h"
#include "graspsim/contact/contact_force_law.h"
#include "graspsim/integration/force_jacobian.h"

#include <vector>

namespace graspsim::contact {

/// The Jacobians of one CompliantContactForce (a handle to it is kept; the element must outlive this).
class CompliantContactJacobian : public integration::ForceJacobianContributor {
public:
    /// `withStiffness`: also add the normal stiffness term K (otherwise only D).
    CompliantContactJacobian(const SimTK::SimbodyMatterSubsystem& matter, const CompliantContactForce& contacts,
                             bool withStiffness = true);
    void addForceJacobians(const SimTK::State& state, SimTK::Matrix& D, SimTK::Matrix& K) const override;
    /// Per contact point that pushes (f_n > 0), in the element's order: 2 pairIndex (the normal
    /// force's stiffness), then 2 pairIndex + 1 if it sticks (slip speed below the pair's transition
    /// velocity: the friction's steep slope), so starting to slide drops a term.
    void appendActiveSet(const SimTK::State& state, std::vector<int>& active) const override;
    /// A sticking term (odd id): the pair's transition velocity less its fastest pushing point's
    /// slip speed (m/s); NaN for a normal-force term and for a pair with no pushing point.
    double findTermMargin(const SimTK::State& state, int id) const override;

private:
    // J = J_b(P) - J_a(P) (3 x nu, column-major) for the pair's two bodies at P (in Ground, m).
    void fillRelativeJacobian(const ContactPair& pair, const SimTK::Vec3& p_G, const SimTK::State& state,
                              std::vector<double>& J) const;

    const SimTK::SimbodyMatterSubsystem& matter_;
    CompliantContactForce contacts_;
    std::vector<ContactParameters> parameters_;  // per pair, copied once
    bool withStiffness_;
    bool withFriction_;
};

/// The 3x3 derivatives of one contact point's force on b (see the file comment).
struct ContactForceDerivatives {
    SimTK::Mat33 dF_dv;  ///< N s/m, with respect to the relative velocity of b's point w.r.t. a's
    SimTK::Mat33 dF_dp;  ///< N/m, with respect to the relative displacement
};

/// The derivatives of `report`'s force (normal force > 0) under `parameters`; friction terms
/// only when `withFriction`.
ContactForceDerivatives calcContactForceDerivatives(const ContactParameters& parameters, const ContactReport& report,
                                                    bool withFriction);

}  // namespace graspsim::contact
