#include "graspsim/simulation/object_loads.h"

#include "graspsim/error.h"

namespace graspsim::simulation {

ObjectLoads::ObjectLoads(system::MultibodyModel& model, const SimTK::MobilizedBody& object,
                         const scenario::Scenario& scenario, const SimulationOptions& options) {
    if (options.perturbation != "none") {
        const scenario::Perturbation* p = scenario.findPerturbation(options.perturbation);
        if (!p) {
            throw InputError("--perturbation: '" + options.perturbation + "' is not a perturbation of scenario '" +
                             scenario.name + "'; use none or one the scenario defines");
        }
        const SimTK::Vec3 F_G(p->force[0], p->force[1], p->force[2]);
        perturbation_ = std::make_unique<PerturbationForce>(model.updForces(), object, F_G, p->start, p->duration);
    }
    if (options.loadRamp) loadRamp_ = std::make_unique<RampLoad>(model.updForces(), object, *options.loadRamp);
}

SimTK::SpatialVec ObjectLoads::findWrenchAt(double t) const {
    SimTK::SpatialVec wrench(SimTK::Vec3(0), SimTK::Vec3(0));
    if (perturbation_) wrench[1] += perturbation_->findForceAt(t);
    if (loadRamp_) {
        const LoadRampSpec& spec = loadRamp_->getSpec();
        wrench[spec.torque ? 0 : 1] += loadRamp_->findMagnitudeAt(t) * SimTK::Vec3(spec.direction);
    }
    return wrench;
}

}  // namespace graspsim::simulation
