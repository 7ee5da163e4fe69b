#pragma once
/// @file
/// The compliance model of compliant_grasp_capacity.h followed in time under a ramp load, with
/// the regularized friction of full compliant contact (contact/contact_force_law.h) in place of a
/// tangential spring: the contacts creep under any tangential load, as they do in full contact,
/// so the displacement that the ramp calls slip onset depends on the rate.
///
/// Quasi-static (no inertia), small displacements, explicit steps in time. Per contact i, with
/// w_i the velocity of the object's material point at C_i relative to the finger's:
///
///     w_i = D_i^T d delta/dt + C_f,i df_i/dt        (the finger gives under the change of force)
///     n_i . w_i = -(df_n/dt) / k_n                   (Hertz normal spring, k_n ~ f_n^(1/3))
///     P_i w_i = v_i(f_i) + P_i (df_i/dt) / k_t       (creep, plus a stiff tangential spring k_t
///                                                    that only regularizes the chain)
///
/// with v_i the slip velocity at which the regularized law gives the present tangential force:
/// |f_t| = mu(|v|) f_n on its rising branch (|v| <= v_tr), v opposite to f_t. Hence
/// df_i/dt = K_i (v_i - D_i^T d delta/dt), K_i = (C_f,i + n n^T / k_n + P / k_t)^-1, and the
/// object's equilibrium sum_i D_i f_i + W(t) = 0 gives
///
///     (sum_i D_i K_i D_i^T) d delta/dt = dW/dt + sum_i D_i K_i v_i.
///
/// When a contact's |f_t| reaches the static peak mu_s f_n it breaks loose: its friction drops to
/// mu_d f_n along the same direction (the regularized law past its peak) and the other contacts
/// take the difference at once (an elastic redistribution); from then on it slides with the
/// sliding stiffness of compliant_grasp_capacity.h. A contact whose normal force reaches zero
/// opens. The grasp can carry no more when the load leaves the stiffness matrix's range.

#include "graspsim/contact/contact_parameters.h"
#include "graspsim/grasp/compliant_grasp_capacity.h"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace graspsim::grasp {

/// Options of runCompliantRamp.
struct CompliantRampOptions {
    double rate = 1;             ///< N/s or N m/s (> 0): the load's rate
    double slipDistance = 2e-3;  ///< m: displacement that counts as the slip onset (> 0)
    double maxLoad = 100;        ///< N or N m (> 0): the ramp stops here at the latest
    double timeStep = 1e-3;      ///< s (> 0): explicit step
};

/// One sample of the ramp.
struct CompliantRampSample {
    double load = 0;  ///< N or N m
    double slip = 0;  ///< m: the largest displacement of a contact's material point since the start
};

/// The ramp's figures (loads +infinity where not reached) and its samples (one per time step).
struct CompliantRamp {
    CompliantCapacity capacity;  ///< firstSlip: the first contact breaks loose; onset; ultimate
    std::vector<CompliantRampSample> samples;
};

/// The regularizing tangential stiffness of the creep model's contacts, as a multiple of their
/// normal stiffness k_n: stiff enough that the contacts' creep, not the spring, sets their give.
inline constexpr double kCreepTangentialStiffnessRatio = 10;

/// The same model followed step by step under any load history (a ramp, a step, a load that comes
/// and goes), for a switch that watches what full contact's creep would make of the load it sees.
/// Copyable: the state of the forces, the contacts' states and the displacement so far.
class CompliantCreep {
public:
    /// `contacts` at the start, their forces balancing the loads present then; each contact's
    /// tangentialStiffness is the regularizing k_t (file comment). `friction`: mu_s, mu_d and v_tr
    /// (viscous friction 0). `slipPoints` (m, in G): where findSlip() measures, the object's
    /// material points; empty: the contacts. Moments about `p_GO` (m, in G).
    /// @throws graspsim::InputError for invalid contacts or friction.
    CompliantCreep(const std::vector<CompliantContact>& contacts, const Eigen::Vector3d& p_GO, const contact::ContactParameters& friction,
                   std::vector<Eigen::Vector3d> slipPoints = {});
    CompliantCreep(const CompliantCreep& other);
    CompliantCreep& operator=(const CompliantCreep& other);
    ~CompliantCreep();

    /// Follows the load growing by `loadChange` = [torque ; force] (N m, N, about p_GO, in G; rotation
    /// first) evenly over `duration` (s, >= 0) in explicit steps of at most `timeStep` (s, > 0), the
    /// contacts breaking loose or opening on the way (runCompliantRamp's steps). A zero duration
    /// takes the change up elastically, as one step of 1e-9 s. False once the grasp has given way
    /// (the load left the stiffness's range), and from then on.
    /// @throws graspsim::InputError for a non-finite change, a negative duration or a non-positive step.
    bool advance(const Eigen::Matrix<double, 6, 1>& loadChange, double duration, double timeStep = 1e-3);
    /// The largest displacement of the slip points since the start (m); +infinity once given way.
    double findSlip() const;
    /// Whether the grasp has given way.
    bool hasGivenWay() const { return givenWay_; }

private:
    struct Model;
    std::unique_ptr<Model> model_;
    bool givenWay_ = false;
};

/// Ramps `direction_G` = [torque ; force] (one unit torque or one unit force, rotation first) at
/// `p_GO` (m, in G) on the grasp `contacts`, whose start forces balance the loads present before.
/// Each contact's tangentialStiffness is the regularizing k_t (file comment); `friction` gives
/// mu_s, mu_d and v_tr (its viscous friction must be 0).
/// @throws graspsim::InputError for invalid contacts, direction, friction or options.
CompliantRamp runCompliantRamp(const std::vector<CompliantContact>& contacts, const Eigen::Vector3d& p_GO,
                               const Eigen::Matrix<double, 6, 1>& direction_G, const contact::ContactParameters& friction,
                               const CompliantRampOptions& options);

}  // namespace graspsim::grasp
