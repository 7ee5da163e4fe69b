#include "graspsim/grasp/grasp_attachment.h"

namespace graspsim::grasp {

SimTK::SpatialVec shiftToObjectOrigin(const SimTK::SpatialVec& W_M, const SimTK::Rotation& R_GO,
                                      const SimTK::Vec3& p_OM) {
    const SimTK::Vec3 p_OM_G = R_GO * p_OM;
    return SimTK::SpatialVec(W_M[0] + p_OM_G % W_M[1], W_M[1]);
}

}  // namespace graspsim::grasp
