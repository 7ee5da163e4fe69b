#include "graspsim/model/sagittal_mirror.h"

namespace graspsim::model {

namespace {

Vec3 mirrorPoint(const Vec3& p) { return {p[0], p[1], -p[2]}; }

Transform mirrorTransform(const Transform& X) {
    Transform Y = X;
    // M R M with M = diag(1, 1, -1): negate the entries of row 2 and column 2 once each.
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            const double sign = ((i == 2) != (j == 2)) ? -1.0 : 1.0;
            Y.R[3 * i + j] = sign * X.R[3 * i + j];
        }
    }
    Y.p = mirrorPoint(X.p);
    return Y;
}

}  // namespace

void mirrorSagittally(ModelDescription& model, std::size_t firstBody, std::size_t firstJoint,
                      std::size_t firstEndEffector) {
    for (std::size_t k = firstBody; k < model.bodies.size(); ++k) {
        Body& b = model.bodies[k];
        b.p_BCm = mirrorPoint(b.p_BCm);
        b.inertia.xz = -b.inertia.xz;
        b.inertia.yz = -b.inertia.yz;
        for (Geometry& g : b.geometry) g.X_BG = mirrorTransform(g.X_BG);
    }
    for (std::size_t k = firstJoint; k < model.joints.size(); ++k) {
        Joint& j = model.joints[k];
        j.X_PJ = mirrorTransform(j.X_PJ);
        j.axis = {-j.axis[0], -j.axis[1], j.axis[2]};
    }
    for (std::size_t k = firstEndEffector; k < model.endEffectors.size(); ++k) {
        model.endEffectors[k].p_BE = mirrorPoint(model.endEffectors[k].p_BE);
    }
}

}  // namespace graspsim::model
