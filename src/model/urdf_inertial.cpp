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
    const double slack = 1e-12 * (moments[0] + moments[1] + moments[2]);
    if (moments[0] + moments[1] < moments[2] - slack) {
        source.reject(line, field, describeInertia(in),
                      "principal moments " + describeMoments(moments) +
                          " break the triangle inequality: the largest may not exceed the sum of the other two");
    }
}

}  // namespace

std::array<double, 3> calcPrincipalMoments(const Inertia& I) {
    // Closed-form eigenvalues of a symmetric 3x3 matrix (Smith 1961): with q = trace/3 and
    // B = (A - q 1)/p, the eigenvalues are q + 2p cos(phi + 2 pi k/3), phi = acos(det(B)/2)/3.
    const double offDiagonal = I.xy * I.xy + I.xz * I.xz + I.yz * I.yz;
    std::array<double, 3> moments{I.xx, I.yy, I.zz};
    if (offDiagonal > 0) {
        const double q = (I.xx + I.yy + I.zz) / 3;
        const double a = I.xx - q, b = I.yy - q, c = I.zz - q;
        const double p = std::sqrt((a * a + b * b + c * c + 2 * offDiagonal) / 6);
        const double det = a * (b * c - I.yz * I.yz) - I.xy * (I.xy * c - I.yz * I.xz) + I.xz * (I.xy * I.yz - b * I.xz);
        const double r = std::clamp(det / (2 * p * p * p), -1.0, 1.0);
        const double phi = std::acos(r) / 3;
        moments[2] = q + 2 * p * std::cos(phi);
        moments[0] = q + 2 * p * std::cos(phi + 2 * kPi / 3);
        moments[1] = 3 * q - moments[0] - moments[2];
    }
    std::sort(moments.begin(), moments.end());
    return moments;
}

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
