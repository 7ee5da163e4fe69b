#include "urdf_rotation.h"

#include <cmath>

namespace graspsim::model {

Vec3 calcRpyFromRotation(const Rotation& R) {
    // With R = Rz(y) Ry(p) Rx(r), column 0 is (cy cp, sy cp, -sp) and row 2 is (-sp, cp sr, cp cr).
    const double cosPitch = std::hypot(R[0], R[3]);
    const double pitch = std::atan2(-R[6], cosPitch);
    // At gimbal lock roll and yaw rotate about the same axis and only their sum matters, and
    // atan2 of two round-off-sized numbers is arbitrary; roll = 0 reads better and costs at most
    // about pi * cosPitch < 4e-15 in R.
    const double roll = cosPitch < 1e-15 ? 0.0 : std::atan2(R[7], R[8]);
    // Yaw from the part of R that remains once this roll is removed: these combinations equal
    // sin(yaw) and cos(yaw) for any roll, so an imprecise roll near gimbal lock cannot spoil R.
    const double sr = std::sin(roll), cr = std::cos(roll);
    const double yaw = std::atan2(sr * R[2] - cr * R[1], cr * R[4] - sr * R[5]);
    return {roll, pitch, yaw};
}

Rotation calcRotationFromRpy(const Vec3& rpy) {
    const double sr = std::sin(rpy[0]), cr = std::cos(rpy[0]);
    const double sp = std::sin(rpy[1]), cp = std::cos(rpy[1]);
    const double sy = std::sin(rpy[2]), cy = std::cos(rpy[2]);
    return {cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr,
            sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr,
            -sp,     cp * sr,                cp * cr};
}

Rotation calcRotationFromQuaternion(double x, double y, double z, double w) {
    return {1 - 2 * (y * y + z * z), 2 * (x * y - z * w),     2 * (x * z + y * w),
            2 * (x * y + z * w),     1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
            2 * (x * z - y * w),     2 * (y * z + x * w),     1 - 2 * (x * x + y * y)};
}

}  // namespace graspsim::model
