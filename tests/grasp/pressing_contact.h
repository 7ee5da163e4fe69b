#pragma once
// A compliance-model contact pressing along its normal, shared by the compliance model's tests.

#include "graspsim/grasp/compliant_grasp_capacity.h"

#include <Eigen/Core>

namespace graspsim::grasp::examples {

// Contact at p pressing the object along n (normalized) with force normalForce (N), normal and
// tangential stiffnesses kn and kt (N/m) and an isotropic finger compliance (m/N).
inline CompliantContact makePressingContact(const Eigen::Vector3d& p, const Eigen::Vector3d& n, double normalForce, double kn,
                                            double kt, double fingerCompliance = 0) {
    CompliantContact c;
    c.p_GC = p;
    c.n_G = n.normalized();
    c.force_G = normalForce * c.n_G;
    c.normalStiffness = kn;
    c.tangentialStiffness = kt;
    c.fingerCompliance_G = fingerCompliance * Eigen::Matrix3d::Identity();
    return c;
}

}  // namespace graspsim::grasp::examples
