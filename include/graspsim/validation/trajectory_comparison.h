#pragma once
/// @file
/// Comparing two runs of one scenario sample by sample: how far the candidate's object (e.g. the
/// grasp approximation, or another integrator) strays from the reference's (full contact).

#include "graspsim/simulation/grasp_simulation.h"

#include <vector>

namespace graspsim::validation {

/// Object pose error of a candidate run against a reference run over a time window.
struct PoseErrors {
    int samples = 0;            ///< samples present in both runs inside the window
    double maxPosition = 0;     ///< largest |p_GO(candidate) - p_GO(reference)| (m)
    double rmsPosition = 0;     ///< root mean square of the same (m)
    double maxAngle = 0;        ///< largest rotation angle between the two orientations (rad)
    double rmsAngle = 0;        ///< root mean square of the same (rad)
};

/// One sample's error (for plots): time (s), position error (m), angle error (rad).
struct PoseErrorSample {
    double time = 0;
    double position = 0;
    double angle = 0;
};

/// Errors at every time present in both trajectories (to 1e-9 s), from `from` to `to` (s).
std::vector<PoseErrorSample> calcPoseErrorSeries(const std::vector<simulation::TrajectorySample>& reference,
                                                 const std::vector<simulation::TrajectorySample>& candidate,
                                                 double from, double to);

/// Max and RMS of calcPoseErrorSeries() over [from, to] (s).
PoseErrors comparePoses(const std::vector<simulation::TrajectorySample>& reference,
                        const std::vector<simulation::TrajectorySample>& candidate, double from, double to);

/// Slip onset: the first sample time after `settleTime` (s) at which the object's centre of mass
/// is more than `distance` (m) from where it was at `settleTime`; -1 if it never is.
double findSlipOnset(const std::vector<simulation::TrajectorySample>& trajectory, double settleTime, double distance);

/// Angle (rad, in [0, pi]) of the rotation between two orientations.
double calcRotationAngle(const SimTK::Quaternion& a, const SimTK::Quaternion& b);

}  // namespace graspsim::validation
