#pragma once
/// @file
/// A compliance model of a grasp's holding capacity: how a load on the object is shared by the
/// contacts while they stick, and the load at which the grasp gives way (issue 17, research step).
///
/// Model (quasi-static, small displacements, the fingers' bases fixed to the palm). Each contact i
/// (point C_i, inward unit normal n_i, force f_i on the object, all in G) is a chain of springs:
/// the finger's Cartesian compliance at C_i, C_f,i = J_i K_q^-1 J_i^T (m/N, from its joint
/// stiffnesses), in series with the contact's own compliance n n^T / k_n + (1 - n n^T) / k_t
/// (k_n the normal stiffness linearized from Hertz at the present depth, k_t a tangential one).
/// A small object displacement delta = [dp ; theta] (about O's origin; force rows first inside
/// this file's solver) moves C_i's material point by u_i = dp + theta x r_i and changes
///
///     sticking:  df_i = -K_i u_i,   K_i = (C_f,i + n n^T / k_n + (1 - n n^T) / k_t)^-1
///     sliding:   df_i = -a_i (n_i . u_i) / (1 / k_n + n_i^T C_f,i a_i),  a_i = n_i + mu_k t_i
///                (friction at the kinetic cone's edge along the fixed unit tangent t_i; only the
///                normal spring resists)
///     open:      f_i = 0.
///
/// Static and kinetic friction: a contact breaks loose at the cone mu (static) and slides at
/// mu_k = kineticMu <= mu, as Coulomb's two coefficients and full contact's regularized law (its
/// peak mu_s at the transition speed, mu_d beyond) have it. At the break-loose its friction drops
/// from mu f_n to mu_k f_n; the grasp takes up the shed force at the same load (the object moves
/// by K^-1 D_i (f_after - f_before)), which can bring further contacts to their cones (a cascade)
/// or leave the stiffness's range: the grasp gives way at that load.
///
/// A load s d (d a unit force or a unit torque about O's origin) is balanced when
/// sum_i D_i K_i D_i^T delta = d s (D_i = [I ; r_i^], the contact's wrench map). The solver
/// follows the load piecewise linearly: in each piece it solves for d delta / ds, finds the next
/// event (a sticking contact reaching its friction cone |f_t| = mu f_n: it slides from then on
/// with its friction, mu_k f_n, along the tangential force it had; or a contact's normal force
/// reaching zero: it opens), takes up what a break-loose shed, and goes on with the new states. The grasp can carry no more when the load
/// direction leaves the range of the stiffness matrix (the remaining contacts let the object move
/// freely along it): that load is the ultimate capacity.
///
/// Rolling: a contact given curvatures (fingerCurvature, objectCurvature) adds its preload's
/// geometric stiffness (rolling_stiffness.h): its force turns with the line of the two surfaces'
/// centres of curvature as the object moves, and the moments are taken about the moving centre of
/// mass. The solver then balances (sum_i D_i K_i D_i^T - G) delta = d s, the contacts' states
/// judged in frames that turn with them.
///
/// Limits of the model: small displacements (the geometry is linearized at the load's start, and
/// frozen for contacts without curvatures); a sliding contact never sticks again and keeps its friction direction; the regularized friction of full contact,
/// which creeps under any tangential load, is replaced by a spring k_t; no inertia.

#include "graspsim/grasp/grasp_contact.h"

#include <Eigen/Core>

#include <limits>
#include <vector>

