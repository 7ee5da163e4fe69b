#include "graspsim/control/fingertip_ik.h"

#include "finger_chains.h"

#include "graspsim/error.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace graspsim::control {

FingertipIk::FingertipIk(const system::MultibodyModel& model, const std::vector<std::string>& endEffectors,
                         const std::vector<std::string>& movingJoints, IkMethod method)
    : model_(model), movingJoints_(movingJoints), assembler_(std::make_unique<SimTK::Assembler>(model.getSystem())),
      chains_(std::make_unique<FingerChains>(model, endEffectors, movingJoints)), method_(method) {
    const model::ModelDescription& d = model.getDescription();
    const SimTK::SimbodyMatterSubsystem& matter = model.getMatter();
    for (const std::string& joint : movingJoints) {
        const model::Joint* j = d.findJoint(joint);
        if (!j || j->type == model::Joint::Type::Fixed) throw InputError("IK: no movable joint named '" + joint + "'");
        const SimTK::MobilizedBody& mobod = model.getMobilizedBody(j->child);
        movingBodies_.push_back(mobod.getMobilizedBodyIndex());
        if (j->hasLimits()) assembler_->restrictQ(mobod.getMobilizedBodyIndex(), SimTK::MobilizerQIndex(0), j->lower, j->upper);
    }
    // Lock everything that is not a moving joint: the rest of the arm and any grasped object.
    for (SimTK::MobilizedBodyIndex b(1); b < matter.getNumBodies(); ++b) {
        if (std::find(movingBodies_.begin(), movingBodies_.end(), b) == movingBodies_.end()) assembler_->lockMobilizer(b);
    }
    // Owned here until the assembler adopts it, so that an unknown name below leaks nothing.
    auto markers = std::make_unique<SimTK::Markers>();
    SimTK::Array_<SimTK::Markers::MarkerIx> order;
    for (const std::string& name : endEffectors) {
        const model::EndEffector* e = d.findEndEffector(name);
        if (!e) throw InputError("IK: no end-effector named '" + name + "'");
        const SimTK::Vec3 p_BE(e->p_BE[0], e->p_BE[1], e->p_BE[2]);
        order.push_back(markers->addMarker(name, model.getMobilizedBody(e->body), p_BE));
    }
    markers->defineObservationOrder(order);
    markers_ = markers.get();
    assembler_->adoptAssemblyGoal(markers.release());
    assembler_->setAccuracy(1e-6);
}

FingertipIk::~FingertipIk() = default;

namespace {

// Whether `body` moves with any of the IK's moving joints (it is one of them or outboard of one).
bool movesWith(const SimTK::MobilizedBody& body, const std::vector<SimTK::MobilizedBodyIndex>& moving) {
    for (const SimTK::MobilizedBody* b = &body; !b->isGround(); b = &b->getParentMobilizedBody()) {
        if (std::find(moving.begin(), moving.end(), b->getMobilizedBodyIndex()) != moving.end()) return true;
    }
    return false;
}

bool involvesMovingBodies(const SimTK::Constraint& constraint, const std::vector<SimTK::MobilizedBodyIndex>& moving) {
    for (SimTK::ConstrainedBodyIndex k(0); k < constraint.getNumConstrainedBodies(); ++k) {
        if (movesWith(constraint.getMobilizedBodyFromConstrainedBody(k), moving)) return true;
    }
    for (SimTK::ConstrainedMobilizerIndex k(0); k < constraint.getNumConstrainedMobilizers(); ++k) {
        if (movesWith(constraint.getMobilizedBodyFromConstrainedMobilizer(k), moving)) return true;
    }
    return false;
}

// The Assembler satisfies every enabled constraint of its state, but two kinds are not part of
// the hand's kinematics. Conditional constraints (rigid contacts, enabled while touching): the IK
// places the fingertips at their goals as if nothing were in the way, and contact pushes back in
// the dynamics. Constraints among bodies no moving joint moves (the Ground weld holding an object
// before its release): the IK cannot change them, so they would only fail the assembly when the
// integrator holds them to a looser tolerance than the Assembler's. Returns nullptr when `state`
// has none enabled (no copy needed).
std::unique_ptr<SimTK::State> withoutUnreachableConstraints(const SimTK::SimbodyMatterSubsystem& matter,
                                                            const SimTK::State& state,
                                                            const std::vector<SimTK::MobilizedBodyIndex>& moving) {
    std::unique_ptr<SimTK::State> copy;
    for (SimTK::ConstraintIndex c(0); c < matter.getNumConstraints(); ++c) {
        const SimTK::Constraint& constraint = matter.getConstraint(c);
        if (constraint.isDisabled(state)) continue;
        if (!constraint.isConditional() && involvesMovingBodies(constraint, moving)) continue;
        if (!copy) copy = std::make_unique<SimTK::State>(state);
        constraint.disable(*copy);
    }
    return copy;
}

}  // namespace

