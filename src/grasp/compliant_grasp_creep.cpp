#include "graspsim/grasp/compliant_grasp_creep.h"

#include "graspsim/contact/contact_force_law.h"
#include "graspsim/error.h"
#include "graspsim/grasp/grasp_matrix.h"
#include "graspsim/grasp/rolling_stiffness.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace graspsim::grasp {

namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Map63 = Eigen::Matrix<double, 6, 3>;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The slip speed v in [0, v_tr] at which the regularized law's mu(v) equals `ratio` (< mu_s) on
// its rising branch, where mu(v) increases (its slope at v_tr is mu_d > 0): bisection.
double findCreepSpeed(const contact::ContactParameters& friction, double ratio) {
    double low = 0, high = friction.transitionVelocity;
    for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (low + high);
        (contact::calcFrictionCoefficient(friction, mid) < ratio ? low : high) = mid;
    }
    return 0.5 * (low + high);
}

struct Contact {
    CompliantContact model;  // normalStiffness follows Hertz, k_n0 (f_n / f_n0)^(1/3)
    double startNormalForce = 0;
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    CompliantContactState state = CompliantContactState::Sticking;
    Eigen::Vector3d tangent = Eigen::Vector3d::Zero();  // friction direction while sliding
    Map63 map;

    double findNormalForce() const { return force.dot(model.n_G); }
    Eigen::Vector3d findTangentialForce() const { return force - findNormalForce() * model.n_G; }
};

Eigen::Matrix3d findStiffness(Contact& c, double mu_d) {
    if (c.state == CompliantContactState::Open) return Eigen::Matrix3d::Zero();
    const double fn = std::max(c.findNormalForce(), 1e-9 * c.startNormalForce);
    const double kn = c.model.normalStiffness * std::cbrt(fn / c.startNormalForce);
    CompliantContact now = c.model;
    now.normalStiffness = kn;
    now.tangentialStiffness = c.model.tangentialStiffness * kn / c.model.normalStiffness;
    if (c.state == CompliantContactState::Sliding) return calcSlidingStiffness(now, c.tangent, mu_d);
    return calcStickingStiffness(now);
}

Eigen::Vector3d findCreepVelocity(const Contact& c, const contact::ContactParameters& friction) {
    if (c.state != CompliantContactState::Sticking) return Eigen::Vector3d::Zero();
    const Eigen::Vector3d ft = c.findTangentialForce();
    const double fn = c.findNormalForce();
    if (!(ft.norm() > 0) || !(fn > 0)) return Eigen::Vector3d::Zero();
    return -findCreepSpeed(friction, ft.norm() / fn) * ft.normalized();
}

bool solve(const Matrix6& a, const Vector6& b, Vector6& x) {
    const Eigen::CompleteOrthogonalDecomposition<Matrix6> solver(a);
    x = solver.solve(b);
    if (solver.rank() < 6 && (a * x - b).norm() > 1e-9 * std::max(b.norm(), 1e-300)) return false;
    return x.allFinite() && x.norm() * a.norm() < 1e12 * std::max(b.norm(), 1e-300);
}

// The springs' stiffness less the rolling stiffness of the forces the contacts carry now
// (rolling_stiffness.h, about p_GO).
Matrix6 assemble(std::vector<Contact>& contacts, const Eigen::Vector3d& p_GO, std::vector<Eigen::Matrix3d>& stiffness, double mu_d) {
    Matrix6 total = Matrix6::Zero();
    stiffness.clear();
    for (Contact& c : contacts) {
        stiffness.push_back(findStiffness(c, mu_d));
        total += c.map * stiffness.back() * c.map.transpose();
        if (c.state != CompliantContactState::Open) total -= calcRollingStiffness(c.model, c.force, p_GO);
    }
    return total;
}

// A contact breaking loose: its friction drops to mu_d f_n and the others take the difference at
// once. False when they cannot (the grasp gives way).
bool breakLoose(std::vector<Contact>& contacts, const Eigen::Vector3d& p_GO, std::size_t i, double mu_d, Vector6& displacement) {
    Contact& c = contacts[i];
    const Eigen::Vector3d ft = c.findTangentialForce();
    c.state = CompliantContactState::Sliding;
    c.tangent = ft.normalized();
    const Eigen::Vector3d drop = (mu_d * c.findNormalForce() - ft.norm()) * c.tangent;
    c.force += drop;
    std::vector<Eigen::Matrix3d> stiffness;
    const Matrix6 total = assemble(contacts, p_GO, stiffness, mu_d);
    Vector6 jump;
    if (!solve(total, c.map * drop, jump)) return false;
    for (std::size_t j = 0; j < contacts.size(); ++j) contacts[j].force -= stiffness[j] * (contacts[j].map.transpose() * jump);
    displacement += jump;
    return true;
}