namespace graspsim::grasp {

/// One contact of the compliance model, at the load's start.
struct CompliantContact {
    Eigen::Vector3d p_GC = Eigen::Vector3d::Zero();  ///< contact point from G's origin, in G (m)
    Eigen::Vector3d n_G = Eigen::Vector3d::UnitZ();  ///< unit normal into the object, in G
    /// Force of the finger on the object at the load's start, in G (N): normal and friction parts.
    Eigen::Vector3d force_G = Eigen::Vector3d::Zero();
    double normalStiffness = 0;      ///< k_n (N/m), > 0: the contact's own normal stiffness
    /// k_t (N/m), > 0; +infinity for a contact that does not give tangentially.
    double tangentialStiffness = 0;
    /// The finger's Cartesian compliance at C (m/N), in G: symmetric positive semi-definite; zero
    /// for a rigid finger (or a contact on the palm).
    Eigen::Matrix3d fingerCompliance_G = Eigen::Matrix3d::Zero();
    /// Curvature (1/m) of the finger's surface at C: 1 / the pad's radius, 0 for a flat one.
    /// With objectCurvature, what turns the contact's force as the object rolls on the finger
    /// (rolling_stiffness.h); both 0 (the default): the contact's geometry stays frozen.
    double fingerCurvature = 0;
    /// Curvature (1/m) of the object's surface at C: 1 / its radius there, 0 for a flat face.
    double objectCurvature = 0;
};

/// What the model does at each contact.
enum class CompliantContactState { Sticking, Sliding, Open };

/// A contact changing state, at a load.
struct CompliantCapacityEvent {
    double load = 0;  ///< N or N m
    int contact = -1;  ///< index in the contact list
    CompliantContactState state = CompliantContactState::Sticking;  ///< the new state
};

/// Options of calcCompliantCapacity.
struct CompliantCapacityOptions {
    double mu = 0.7;              ///< friction coefficient of every contact (>= 0): where it breaks loose
    /// Kinetic friction coefficient of a contact once it slides, in [0, mu]; NaN (default): mu.
    /// Below mu, a contact that breaks loose sheds (mu - kineticMu) f_n of friction at once, and
    /// the grasp takes that up at the same load (file comment).
    double kineticMu = std::numeric_limits<double>::quiet_NaN();
    double slipDistance = 2e-3;   ///< m: the displacement that counts as slip onset (the ramp's)
    /// The object's material points whose largest displacement measures the onset (m, in G, at
    /// the load's start): the grasp goals, where the capacity ramp measures it. Empty: the contact
    /// points.
    std::vector<Eigen::Vector3d> slipPoints_G;
    double maxLoad = 1e3;         ///< N or N m: the model is followed this far at most
};

/// The model's answer along one load direction. Loads in N (force) or N m (torque); +infinity
/// where not reached up to maxLoad.
struct CompliantCapacity {
    /// The first contact reaches its friction cone.
    double firstSlip = 0;
    /// The largest displacement of the material points at the options' slipPoints_G (or at the
    /// contacts) reaches slipDistance: the figure comparable to the ramp's slip onset, which
    /// measures at the grasp goals.
    double onset = 0;
    /// The grasp can carry no more along the direction.
    double ultimate = 0;
    /// Every change of a contact's state, in load order.
    std::vector<CompliantCapacityEvent> events;
    /// The contact forces on the object at the ultimate load (or at maxLoad), in G (N); with
    /// curvatures, in the contacts' frames turned back to their start.
    std::vector<Eigen::Vector3d> forces_G;
    /// The object's displacement from the load's start to the same load: rotation (rad, small,
    /// as a rotation vector) then translation of the point at p_GO (m), both in G.
    Eigen::Matrix<double, 6, 1> displacement_G = Eigen::Matrix<double, 6, 1>::Zero();
};

/// Shares the contacts' total tangential stiffness in proportion to their normal forces:
/// k_t,i = (sum_j k_t,j) f_n,i / sum_j f_n,j (f_n the force along the normal; N/m). Why: full
/// contact's regularized friction has no tangential spring. A sticking contact creeps at the slip
/// speed v where mu(v) f_n = |f_t|, so its friction ratio |f_t| / f_n is a function of its slip
/// alone, whatever its normal force, and contacts that slip alike reach the cone together. A
/// spring gives the ratio k_t u / f_n: a function of the slip u alone only when k_t is
/// proportional to f_n. Hertz-Mindlin's k_t ~ f_n^(1/3) brings lightly pressed contacts to their
/// cones first and centres the grasp's tangential stiffness away from the firmly pressed ones.
/// The total is kept: the creep's absolute rate is not a stiffness, and only the sharing changes.
/// Contacts without a positive normal force or a finite positive k_t are left out and as they are.
void setTangentialStiffnessByNormalForce(std::vector<CompliantContact>& contacts);

/// The sticking stiffness K = (C_f + n n^T / k_n + (1 - n n^T) / k_t)^-1 of a contact (N/m, in G).
/// @throws graspsim::InputError for a non-positive stiffness or a normal that is not unit.
Eigen::Matrix3d calcStickingStiffness(const CompliantContact& contact);

/// The sliding stiffness a n^T / (1 / k_n + n^T C_f a), a = n + mu t (N/m, in G), of a contact
/// whose friction mu f_n acts along the unit tangent `tangent` (file comment).
Eigen::Matrix3d calcSlidingStiffness(const CompliantContact& contact, const Eigen::Vector3d& tangent, double mu);

/// Follows a load `direction_G` = [torque ; force] (Simbody's order, rotation first; exactly one
/// of the two parts non-zero and unit), applied at or about `p_GO` (m, in G; the object's centre
/// of mass), until the grasp gives way (file comment). The contacts' start forces already balance
/// the loads present before (the object's weight).
/// @throws graspsim::InputError for invalid contacts, a direction that is not one unit force or one
///         unit torque, or negative options.
CompliantCapacity calcCompliantCapacity(const std::vector<CompliantContact>& contacts, const Eigen::Vector3d& p_GO,
                                        const Eigen::Matrix<double, 6, 1>& direction_G,
                                        const CompliantCapacityOptions& options);

/// The same model along any load wrench `load_G` = [torque ; force] (rotation first, N m and N,
/// about `p_GO`, in G; torque and force may be mixed), such as the wrench a constraint carries
/// beyond what the contacts carried at the start. A load along one axis at a time, as the per-axis
/// limits of compliance_limits.h take it, does not bound a load that combines axes: its parts
/// draw on the same friction cones. Loads are in multiples of `load_G`: onset <= 1 means the grasp
/// reaches its slip onset before the load reaches `load_G`.
/// @throws graspsim::InputError for invalid contacts, a zero or non-finite load, or negative options.
CompliantCapacity calcCompliantCapacityAlong(const std::vector<CompliantContact>& contacts, const Eigen::Vector3d& p_GO,
                                             const Eigen::Matrix<double, 6, 1>& load_G,
                                             const CompliantCapacityOptions& options);

}  // namespace graspsim::grasp
