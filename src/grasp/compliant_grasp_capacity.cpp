#include "graspsim/grasp/compliant_grasp_capacity.h"

#include "graspsim/error.h"
#include "graspsim/grasp/grasp_matrix.h"
#include "graspsim/grasp/rolling_stiffness.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace graspsim::grasp {

namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Map63 = Eigen::Matrix<double, 6, 3>;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

void checkContact(const CompliantContact& c, std::size_t i) {
    const std::string where = "compliant grasp capacity: contact " + std::to_string(i) + ": ";
    if (!c.p_GC.allFinite() || !c.force_G.allFinite() || !c.fingerCompliance_G.allFinite()) {
        throw InputError(where + "position, force and finger compliance must be finite");
    }
    if (std::abs(c.n_G.norm() - 1) > 1e-6) throw InputError(where + "normal is not a unit vector (to 1e-6)");
    if (!(c.normalStiffness > 0) || !std::isfinite(c.normalStiffness)) {
        throw InputError(where + "normal stiffness (" + std::to_string(c.normalStiffness) + " N/m) must be finite and > 0");
    }
    if (!(c.tangentialStiffness > 0)) {
        throw InputError(where + "tangential stiffness (" + std::to_string(c.tangentialStiffness) + " N/m) must be > 0");
    }
}

// The solver's running state: per contact its force, mode and (sliding) friction direction.
struct Progress {
    std::vector<Eigen::Vector3d> forces;
    std::vector<CompliantContactState> states;
    std::vector<Eigen::Vector3d> tangents;
    Vector6 displacement = Vector6::Zero();  // [dp ; theta] of the object since the start
    double load = 0;
    // Force-first wrench on the object left unbalanced by friction that dropped from mu to the
    // kinetic coefficient at a break-loose, still to be taken up by the grasp at the present load.
    Vector6 pending = Vector6::Zero();
};

Eigen::Matrix3d findStiffness(const CompliantContact& c, const Progress& p, std::size_t i, double kineticMu) {
    switch (p.states[i]) {
        case CompliantContactState::Sticking: return calcStickingStiffness(c);
        case CompliantContactState::Sliding: return calcSlidingStiffness(c, p.tangents[i], kineticMu);
        case CompliantContactState::Open: break;
    }
    return Eigen::Matrix3d::Zero();
}

// d delta / ds for the load direction, or false when the direction is outside the stiffness
// matrix's range (the grasp lets the object move freely along it).
bool solveRate(const Matrix6& stiffness, const Vector6& direction, Vector6& rate) {
    const Eigen::CompleteOrthogonalDecomposition<Matrix6> solver(stiffness);
    rate = solver.solve(direction);
    const double scale = std::max(stiffness.norm(), 1e-300);
    if (solver.rank() < 6 && (stiffness * rate - direction).norm() > 1e-9 * direction.norm()) return false;
    return rate.allFinite() && rate.norm() * scale < 1e12 * direction.norm();
}

// Smallest root in (0, limit] of a s^2 + b s + c = 0, or limit if none.
double findFirstRoot(double a, double b, double c, double limit) {
    double best = limit;
    const auto consider = [&](double s) {
        if (s > 1e-15 && s < best) best = s;
    };
    if (std::abs(a) < 1e-300) {
        if (b != 0) consider(-c / b);
        return best;
    }
    const double disc = b * b - 4 * a * c;
    if (disc < 0) return best;
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    if (q != 0) consider(c / q);
    consider(q / a);
    return best;
}

// Load step to the cone's edge, |P f| = mu f_n, along f + s df (the contact is inside now).
double findConeStep(const Eigen::Vector3d& n, const Eigen::Vector3d& f, const Eigen::Vector3d& df, double mu,
                    double limit) {
    const Eigen::Vector3d ft = f - f.dot(n) * n, dft = df - df.dot(n) * n;
    const double fn = f.dot(n), dfn = df.dot(n);
    const double a = dft.squaredNorm() - mu * mu * dfn * dfn;
    const double b = 2 * (ft.dot(dft) - mu * mu * fn * dfn);
    const double c = ft.squaredNorm() - mu * mu * fn * fn;
    return findFirstRoot(a, b, std::min(c, 0.0), limit);
}

// Load step at which the largest material-point displacement reaches `distance`.
double findOnsetStep(const std::vector<Map63>& maps, const Vector6& delta, const Vector6& rate, double distance,
                     double limit) {
    double best = limit;
    for (const Map63& d : maps) {
        const Eigen::Vector3d u = d.transpose() * delta, du = d.transpose() * rate;
        if (u.norm() >= distance) return 0;
        best = findFirstRoot(du.squaredNorm(), 2 * u.dot(du), u.squaredNorm() - distance * distance, best);
    }
    return best;
}

