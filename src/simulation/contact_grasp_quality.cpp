#include "graspsim/simulation/contact_grasp_quality.h"

#include "graspsim/grasp/grasp_quality.h"
#include "graspsim/system/simtk_conversion.h"

namespace graspsim::simulation {

double calcContactGraspQuality(const std::vector<contact::ContactReport>& reports, const SimTK::Transform& X_GO,
                               const grasp::QualityOptions& options) {
    std::vector<grasp::GraspContact> contacts;
    for (const contact::ContactReport& r : reports) {
        if (!(r.normalForce > 0)) continue;
        grasp::GraspContact c;
        c.p_GC = system::toEigenVector(r.p_G);
        c.n_G = system::toEigenVector(SimTK::Vec3(r.n_G));
        c.normalForce = r.normalForce;
        contacts.push_back(c);
    }
    grasp::ObjectFrame frame;
    frame.R_GO = system::toEigenMatrix(X_GO.R());
    frame.p_GO = system::toEigenVector(X_GO.p());
    return grasp::calcGraspQuality(contacts, frame, options);
}

grasp::QualityOptions makeQualityOptions(const contact::ContactParameters& contact) {
    grasp::QualityOptions options;
    options.mu = contact.staticFriction;
    return options;
}

}  // namespace graspsim::simulation
