#include "graspsim/system/implicit_joint_impedance.h"

#include "graspsim/error.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

namespace graspsim::system {

using SimTK::State;
using SimTK::Vector;

class ImplicitJointImpedance::Implementation : public SimTK::Force::Custom::Implementation {
public:
    Implementation(const SimTK::GeneralForceSubsystem& forces, const SimTK::SimbodyMatterSubsystem& matter,
                   std::vector<JointImpedance> joints)
        : forces_(forces), matter_(matter), joints_(std::move(joints)) {
        for (std::size_t k = 0; k < joints_.size(); ++k) {
            if (joints_[k].stop.isEmptyHandle()) continue;
            const std::size_t f = std::size_t(int(joints_[k].stop.getForceIndex()));
            if (stopJoints_.size() <= f) stopJoints_.resize(f + 1, -1);
            stopJoints_[f] = int(k);
        }
    }

    void setSelf(SimTK::ForceIndex self) { self_ = self; }
    const SimTK::SimbodyMatterSubsystem& getMatter() const { return matter_; }

    void realizeTopology(State& state) const override {
        stepSizeIndex_ = matter_.allocateDiscreteVariable(state, SimTK::Stage::Dynamics, new SimTK::Value<double>(0.0));
        // Stage::Acceleration: updateConstraintForces() invalidates Stage::Dynamics itself unless
        // it completes the state's Dynamics realization (see there).
        constraintForcesIndex_ =
            matter_.allocateDiscreteVariable(state, SimTK::Stage::Acceleration, new SimTK::Value<Vector>(Vector()));
        constraintForcesTimeIndex_ =
            matter_.allocateDiscreteVariable(state, SimTK::Stage::Acceleration, new SimTK::Value<double>(SimTK::NaN));
        operatorIndex_ = matter_.allocateLazyCacheEntry(state, SimTK::Stage::Position, new SimTK::Value<StepOperator>());
    }

    double getStepSize(const State& s) const {
        return SimTK::Value<double>::downcast(matter_.getDiscreteVariable(s, stepSizeIndex_)).get();
    }
    void setStepSize(State& s, double h) const {
        SimTK::Value<double>::updDowncast(matter_.updDiscreteVariable(s, stepSizeIndex_)).upd() = h;
    }
    const Vector& getConstraintForces(const State& s) const {
        return SimTK::Value<Vector>::downcast(matter_.getDiscreteVariable(s, constraintForcesIndex_)).get();
    }
    Vector& updConstraintForces(State& s) const {
        return SimTK::Value<Vector>::updDowncast(matter_.updDiscreteVariable(s, constraintForcesIndex_)).upd();
    }
    void setConstraintForcesTime(State& s, double t) const {
        SimTK::Value<double>::updDowncast(matter_.updDiscreteVariable(s, constraintForcesTimeIndex_)).upd() = t;
    }
    // SemiExplicitEulerTimeStepper realizes Stage::Dynamics once more at the end of its step, with
    // the step's old constraint forces; this element adds nothing there, and
    // updateConstraintForces() completes that realization with the correction
    // (addCorrectionToRealizedForces) instead of evaluating every force element again.
    bool isStale(const State& s) const {
        const double t = SimTK::Value<double>::downcast(matter_.getDiscreteVariable(s, constraintForcesTimeIndex_)).get();
        return !std::isnan(t) && s.getTime() != t;
    }

    void calcForce(const State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                   Vector& mobilityForces) const override {
        if (getStepSize(s) == 0 || isStale(s)) return;
        mobilityForces += calcCorrection(s);
    }

    SimTK::Real calcPotentialEnergy(const State&) const override { return 0; }
    bool dependsOnlyOnPositions() const override { return false; }

    Vector calcCorrection(const State& s) const {
        if (getStepSize(s) == 0) return Vector(s.getNU(), 0.0);
        return calcCorrection(s, calcGeneralizedForce(s));
    }

    // Adds the correction to the mobility forces of a state realized to Stage::Dynamics without
    // this element (isStale()), with F read from that realization: no force element is
    // evaluated again. F is the whole system's, which is what calcGeneralizedForce() sums while
    // the element's force subsystem is the system's only one (multibody_model.h builds one).
    void addCorrectionToRealizedForces(const State& s) const {
        const SimTK::MultibodySystem& system = SimTK::MultibodySystem::downcast(matter_.getSystem());
        const Vector F = calcResidualForce(s, system.getMobilityForces(s, SimTK::Stage::Dynamics),
                                           system.getRigidBodyForces(s, SimTK::Stage::Dynamics));
        system.updMobilityForces(s, SimTK::Stage::Dynamics) += calcCorrection(s, F);
    }