Vector6 reorderToForceFirst(const Vector6& rotationFirst) {
    Vector6 v;
    v << rotationFirst.tail<3>(), rotationFirst.head<3>();
    return v;
}

void checkOptions(const CompliantCapacityOptions& options) {
    for (const Eigen::Vector3d& p : options.slipPoints_G) {
        if (!p.allFinite()) throw InputError("compliant grasp capacity: slip points must be finite");
    }
    if (!(options.mu >= 0) || !(options.slipDistance > 0) || !(options.maxLoad > 0)) {
        throw InputError("compliant grasp capacity: mu must be >= 0, slipDistance and maxLoad > 0");
    }
    if (!std::isnan(options.kineticMu) && !(options.kineticMu >= 0 && options.kineticMu <= options.mu)) {
        throw InputError("compliant grasp capacity: kineticMu must be in [0, mu] (or NaN: mu)");
    }
}

void checkDirection(const Vector6& direction_G, const CompliantCapacityOptions& options) {
    const double torque = direction_G.head<3>().norm(), force = direction_G.tail<3>().norm();
    const bool unitTorque = std::abs(torque - 1) < 1e-6 && force == 0;
    const bool unitForce = std::abs(force - 1) < 1e-6 && torque == 0;
    if (!unitTorque && !unitForce) {
        throw InputError("compliant grasp capacity: the load direction must be one unit torque or one unit force");
    }
    checkOptions(options);
}

Progress startProgress(const std::vector<CompliantContact>& contacts, double mu) {
    Progress p;
    for (const CompliantContact& c : contacts) {
        const double fn = c.force_G.dot(c.n_G);
        const Eigen::Vector3d ft = c.force_G - fn * c.n_G;
        p.forces.push_back(c.force_G);
        p.tangents.push_back(ft.norm() > 0 ? Eigen::Vector3d(ft.normalized()) : Eigen::Vector3d(c.n_G.unitOrthogonal()));
        if (!(fn > 0)) {
            p.states.push_back(CompliantContactState::Open);
        } else {
            p.states.push_back(ft.norm() >= mu * fn ? CompliantContactState::Sliding : CompliantContactState::Sticking);
        }
    }
    return p;
}

// The next event's load step and, through `events`, which contacts change (none: no event up to `limit`).
double findNextEvent(const std::vector<CompliantContact>& contacts, const Progress& p,
                     const std::vector<Eigen::Vector3d>& rates, double mu, double limit,
                     std::vector<CompliantCapacityEvent>& events) {
    double step = limit;
    std::vector<std::pair<double, CompliantCapacityEvent>> candidates;
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        if (p.states[i] == CompliantContactState::Open) continue;
        const Eigen::Vector3d& n = contacts[i].n_G;
        const double dfn = rates[i].dot(n);
        if (dfn < 0) candidates.push_back({-p.forces[i].dot(n) / dfn, {0, int(i), CompliantContactState::Open}});
        const double opening = dfn < 0 ? -p.forces[i].dot(n) / dfn : kInfinity;
        if (p.states[i] == CompliantContactState::Sticking) {
            // A contact whose normal force runs out leaves its cone at the same load: it opens.
            const double s = findConeStep(n, p.forces[i], rates[i], mu, limit);
            if (s < limit && s < opening * (1 - 1e-6)) candidates.push_back({s, {0, int(i), CompliantContactState::Sliding}});
        }
    }
    for (const auto& [s, e] : candidates) step = std::min(step, std::max(s, 0.0));
    for (const auto& [s, e] : candidates) {
        if (std::max(s, 0.0) <= step * (1 + 1e-9) + 1e-15) events.push_back(e);
    }
    return step;
}

}  // namespace

void setTangentialStiffnessByNormalForce(std::vector<CompliantContact>& contacts) {
    const auto shares = [](const CompliantContact& c) {
        return c.force_G.dot(c.n_G) > 0 && c.tangentialStiffness > 0 && std::isfinite(c.tangentialStiffness);
    };
    double stiffness = 0, normalForce = 0;
    for (const CompliantContact& c : contacts) {
        if (!shares(c)) continue;
        stiffness += c.tangentialStiffness;
        normalForce += c.force_G.dot(c.n_G);
    }
    for (CompliantContact& c : contacts) {
        if (shares(c)) c.tangentialStiffness = stiffness * c.force_G.dot(c.n_G) / normalForce;
    }
}

