#include "graspsim/simulation/perturbation_force.h"

namespace graspsim::simulation {

namespace {

class PerturbationImpl : public SimTK::Force::Custom::Implementation {
public:
    PerturbationImpl(const SimTK::MobilizedBody& body, const PerturbationForce& owner) : body_(body), owner_(owner) {}

    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override {
        const SimTK::Vec3 F = owner_.findForceAt(s.getTime());
        if (F == SimTK::Vec3(0)) return;
        body_.applyForceToBodyPoint(s, body_.getBodyMassCenterStation(s), F, bodyForces);
    }
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
    // Time appears in the force: results depend on it, so Simbody must not cache across times.
    bool dependsOnlyOnPositions() const override { return false; }

private:
    const SimTK::MobilizedBody& body_;
    const PerturbationForce& owner_;
};

}  // namespace

PerturbationForce::PerturbationForce(SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& body,
                                     const SimTK::Vec3& F_B_G, double start, double duration)
    : F_B_G_(F_B_G), start_(start), duration_(duration) {
    SimTK::Force::Custom(forces, new PerturbationImpl(body, *this));
}

SimTK::Vec3 PerturbationForce::findForceAt(double t) const {
    return (t >= start_ && t < start_ + duration_) ? F_B_G_ : SimTK::Vec3(0);
}

}  // namespace graspsim::simulation
