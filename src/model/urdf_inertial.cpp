#include "urdf_inertial.h"

#include "urdf_number.h"
#include "urdf_rotation.h"

#include "graspsim/model/geometry_inertia.h"

#include <algorithm>
#include <cmath>

namespace graspsim::model {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The URDF attributes as written, for messages.
std::string describeInertia(const urdf::Inertial& in) {
    return "ixx=" + formatUrdfNumber(in.ixx) + " iyy=" + formatUrdfNumber(in.iyy) + " izz=" + formatUrdfNumber(in.izz) +
           " ixy=" + formatUrdfNumber(in.ixy) + " ixz=" + formatUrdfNumber(in.ixz) + " iyz=" + formatUrdfNumber(in.iyz);
}

std::string describeMoments(const std::array<double, 3>& m) {
    return "(" + formatUrdfNumber(m[0]) + ", " + formatUrdfNumber(m[1]) + ", " + formatUrdfNumber(m[2]) + ")";
}

void checkInertia(const urdf::Inertial& in, const std::string& field, int line, const UrdfSource& source) {
    for (double v : {in.ixx, in.iyy, in.izz, in.ixy, in.ixz, in.iyz}) {
        if (!std::isfinite(v)) source.reject(line, field, describeInertia(in), "inertia components must be finite");
    }
    if (in.mass == 0) return;  // a virtual link; ModelDescription::validate decides what it may carry
    const std::array<double, 3> moments = calcPrincipalMoments(Inertia{in.ixx, in.iyy, in.izz, in.ixy, in.ixz, in.iyz});
    if (!(moments[0] > 0)) {
        source.reject(line, field, describeInertia(in),
                      "a link with mass needs a positive definite inertia, but its principal moments are " +
                          describeMoments(moments));
    }
    // Same relative slack as ModelDescription::validate, so both accept the same flat plates.
    const double slack = kInertiaTriangleTolerance * (moments[0] + moments[1] + moments[2]);
    if (moments[0] + moments[1] < moments[2] - slack) {
        source.reject(line, field, describeInertia(in),
                      "principal moments " + describeMoments(moments) +
                          " break the triangle inequality: the largest may not exceed the sum of the other two");
    }
}

}  // namespace

void setBodyMassProperties(const urdf::Inertial& in, int line, const UrdfSource& source, Body& body) {
    const std::string field = "link " + quoted(body.name) + " <inertial>";
    if (!std::isfinite(in.mass) || in.mass < 0) {
        source.reject(line, field + " <mass value>", formatUrdfNumber(in.mass), "mass must be finite and >= 0 kg");
    }
    checkInertia(in, field + " <inertia>", line, source);
    const urdf::Rotation& q = in.origin.rotation;
    Transform X_BI;
    X_BI.R = calcRotationFromQuaternion(q.x, q.y, q.z, q.w);
    body.mass = in.mass;
    body.p_BCm = {in.origin.position.x, in.origin.position.y, in.origin.position.z};
    body.inertia = reexpressInertia(Inertia{in.ixx, in.iyy, in.izz, in.ixy, in.ixz, in.iyz}, X_BI);
}

}  // namespace graspsim::model
