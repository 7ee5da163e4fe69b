#include "graspsim/validation/trajectory_comparison.h"

#include <algorithm>
#include <cmath>

namespace graspsim::validation {

double calcRotationAngle(const SimTK::Quaternion& a, const SimTK::Quaternion& b) {
    // q and -q are the same rotation, hence the absolute value of the 4-D dot product.
    const double dot = std::abs(~a.asVec4() * b.asVec4());
    return 2 * std::acos(std::min(1.0, dot));
}

std::vector<PoseErrorSample> calcPoseErrorSeries(const std::vector<simulation::TrajectorySample>& reference,
                                                 const std::vector<simulation::TrajectorySample>& candidate,
                                                 double from, double to) {
    constexpr double kSameTime = 1e-9;  // s; both runs sample at the same output instants
    std::vector<PoseErrorSample> series;
    auto c = candidate.begin();
    for (const simulation::TrajectorySample& r : reference) {
        if (r.time < from - kSameTime || r.time > to + kSameTime) continue;
        while (c != candidate.end() && c->time < r.time - kSameTime) ++c;
        if (c == candidate.end()) break;
        if (std::abs(c->time - r.time) > kSameTime) continue;
        series.push_back({r.time, (c->p_GO - r.p_GO).norm(), calcRotationAngle(c->q_GO, r.q_GO)});
    }
    return series;
}

PoseErrors comparePoses(const std::vector<simulation::TrajectorySample>& reference,
                        const std::vector<simulation::TrajectorySample>& candidate, double from, double to) {
    PoseErrors e;
    double sumPosition = 0, sumAngle = 0;
    for (const PoseErrorSample& s : calcPoseErrorSeries(reference, candidate, from, to)) {
        ++e.samples;
        e.maxPosition = std::max(e.maxPosition, s.position);
        e.maxAngle = std::max(e.maxAngle, s.angle);
        sumPosition += s.position * s.position;
        sumAngle += s.angle * s.angle;
    }
    if (e.samples > 0) {
        e.rmsPosition = std::sqrt(sumPosition / e.samples);
        e.rmsAngle = std::sqrt(sumAngle / e.samples);
    }
    return e;
}

double findSlipOnset(const std::vector<simulation::TrajectorySample>& trajectory, double settleTime, double distance) {
    const auto settled = std::find_if(trajectory.begin(), trajectory.end(),
                                      [&](const simulation::TrajectorySample& t) { return t.time >= settleTime - 1e-12; });
    if (settled == trajectory.end()) return -1;
    for (auto t = settled; t != trajectory.end(); ++t) {
        if ((t->p_GO - settled->p_GO).norm() > distance) return t->time;
    }
    return -1;
}

}  // namespace graspsim::validation
