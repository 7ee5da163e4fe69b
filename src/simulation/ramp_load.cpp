#include "graspsim/simulation/ramp_load.h"

namespace graspsim::simulation {

namespace {

class RampLoadImpl : public SimTK::Force::Custom::Implementation {
public:
    RampLoadImpl(const SimTK::MobilizedBody& body, const RampLoad& owner) : body_(body), owner_(owner) {}

    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override {
        const double magnitude = owner_.findMagnitudeAt(s.getTime());
        if (magnitude == 0) return;
        const SimTK::Vec3 load = magnitude * SimTK::Vec3(owner_.getSpec().direction);
        if (owner_.getSpec().torque) {
            body_.applyBodyTorque(s, load, bodyForces);
        } else {
            body_.applyForceToBodyPoint(s, body_.getBodyMassCenterStation(s), load, bodyForces);
        }
    }
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
    // Time appears in the load: Simbody must not cache it across times.
    bool dependsOnlyOnPositions() const override { return false; }

private:
    const SimTK::MobilizedBody& body_;
    const RampLoad& owner_;
};

}  // namespace

RampLoad::RampLoad(SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& body, const LoadRampSpec& spec)
    : spec_(spec) {
    SimTK::Force::Custom(forces, new RampLoadImpl(body, *this));
}

double RampLoad::findMagnitudeAt(double t) const {
    return t >= spec_.start ? spec_.initial + spec_.rate * (t - spec_.start) : 0.0;
}

}  // namespace graspsim::simulation
