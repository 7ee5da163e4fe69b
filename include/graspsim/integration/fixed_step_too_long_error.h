#pragma once
/// @file
/// The error of a fixed-step run whose step cannot be trusted (linearly_implicit_stepper.h).

#include "graspsim/error.h"

#include <cstdio>
#include <string>

namespace graspsim::integration {

/// Thrown by the linearly implicit stepper at fixed steps (ROS2, no error control) when a step's
/// embedded error estimate reaches the state's own scale: the step's second-order solution and
/// its embedded first-order one disagree by as much as the state itself, so neither approximates
/// the step (LinearlyImplicitStepper::kUntrustedStepEstimate). A step size not accepted for this
/// System: an InputError; callers that know where the step came from (an option, a file) say so.
class FixedStepTooLongError : public InputError {
public:
    /// `stepSize` (s), the step's start `time` (s) and its `estimate` (weighted RMS over the
    /// state's scale, 1 + |y| per entry).
    FixedStepTooLongError(double stepSize, double time, double estimate)
        : InputError(describe(stepSize, time, estimate)), stepSize_(stepSize), time_(time), estimate_(estimate) {}
    double getStepSize() const { return stepSize_; }
    double getTime() const { return time_; }
    double getEstimate() const { return estimate_; }

private:
    static std::string describe(double stepSize, double time, double estimate) {
        char text[320];
        std::snprintf(text, sizeof text,
                      "fixed step %g s: the step from t = %.4f s has an error estimate %.3g times the state's own "
                      "scale (its second- and first-order solutions disagree entirely); use a shorter step or error "
                      "control",
                      stepSize, time, estimate);
        return text;
    }

    double stepSize_, time_, estimate_;
};

}  // namespace graspsim::integration
