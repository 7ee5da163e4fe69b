#include "graspsim/simulation/contact_grasp_quality.h"

#include "graspsim/grasp/grasp_quality.h"

namespace graspsim::simulation {

namespace {

Eigen::Vector3d toEigen(const SimTK::Vec3& v) { return {v[0], v[1], v[2]}; }

}  // namespace

double calcContactGraspQuality(const std::vector<contact::ContactReport>& reports, const SimTK::Transform& X_GO,
                               const grasp::QualityOptions& options) {
    std::vector<grasp::GraspContact> contacts;
    for (const contact::ContactReport& r : reports) {
        if (!(r.normalForce > 0)) continue;
        grasp::GraspContact c;
        c.p_GC = toEigen(r.p_G);
        c.n_G = toEigen(SimTK::Vec3(r.n_G));
        c.normalForce = r.normalForce;
        contacts.push_back(c);
    }
    grasp::ObjectFrame frame;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) frame.R_GO(i, j) = X_GO.R().asMat33()(i, j);
    frame.p_GO = toEigen(X_GO.p());
    return grasp::calcGraspQuality(contacts, frame, options);
}

grasp::QualityOptions makeQualityOptions(const contact::ContactParameters& contact) {
    grasp::QualityOptions options;
    options.mu = contact.staticFriction;
    return options;
}

}  // namespace graspsim::simulation
