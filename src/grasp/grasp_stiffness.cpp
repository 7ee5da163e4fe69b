#include "graspsim/grasp/grasp_stiffness.h"

#include "graspsim/grasp/grasp_matrix.h"
#include "graspsim/grasp/rolling_stiffness.h"

namespace graspsim::grasp {

Eigen::Matrix<double, 6, 6> calcStickingGraspStiffness(const std::vector<CompliantContact>& contacts,
                                                       const Eigen::Vector3d& p_GO) {
    Eigen::Matrix<double, 6, 6> total = -calcRollingStiffness(contacts, p_GO);
    for (const CompliantContact& c : contacts) {
        const Eigen::Matrix<double, 6, 3> map = calcContactWrenchMap(c.p_GC - p_GO, 1.0);
        total += map * calcStickingStiffness(c) * map.transpose();
    }
    return total;
}

}  // namespace graspsim::grasp