    // X for the generalized force F of every other element (see the header).
    Vector calcCorrection(const State& s, const Vector& F) const {
        const double h = getStepSize(s);
        const int nu = s.getNU();
        Vector X(nu, 0.0);
        if (h == 0) return X;
        const StepOperator& op = findStepOperator(s, h);
        // Right-hand side of (1): F - h K u, F including last step's constraint forces.
        Vector rhs = F;
        const Vector& fc = getConstraintForces(s);
        if (fc.size() == nu) rhs += fc;
        const Vector& u = s.getU();
        for (int i = 0; i < nu; ++i) {
            if (op.K[i] == 0 && op.C[i] == 0) continue;
            rhs[i] -= h * op.K[i] * u[i];
        }
        Vector w;
        op.lu.solve(rhs, w);
        for (int i = 0; i < nu; ++i) {
            if (op.K[i] == 0 && op.C[i] == 0) continue;
            X[i] = -h * op.K[i] * u[i] - (h * op.C[i] + h * h * op.K[i]) * w[i];
        }
        return X;
    }

private:
    // M + h C + h^2 K, factored, and the K and C it holds: functions of q and h alone.
    struct StepOperator {
        double h = SimTK::NaN;
        Vector K, C;
        SimTK::FactorLU lu;
    };

    // A step may need the correction twice at one pose (completing the stepper's realization, then
    // again after an impact or an IK update changed u or the targets); the mass matrix and its
    // factorization are most of its cost.
    const StepOperator& findStepOperator(const State& s, double h) const {
        StepOperator& op = SimTK::Value<StepOperator>::updDowncast(matter_.updCacheEntry(s, operatorIndex_)).upd();
        if (matter_.isCacheValueRealized(s, operatorIndex_) && op.h == h) return op;
        const int nu = s.getNU();
        op.h = h;
        op.K.resize(nu);
        op.K = 0;
        op.C.resize(nu);
        op.C = 0;
        addImpedance(s, op.K, op.C);
        SimTK::Matrix A;
        matter_.calcM(s, A);
        for (int i = 0; i < nu; ++i) {
            if (op.K[i] == 0 && op.C[i] == 0) continue;
            A(i, i) += h * op.C[i] + h * h * op.K[i];
        }
        op.lu.factor(A);
        matter_.markCacheValueRealized(s, operatorIndex_);
        return op;
    }

    // Diagonal joint-space K and C: each joint's constant part plus its stop's linearization
    // (stop force -k x (1 + d u) for a violation x: -dtau/dq = k (1 + d u) ~ k, -dtau/du = k d x).
    void addImpedance(const State& s, Vector& K, Vector& C) const {
        for (const JointImpedance& j : joints_) {
            const SimTK::MobilizedBody& mobod = matter_.getMobilizedBody(j.mobod);
            if (mobod.getNumU(s) != 1)
                throw InputError("implicit joint impedance: mobilized body " + std::to_string(int(j.mobod)) + " has " +
                                 std::to_string(mobod.getNumU(s)) + " mobilities; must have 1");
            const int i = mobod.getFirstUIndex(s);
            K[i] += j.stiffness;
            C[i] += j.damping;
            if (j.stop.isEmptyHandle() || forces_.isForceDisabled(s, j.stop.getForceIndex())) continue;
            const double q = mobod.getOneQ(s, 0);
            const double x = std::max(q - j.stop.getUpperBound(s), j.stop.getLowerBound(s) - q);
            if (x <= 0) continue;
            K[i] += j.stop.getStiffness(s);
            C[i] += j.stop.getStiffness(s) * j.stop.getDissipation(s) * x;
        }
    }

    // Every other enabled element's generalized force, minus the Coriolis and gyroscopic forces:
    // F = -(residual of M udot = F at udot = 0).
    Vector calcGeneralizedForce(const State& s) const {
        Vector mobility(s.getNU(), 0.0);
        SimTK::Vector_<SimTK::SpatialVec> bodies(matter_.getNumBodies(), SimTK::SpatialVec(SimTK::Vec3(0), SimTK::Vec3(0)));
        SimTK::Vector_<SimTK::SpatialVec> elementBodies;
        SimTK::Vector_<SimTK::Vec3> elementParticles;
        Vector elementMobility;
        for (SimTK::ForceIndex f(0); f < forces_.getNumForces(); ++f) {
            if (f == self_ || forces_.isForceDisabled(s, f) || isIdleStop(s, f)) continue;
            // calcForceContribution() zeroes its arrays: sum element by element.
            forces_.getForce(f).calcForceContribution(s, elementBodies, elementParticles, elementMobility);
            addTo(bodies, elementBodies);
            addTo(mobility, elementMobility);
        }
        return calcResidualForce(s, mobility, bodies);
    }

    // A listed joint's stop between its bounds adds nothing (Force::MobilityLinearStop's own test),
    // and leaving its zero arrays out of the sums changes no bit: they start at +0 and never
    // become -0. A third of a hand's force elements are stops, mostly idle.
    bool isIdleStop(const State& s, SimTK::ForceIndex f) const {
        if (std::size_t(int(f)) >= stopJoints_.size() || stopJoints_[std::size_t(int(f))] < 0) return false;
        const JointImpedance& j = joints_[std::size_t(stopJoints_[std::size_t(int(f))])];
        if (j.stop.getStiffness(s) == 0) return true;
        const double q = matter_.getMobilizedBody(j.mobod).getOneQ(s, 0);
        return !(q > j.stop.getUpperBound(s)) && !(q < j.stop.getLowerBound(s));
    }

