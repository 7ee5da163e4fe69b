// Grasp quality of hand-made contacts: three fingertips around a 3-cm ball, then the same grasp
// with one finger lifted. Needs no simulation: grasp quality is plain Eigen.

#include <graspsim/error.h>
#include <graspsim/grasp/grasp_quality.h>

#include <Eigen/Core>

#include <cmath>
#include <iostream>
#include <vector>

namespace {

// A contact on the sphere of radius r about the origin, at azimuth `angle` (rad) in the x-y
// plane, pushing toward the centre with 1 N.
graspsim::grasp::GraspContact makeContact(double r, double angle) {
    graspsim::grasp::GraspContact c;
    c.p_GC = Eigen::Vector3d(r * std::cos(angle), r * std::sin(angle), 0);  // m, ground
    c.n_G = -c.p_GC.normalized();                                           // into the object
    c.normalForce = 1;                                                      // N
    return c;
}

}  // namespace

int main() {
    const double pi = std::acos(-1.0), r = 0.03;
    graspsim::grasp::ObjectFrame ball;  // at the origin, axes along ground's
    graspsim::grasp::QualityOptions options;
    options.mu = 0.8;          // finger pad on plastic
    options.torqueScale = r;   // torques per ball radius, so forces and torques compare

    std::vector<graspsim::grasp::GraspContact> contacts = {makeContact(r, 0), makeContact(r, 2 * pi / 3),
                                                           makeContact(r, 4 * pi / 3)};
    try {
        for (auto metric : {graspsim::grasp::QualityMetric::MinSingularValue, graspsim::grasp::QualityMetric::FerrariCanny}) {
            options.metric = metric;
            const double three = graspsim::grasp::calcGraspQuality(contacts, ball, options);
            const std::vector<graspsim::grasp::GraspContact> two(contacts.begin(), contacts.begin() + 2);
            const double lifted = graspsim::grasp::calcGraspQuality(two, ball, options);
            std::cout << (metric == graspsim::grasp::QualityMetric::FerrariCanny ? "Ferrari-Canny epsilon" : "smallest singular value")
                      << ": three fingers " << three << ", one lifted " << lifted << "\n";
        }
    } catch (const graspsim::Error& e) {
        std::cerr << e.what() << "\n";
        return 2;
    }
    return 0;
}