Eigen::Matrix3d calcSlidingStiffness(const CompliantContact& c, const Eigen::Vector3d& tangent, double mu) {
    const Eigen::Vector3d a = c.n_G + mu * tangent;
    const double compliance = 1 / c.normalStiffness + c.n_G.dot(c.fingerCompliance_G * a);
    return a * c.n_G.transpose() / std::max(compliance, 1e-12 / c.normalStiffness);
}

Eigen::Matrix3d calcStickingStiffness(const CompliantContact& c) {
    checkContact(c, 0);
    const Eigen::Matrix3d nn = c.n_G * c.n_G.transpose();
    const double tangential = std::isinf(c.tangentialStiffness) ? 0.0 : 1 / c.tangentialStiffness;
    const Eigen::Matrix3d compliance =
        c.fingerCompliance_G + nn / c.normalStiffness + (Eigen::Matrix3d::Identity() - nn) * tangential;
    // A rigid finger with a rigid tangential spring leaves only the normal's compliance: singular.
    if (!(std::abs(compliance.determinant()) > 0)) {
        throw InputError("compliant grasp: a contact with a rigid finger and an infinite tangential stiffness has no "
                         "sticking stiffness; give the finger a compliance or the tangent a finite stiffness");
    }
    return compliance.inverse();
}

namespace {

// The kinetic friction coefficient of a sliding contact: the options' kineticMu, or mu if unset.
double findKineticMu(const CompliantCapacityOptions& options) {
    return std::isnan(options.kineticMu) ? options.mu : options.kineticMu;
}

// A contact breaks loose: it slides from now on along its tangential force, which drops from the
// cone at mu to the cone at kineticMu; the friction it sheds is added to the wrench the grasp must
// still take up at the present load.
void breakLoose(const CompliantContact& c, const Map63& map, double mu, double kineticMu, std::size_t i, Progress& p) {
    const double fn = p.forces[i].dot(c.n_G);
    const Eigen::Vector3d ft = p.forces[i] - fn * c.n_G;
    if (ft.norm() > 0) p.tangents[i] = ft.normalized();
    if (!(kineticMu < mu) || !(fn > 0) || !(kineticMu * fn < ft.norm())) return;
    const Eigen::Vector3d after = fn * c.n_G + kineticMu * fn * p.tangents[i];
    p.pending += map * (after - p.forces[i]);
    p.forces[i] = after;
}

// One piece of the path: the object's displacement rate per unit of the driving parameter (the
// load, or the fraction of the pending wrench taken up), or false outside the stiffness's range.
// Less the rolling stiffness of the forces the contacts carry now (rolling_stiffness.h, about p_GO);
// the contacts' force rates are their springs' alone, in frames that turn with them.
bool solvePiece(const std::vector<CompliantContact>& contacts, const std::vector<Map63>& maps, const Eigen::Vector3d& p_GO,
                const Progress& p, double kineticMu, const Vector6& driving, Vector6& rate, std::vector<Eigen::Vector3d>& rates) {
    std::vector<Eigen::Matrix3d> stiffness;
    Matrix6 total = Matrix6::Zero();
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        if (p.states[i] != CompliantContactState::Open) total -= calcRollingStiffness(contacts[i], p.forces[i], p_GO);
    }
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        stiffness.push_back(findStiffness(contacts[i], p, i, kineticMu));
        total += maps[i] * stiffness[i] * maps[i].transpose();
    }
    if (!solveRate(total, driving, rate)) return false;
    rates.clear();
    for (std::size_t i = 0; i < contacts.size(); ++i) rates.push_back(-stiffness[i] * (maps[i].transpose() * rate));
    return true;
}

// The maps of the material points whose displacement is the slip: the options' slip points, or
// the contacts' (`contactMaps`).
std::vector<Map63> makeSlipMaps(const CompliantCapacityOptions& options, const Eigen::Vector3d& p_GO,
                                const std::vector<Map63>& contactMaps) {
    if (options.slipPoints_G.empty()) return contactMaps;
    std::vector<Map63> maps;
    for (const Eigen::Vector3d& p_GS : options.slipPoints_G) maps.push_back(calcContactWrenchMap(p_GS - p_GO, 1.0));
    return maps;
}

// Contacts outside their cone at the start slide from the start.
void recordStartSliding(const Progress& p, CompliantCapacity& result) {
    for (std::size_t i = 0; i < p.states.size(); ++i) {
        if (p.states[i] == CompliantContactState::Sliding) {
            result.firstSlip = 0;
            result.events.push_back({0, int(i), CompliantContactState::Sliding});
        }
    }
}