double findContactSlip(const std::vector<Contact>& contacts, const Vector6& displacement) {
    double slip = 0;
    for (const Contact& c : contacts) slip = std::max(slip, (c.map.transpose() * displacement).norm());
    return slip;
}

void checkInputs(const Eigen::Matrix<double, 6, 1>& direction_G, const contact::ContactParameters& friction,
                 const CompliantRampOptions& o) {
    const double torque = direction_G.head<3>().norm(), force = direction_G.tail<3>().norm();
    if (!((std::abs(torque - 1) < 1e-6 && force == 0) || (std::abs(force - 1) < 1e-6 && torque == 0))) {
        throw InputError("compliant ramp: the load direction must be one unit torque or one unit force");
    }
    friction.validate("compliant ramp: friction");
    if (friction.viscousFriction != 0) throw InputError("compliant ramp: friction: viscous friction must be 0");
    if (!(o.rate > 0) || !(o.slipDistance > 0) || !(o.maxLoad > 0) || !(o.timeStep > 0)) {
        throw InputError("compliant ramp: rate, slipDistance, maxLoad and timeStep must be > 0");
    }
}

std::vector<Contact> makeContacts(const std::vector<CompliantContact>& contacts, const Eigen::Vector3d& p_GO) {
    std::vector<Contact> result;
    for (const CompliantContact& m : contacts) {
        calcStickingStiffness(m);  // validates
        Contact c;
        c.model = m;
        c.force = m.force_G;
        c.startNormalForce = m.force_G.dot(m.n_G);
        c.map = calcContactWrenchMap(m.p_GC - p_GO, 1);
        if (!(c.startNormalForce > 0)) c.state = CompliantContactState::Open;
        result.push_back(c);
    }
    return result;
}

// Contacts opening or breaking loose at `load`; false when the grasp gives way.
bool updateContactStates(std::vector<Contact>& contacts, const Eigen::Vector3d& p_GO, double load,
                         const contact::ContactParameters& friction, Vector6& displacement, CompliantCapacity& capacity) {
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        Contact& c = contacts[i];
        if (c.state == CompliantContactState::Open) continue;
        if (c.findNormalForce() <= 0) {
            c.state = CompliantContactState::Open;
            c.force.setZero();
            capacity.events.push_back({load, int(i), c.state});
        } else if (c.state == CompliantContactState::Sticking &&
                   c.findTangentialForce().norm() >= friction.staticFriction * c.findNormalForce()) {
            capacity.events.push_back({load, int(i), CompliantContactState::Sliding});
            capacity.firstSlip = std::min(capacity.firstSlip, load);
            if (!breakLoose(contacts, p_GO, i, friction.dynamicFriction, displacement)) return false;
        }
    }
    return true;
}

// One explicit step of the forces and the displacement under the load's rate `loadRate` (a wrench
// per second, force first); false when the grasp gives way.
bool stepRamp(std::vector<Contact>& contacts, const Eigen::Vector3d& p_GO, const Vector6& loadRate,
              const contact::ContactParameters& friction, double timeStep, Vector6& displacement) {
    std::vector<Eigen::Matrix3d> stiffness;
    const Matrix6 total = assemble(contacts, p_GO, stiffness, friction.dynamicFriction);
    Vector6 rhs = loadRate;
    std::vector<Eigen::Vector3d> creep;
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        creep.push_back(findCreepVelocity(contacts[i], friction));
        rhs += contacts[i].map * (stiffness[i] * creep[i]);
    }
    Vector6 rate;
    if (!solve(total, rhs, rate)) return false;
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        contacts[i].force += timeStep * stiffness[i] * (creep[i] - contacts[i].map.transpose() * rate);
    }
    displacement += timeStep * rate;
    return true;
}

}  // namespace

struct CompliantCreep::Model {
    std::vector<Contact> contacts;
    Eigen::Vector3d p_GO;
    contact::ContactParameters friction;
    std::vector<Eigen::Vector3d> slipPoints;  // from p_GO, in G
    Vector6 displacement = Vector6::Zero();   // force first, as the wrench maps
};

