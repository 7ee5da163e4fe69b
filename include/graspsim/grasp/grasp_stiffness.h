#pragma once
/// @file
/// The stiffness of a grasp whose contacts all stick, at the load's start: how the contacts'
/// wrench on the object changes under a small displacement of the object (the compliance model of
/// compliant_grasp_capacity.h before any contact slides or opens).

#include "graspsim/grasp/compliant_grasp_capacity.h"

#include <Eigen/Core>

#include <vector>

namespace graspsim::grasp {

/// sum_i D_i K_i D_i^T - G (N/m, N, N m/rad; 6 x 6, rows and columns FORCE FIRST: [force ; moment]
/// by [dp ; theta], dp of the point at p_GO, m, in G): K_i each contact's sticking stiffness
/// (calcStickingStiffness), D_i = [I ; (C_i - p_GO)^] its wrench map, G the preload's rolling
/// stiffness (rolling_stiffness.h; zero for contacts without curvatures). A restoring stiffness: the
/// contacts' wrench changes by minus it times the displacement.
/// @throws graspsim::InputError for an invalid contact.
Eigen::Matrix<double, 6, 6> calcStickingGraspStiffness(const std::vector<CompliantContact>& contacts,
                                                       const Eigen::Vector3d& p_GO);

}  // namespace graspsim::grasp
