#pragma once
// The error-controlled stepper's choice of step sizes: the next step from the last one's error
// estimate (second-order rule) and the steps that reach a stop without leaving a sliver.

namespace graspsim::integration {

class StepSizeControl {
public:
    // Steps no longer than `longest` (s, > 0).
    explicit StepSizeControl(double longest) : longest_(longest) {}
    // The next step's proposal p = min(the error's next step, the longest), s.
    double getProposal() const;
    // The next step toward a stop `remaining` (s, > 0) ahead (see the .cpp).
    double findStepToStop(double remaining) const;
    // After a step of h (s) whose error estimate (in units of the accuracy) is `error`: true if it
    // is accepted (error <= 1, or h at most kMinStepSize); either way the next proposal follows.
    bool acceptStep(double h, double error);
    // After a jump in the inputs (a landing time): the next step is `h` (s, > 0), growing from there
    // by the error's rule, as the first steps after a localized switch do.
    void restart(double h);

    static constexpr double kMinStepSize = 1e-8;  // s; a step this short is accepted whatever its error

private:
    // Equal steps to a stop at the cap (findStepToStop): up to this many, when the proposal is
    // within this factor of the cap.
    static constexpr double kMaxEqualSteps = 4, kStepStretch = 1.15;
    double longest_;
    double next_ = 1e300;  // s, from the last step's error; none yet
    bool justRejected_ = false;
};

}  // namespace graspsim::integration