void applyEvents(const std::vector<CompliantContact>& contacts, const std::vector<Map63>& maps, double mu, double kineticMu,
                 const std::vector<CompliantCapacityEvent>& events, Progress& p, CompliantCapacity& result) {
    for (CompliantCapacityEvent e : events) {
        const std::size_t i = std::size_t(e.contact);
        e.load = p.load;
        p.states[i] = e.state;
        if (e.state == CompliantContactState::Open) p.forces[i].setZero();
        if (e.state == CompliantContactState::Sliding) {
            breakLoose(contacts[i], maps[i], mu, kineticMu, i, p);
            result.firstSlip = std::min(result.firstSlip, p.load);
        }
        result.events.push_back(e);
    }
}

}  // namespace

namespace {

// The piecewise-linear path of the file comment along `direction_G` (rotation first, any non-zero
// wrench: the load is measured in multiples of it); the options are checked by the caller.
CompliantCapacity followLoad(const std::vector<CompliantContact>& contacts, const Eigen::Vector3d& p_GO,
                             const Vector6& direction_G, const CompliantCapacityOptions& options) {
    std::vector<Map63> maps;
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        checkContact(contacts[i], i);
        maps.push_back(calcContactWrenchMap(contacts[i].p_GC - p_GO, 1.0));  // force first, moment in N m
    }
    const std::vector<Map63> slipMaps = makeSlipMaps(options, p_GO, maps);
    const Vector6 direction = reorderToForceFirst(direction_G);
    const double mu = options.mu, kineticMu = findKineticMu(options);
    CompliantCapacity result{kInfinity, kInfinity, kInfinity, {}, {}, Vector6::Zero()};
    Progress p = startProgress(contacts, mu);
    recordStartSliding(p, result);
    // Each piece ends at a contact's change of state (at most two per contact), at maxLoad, or
    // with the pending wrench taken up (once per break-loose).
    for (int piece = 0; piece < 8 * int(contacts.size()) + 4; ++piece) {
        const bool takingUp = !p.pending.isZero(0);
        if (!takingUp && !(p.load < options.maxLoad)) break;
        Vector6 rate;
        std::vector<Eigen::Vector3d> rates;
        if (!solvePiece(contacts, maps, p_GO, p, kineticMu, takingUp ? p.pending : direction, rate, rates)) {
            result.ultimate = p.load;  // the grasp cannot take up the load (or the friction it shed)
            break;
        }
        std::vector<CompliantCapacityEvent> events;
        const double step = findNextEvent(contacts, p, rates, mu, takingUp ? 1.0 : options.maxLoad - p.load, events);
        if (!std::isfinite(result.onset)) {
            const double s = findOnsetStep(slipMaps, p.displacement, rate, options.slipDistance, step);
            if (s < step) result.onset = p.load + (takingUp ? 0.0 : s);  // taking up happens at the present load
        }
        if (takingUp) {
            p.pending *= events.empty() ? 0.0 : 1 - step;
        } else {
            p.load += step;
        }
        p.displacement += step * rate;
        for (std::size_t i = 0; i < contacts.size(); ++i) p.forces[i] += step * rates[i];
        applyEvents(contacts, maps, mu, kineticMu, events, p, result);
    }
    if (std::isfinite(result.ultimate)) result.onset = std::min(result.onset, result.ultimate);
    result.forces_G = p.forces;
    result.displacement_G << p.displacement.tail<3>(), p.displacement.head<3>();
    return result;
}

}  // namespace

CompliantCapacity calcCompliantCapacity(const std::vector<CompliantContact>& contacts, const Eigen::Vector3d& p_GO,
                                        const Eigen::Matrix<double, 6, 1>& direction_G,
                                        const CompliantCapacityOptions& options) {
    checkDirection(direction_G, options);
    return followLoad(contacts, p_GO, direction_G, options);
}

CompliantCapacity calcCompliantCapacityAlong(const std::vector<CompliantContact>& contacts, const Eigen::Vector3d& p_GO,
                                             const Eigen::Matrix<double, 6, 1>& load_G, const CompliantCapacityOptions& options) {
    if (!load_G.allFinite() || load_G.isZero(0)) {
        throw InputError("compliant grasp capacity: the load wrench must be finite and not zero");
    }
    checkOptions(options);
    return followLoad(contacts, p_GO, load_G, options);
}

}  // namespace graspsim::grasp