    // -(residual of M udot = f + J^T F_bodies at udot = 0): the applied generalized force minus
    // the Coriolis and gyroscopic forces.
    Vector calcResidualForce(const State& s, const Vector& mobility, const SimTK::Vector_<SimTK::SpatialVec>& bodies) const {
        Vector residual;
        matter_.calcResidualForceIgnoringConstraints(s, mobility, bodies, Vector(s.getNU(), 0.0), residual);
        residual *= -1;
        return residual;
    }

    // sum += term on the contiguous scalars: Vector's own operator+= goes through Simbody's
    // generic element access, which cost more than the force elements themselves. The same
    // additions in the same order, so the same sums.
    template <class E>
    static void addTo(SimTK::Vector_<E>& sum, const SimTK::Vector_<E>& term) {
        const std::ptrdiff_t n = sum.getContiguousScalarDataLength();
        if (term.getContiguousScalarDataLength() != n) throw NumericalError("implicit joint impedance: a force element's array has the wrong size");
        double* a = sum.updContiguousScalarData();
        const double* b = term.getContiguousScalarData();
        for (std::ptrdiff_t i = 0; i < n; ++i) a[i] += b[i];
    }

    const SimTK::GeneralForceSubsystem& forces_;
    const SimTK::SimbodyMatterSubsystem& matter_;
    std::vector<JointImpedance> joints_;
    std::vector<int> stopJoints_;  // by ForceIndex: the joint (index in joints_) whose stop it is, or -1
    SimTK::ForceIndex self_;
    mutable SimTK::DiscreteVariableIndex stepSizeIndex_, constraintForcesIndex_, constraintForcesTimeIndex_;
    mutable SimTK::CacheEntryIndex operatorIndex_;
};

namespace {

void checkJoint(const JointImpedance& j) {
    const auto bad = [](double x) { return !(std::isfinite(x) && x >= 0); };
    const std::string where = "implicit joint impedance, mobilized body " + std::to_string(int(j.mobod));
    if (bad(j.stiffness)) throw InputError(where + ": stiffness (" + std::to_string(j.stiffness) + ") must be finite and >= 0");
    if (bad(j.damping)) throw InputError(where + ": damping (" + std::to_string(j.damping) + ") must be finite and >= 0");
}

}  // namespace

ImplicitJointImpedance::ImplicitJointImpedance(SimTK::GeneralForceSubsystem& forces,
                                               const SimTK::SimbodyMatterSubsystem& matter,
                                               std::vector<JointImpedance> joints) {
    for (const JointImpedance& j : joints) checkJoint(j);
    auto* implementation = new Implementation(forces, matter, std::move(joints));
    static_cast<SimTK::Force::Custom&>(*this) = SimTK::Force::Custom(forces, implementation);
    implementation->setSelf(getForceIndex());
}

const ImplicitJointImpedance::Implementation& ImplicitJointImpedance::getImpl() const {
    return dynamic_cast<const Implementation&>(getImplementation());
}

void ImplicitJointImpedance::setStepSize(SimTK::State& state, double h) const {
    if (!(std::isfinite(h) && h >= 0)) throw InputError("implicit joint impedance: step size (" + std::to_string(h) + " s) must be finite and >= 0");
    getImpl().setStepSize(state, h);
}

double ImplicitJointImpedance::getStepSize(const SimTK::State& state) const { return getImpl().getStepSize(state); }

void ImplicitJointImpedance::updateConstraintForces(SimTK::State& state) const {
    const Implementation& impedance = getImpl();
    // The stepper's own end-of-step realization of Stage::Dynamics left this element out (a
    // stale state) and is the next step's start: completing it with the correction spares the
    // next step a second evaluation of every force element. Any other state is invalidated.
    const bool complete = state.getSystemStage() >= SimTK::Stage::Dynamics && impedance.isStale(state) && impedance.getStepSize(state) != 0;
    const SimTK::SimbodyMatterSubsystem& matter = impedance.getMatter();
    Vector GtLambda;
    if (state.getNMultipliers() > 0) matter.multiplyByGTranspose(state, state.updMultipliers(), GtLambda);
    else GtLambda.resize(state.getNU()), GtLambda = 0;
    GtLambda *= -1;
    impedance.updConstraintForces(state) = GtLambda;
    impedance.setConstraintForcesTime(state, state.getTime());
    if (complete) impedance.addCorrectionToRealizedForces(state);
    else state.invalidateAllCacheAtOrAbove(SimTK::Stage::Dynamics);
}

SimTK::Vector ImplicitJointImpedance::calcCorrection(const SimTK::State& state) const {
    return getImpl().calcCorrection(state);
}

}  // namespace graspsim::system