SimTK::Vector FingertipIk::solve(const SimTK::State& state, const std::vector<SimTK::Vec3>& goals_G) {
    if (goals_G.size() != static_cast<std::size_t>(chains_->getNumEndEffectors())) {
        throw Error("fingertip IK: got " + std::to_string(goals_G.size()) + " goals for " +
                    std::to_string(chains_->getNumEndEffectors()) + " end-effectors");
    }
    if (method_ == IkMethod::Assembler || hasConstraintOnMovingJoints(state)) return solveWithAssembler(state, goals_G);
    return solveWithDampedLeastSquares(state, goals_G);
}

bool FingertipIk::hasConstraintOnMovingJoints(const SimTK::State& state) const {
    const SimTK::SimbodyMatterSubsystem& matter = model_.getMatter();
    for (SimTK::ConstraintIndex c(0); c < matter.getNumConstraints(); ++c) {
        const SimTK::Constraint& constraint = matter.getConstraint(c);
        if (!constraint.isDisabled(state) && !constraint.isConditional() && involvesMovingBodies(constraint, movingBodies_)) return true;
    }
    return false;
}

SimTK::Vector FingertipIk::solveWithAssembler(const SimTK::State& state, const std::vector<SimTK::Vec3>& goals_G) {
    lastIterations_ = 0;
    SimTK::Array_<SimTK::Vec3> observations(goals_G.begin(), goals_G.end());
    markers_->moveAllObservations(observations);
    const std::unique_ptr<SimTK::State> unconstrained = withoutUnreachableConstraints(model_.getMatter(), state, movingBodies_);
    try {
        // The locked joints (arm, object) come from `state`; the Assembler starts the moving
        // joints from there too, which keeps consecutive solutions close (warm start).
        assembler_->initialize(unconstrained ? *unconstrained : state);
        assembler_->assemble();
    } catch (const std::exception& e) {
        throw Error(std::string("fingertip IK failed at t = ") + std::to_string(state.getTime()) + " s: " + e.what());
    }
    const SimTK::State& solved = assembler_->getInternalState();
    double sumSquares = 0;
    lastDistances_.clear();
    for (SimTK::Markers::MarkerIx m(0); m < markers_->getNumMarkers(); ++m) {
        const double squared = markers_->findCurrentMarkerErrorSquared(m);
        sumSquares += squared;
        lastDistances_.push_back(std::sqrt(squared));
    }
    lastError_ = std::sqrt(sumSquares / std::max(1, markers_->getNumMarkers()));
    SimTK::Vector q(static_cast<int>(movingBodies_.size()));
    for (std::size_t k = 0; k < movingBodies_.size(); ++k) {
        q[static_cast<int>(k)] = model_.getMatter().getMobilizedBody(movingBodies_[k]).getOneQ(solved, 0);
    }
    return q;
}