CompliantCreep::CompliantCreep(const std::vector<CompliantContact>& contacts, const Eigen::Vector3d& p_GO,
                               const contact::ContactParameters& friction, std::vector<Eigen::Vector3d> slipPoints)
    : model_(std::make_unique<Model>()) {
    friction.validate("compliant creep: friction");
    if (friction.viscousFriction != 0) throw InputError("compliant creep: friction: viscous friction must be 0");
    model_->contacts = makeContacts(contacts, p_GO);
    model_->p_GO = p_GO;
    model_->friction = friction;
    for (const Eigen::Vector3d& p : slipPoints) model_->slipPoints.push_back(p - p_GO);
}

CompliantCreep::CompliantCreep(const CompliantCreep& other) : model_(std::make_unique<Model>(*other.model_)), givenWay_(other.givenWay_) {}

CompliantCreep& CompliantCreep::operator=(const CompliantCreep& other) {
    if (this != &other) {
        model_ = std::make_unique<Model>(*other.model_);
        givenWay_ = other.givenWay_;
    }
    return *this;
}

CompliantCreep::~CompliantCreep() = default;

bool CompliantCreep::advance(const Eigen::Matrix<double, 6, 1>& loadChange, double duration, double timeStep) {
    if (!loadChange.allFinite() || !(duration >= 0) || !(timeStep > 0)) {
        throw InputError("compliant creep: the load change must be finite, the duration >= 0 and the step > 0");
    }
    if (givenWay_) return false;
    const double span = duration > 0 ? duration : 1e-9;
    const long steps = std::max(1L, static_cast<long>(std::ceil(span / timeStep - 1e-9)));
    const double h = span / static_cast<double>(steps);
    Vector6 loadRate;
    loadRate << loadChange.tail<3>(), loadChange.head<3>();  // force first, as the wrench maps
    loadRate /= span;
    CompliantCapacity events;  // the states' changes are not recorded here
    for (long k = 0; k < steps; ++k) {
        if (!updateContactStates(model_->contacts, model_->p_GO, 0, model_->friction, model_->displacement, events) ||
            !stepRamp(model_->contacts, model_->p_GO, loadRate, model_->friction, h, model_->displacement)) {
            givenWay_ = true;
            return false;
        }
    }
    return true;
}

double CompliantCreep::findSlip() const {
    if (givenWay_) return kInfinity;
    if (model_->slipPoints.empty()) return findContactSlip(model_->contacts, model_->displacement);
    double slip = 0;
    const Eigen::Vector3d dp = model_->displacement.head<3>(), theta = model_->displacement.tail<3>();
    for (const Eigen::Vector3d& p : model_->slipPoints) slip = std::max(slip, (dp + theta.cross(p)).norm());
    return slip;
}

CompliantRamp runCompliantRamp(const std::vector<CompliantContact>& input, const Eigen::Vector3d& p_GO,
                               const Eigen::Matrix<double, 6, 1>& direction_G, const contact::ContactParameters& friction,
                               const CompliantRampOptions& options) {
    checkInputs(direction_G, friction, options);
    std::vector<Contact> contacts = makeContacts(input, p_GO);
    Vector6 loadRate;
    loadRate << direction_G.tail<3>(), direction_G.head<3>();  // force first, as the wrench maps
    loadRate *= options.rate;
    CompliantRamp ramp;
    ramp.capacity = CompliantCapacity{kInfinity, kInfinity, kInfinity, {}, {}, Eigen::Matrix<double, 6, 1>::Zero()};
    Vector6 displacement = Vector6::Zero();
    // The load from the step count, not summed, so that no rounding accumulates over the ramp.
    for (long k = 0;; ++k) {
        const double load = static_cast<double>(k) * options.rate * options.timeStep;
        if (!(load < options.maxLoad)) break;
        if (!updateContactStates(contacts, p_GO, load, friction, displacement, ramp.capacity)) {
            ramp.capacity.ultimate = load;
            break;
        }
        const double slip = findContactSlip(contacts, displacement);
        ramp.samples.push_back({load, slip});
        if (slip >= options.slipDistance && !std::isfinite(ramp.capacity.onset)) ramp.capacity.onset = load;
        if (!stepRamp(contacts, p_GO, loadRate, friction, options.timeStep, displacement)) {
            ramp.capacity.ultimate = load;
            break;
        }
    }
    if (std::isfinite(ramp.capacity.ultimate)) ramp.capacity.onset = std::min(ramp.capacity.onset, ramp.capacity.ultimate);
    for (const Contact& c : contacts) ramp.capacity.forces_G.push_back(c.force);
    return ramp;
}

}  // namespace graspsim::grasp