namespace {

constexpr int kMaxIterations = 200;
constexpr double kStepTolerance = 1e-12;  // rad or m: a smaller change no longer moves a fingertip in double
constexpr double kMinDamping = 1e-9, kMaxDamping = 1e10;

double sumSquaredErrors(const std::vector<SimTK::Vec3>& p_GE, const std::vector<SimTK::Vec3>& goals_G) {
    double sum = 0;
    for (std::size_t e = 0; e < p_GE.size(); ++e) sum += (p_GE[e] - goals_G[e]).normSqr();
    return sum;
}

// The Gauss-Newton normal equations of the fit: A = J^T J (n x n, row-major) and g = J^T r, the
// gradient of half the squared error, with r = p_GE - goals.
void formNormalEquations(const std::vector<double>& J, const std::vector<SimTK::Vec3>& p_GE,
                         const std::vector<SimTK::Vec3>& goals_G, int n, std::vector<double>& A, std::vector<double>& g) {
    A.assign(static_cast<std::size_t>(n) * n, 0.0);
    g.assign(n, 0.0);
    for (std::size_t row = 0; row < 3 * p_GE.size(); ++row) {
        const double r = p_GE[row / 3][static_cast<int>(row % 3)] - goals_G[row / 3][static_cast<int>(row % 3)];
        const double* Jr = &J[row * n];
        for (int i = 0; i < n; ++i) {
            if (Jr[i] == 0) continue;
            g[i] += Jr[i] * r;
            for (int j = 0; j < n; ++j) A[i * n + j] += Jr[i] * Jr[j];
        }
    }
}

// The Levenberg step: solves (A + mu a I) dq = -g for the free joints (the others stay where they
// are) by Cholesky, with a the mean diagonal of A. The damping is the same on every joint (not
// Marquardt's diag(A)) because then the step J^T (J J^T + mu a I)^-1 r lies in the row space of J:
// a finger with more joints than its goal constrains does not drift in its null space from one
// solve to the next, it moves as little as the fit needs, as a gradient method does.
std::vector<double> solveDampedStep(const std::vector<double>& A, const std::vector<double>& g,
                                    const std::vector<int>& free, int n, double mu) {
    const int m = static_cast<int>(free.size());
    double meanDiagonal = 0;
    for (int i = 0; i < m; ++i) meanDiagonal += A[free[i] * n + free[i]] / m;
    const double damping = mu * meanDiagonal + 1e-14;  // the absolute term keeps a joint no goal depends on at rest
    std::vector<double> L(static_cast<std::size_t>(m) * m, 0.0), x(m);
    for (int i = 0; i < m; ++i) {
        for (int j = 0; j <= i; ++j) {
            double v = A[free[i] * n + free[j]];
            if (i == j) v += damping;
            for (int k = 0; k < j; ++k) v -= L[i * m + k] * L[j * m + k];
            L[i * m + j] = i == j ? std::sqrt(std::max(v, 1e-300)) : v / L[j * m + j];
        }
    }
    for (int i = 0; i < m; ++i) {  // L y = -g
        double v = -g[free[i]];
        for (int k = 0; k < i; ++k) v -= L[i * m + k] * x[k];
        x[i] = v / L[i * m + i];
    }
    for (int i = m - 1; i >= 0; --i) {  // L^T dq = y
        double v = x[i];
        for (int k = i + 1; k < m; ++k) v -= L[k * m + i] * x[k];
        x[i] = v / L[i * m + i];
    }
    std::vector<double> dq(n, 0.0);
    for (int i = 0; i < m; ++i) dq[free[i]] = x[i];
    return dq;
}

// Joints that may move this iteration: a joint at a bound with the descent direction pointing out
// of its range stays there (the bound is active), which makes the fixed point a bounded minimum.
std::vector<int> findFreeJoints(const FingerChains& chains, const std::vector<double>& q, const std::vector<double>& g) {
    std::vector<int> free;
    for (int k = 0; k < chains.getNumJoints(); ++k) {
        const bool atLower = q[k] <= chains.getLower(k) && g[k] > 0, atUpper = q[k] >= chains.getUpper(k) && g[k] < 0;
        if (!atLower && !atUpper) free.push_back(k);
    }
    return free;
}

void clampToRanges(const FingerChains& chains, std::vector<double>& q) {
    for (int k = 0; k < chains.getNumJoints(); ++k) q[k] = std::clamp(q[k], chains.getLower(k), chains.getUpper(k));
}

}  // namespace

// Bounded Levenberg-Marquardt from the state's angles: a step that lowers the squared error is
// taken and the damping relaxed toward Gauss-Newton; one that does not is refused and the damping
// raised toward a short gradient step. It stops when the pose no longer changes.
SimTK::Vector FingertipIk::solveWithDampedLeastSquares(const SimTK::State& state, const std::vector<SimTK::Vec3>& goals_G) {
    FingerChains& chains = *chains_;
    chains.capture(state);
    const int n = chains.getNumJoints();
    std::vector<double> q = chains.getCapturedAngles(), J, A, g;
    clampToRanges(chains, q);
    std::vector<SimTK::Vec3> p_GE, pTry_GE;
    chains.calcLocations(q, p_GE, &J);
    double cost = sumSquaredErrors(p_GE, goals_G), mu = 1e-3;
    int iterations = 0;
    while (iterations < kMaxIterations && cost > 0 && mu < kMaxDamping) {
        ++iterations;
        formNormalEquations(J, p_GE, goals_G, n, A, g);
        std::vector<double> qTry = q, dq = solveDampedStep(A, g, findFreeJoints(chains, q, g), n, mu);
        for (int k = 0; k < n; ++k) qTry[k] += dq[k];
        clampToRanges(chains, qTry);
        chains.calcLocations(qTry, pTry_GE, nullptr);
        const double costTry = sumSquaredErrors(pTry_GE, goals_G);
        if (!(costTry < cost)) {
            mu *= 10;
            continue;
        }
        double change = 0;
        for (int k = 0; k < n; ++k) change = std::max(change, std::abs(qTry[k] - q[k]));
        q.swap(qTry);
        cost = costTry;
        mu = std::max(mu / 10, kMinDamping);
        if (change < kStepTolerance) break;
        chains.calcLocations(q, p_GE, &J);
    }
    lastIterations_ = iterations;
    lastError_ = std::sqrt(cost / std::max(1, chains.getNumEndEffectors()));
    chains.calcLocations(q, p_GE, nullptr);
    lastDistances_.clear();
    for (std::size_t k = 0; k < p_GE.size(); ++k) lastDistances_.push_back((p_GE[k] - goals_G[k]).norm());
    SimTK::Vector result(n);
    for (int k = 0; k < n; ++k) result[k] = q[k];
    return result;
}

}  // namespace graspsim::control
