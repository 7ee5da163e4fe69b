#pragma once
// Where a force element switches regime inside a step: a term of the Jacobian contributors' active
// set (ForceJacobianContributor::appendActiveSet) that was active at the step's start is gone at
// its end (a contact starts sliding or stops pushing, a limit stop disengages). ROS2's two stages
// and its embedded first-order solution share the start's matrix W, which keeps that term's
// stiffness past the switch, and the second stage rarely lands beyond it: the error estimate
// cannot see the switch (a box pulled loose from sticking friction ended a 5 ms step near the
// sticking law's viscous equilibrium, its estimate 0.006 of the accuracy). So such a step is taken
// again, toward the switch (estimated from the lost terms' margins where the elements give them,
// else bisecting), until one that crosses it is no longer than the window.
// Terms that appear (a contact touching, sliding turning to sticking) are not localized: the step
// treats them explicitly, and their force shows in the second stage and the error estimate.

#include "graspsim/simbody.h"

#include <cstdint>
#include <vector>

namespace graspsim::integration {

class SwitchLocalization {
public:
    // A switch is localized to within `window` (s, > 0).
    explicit SwitchLocalization(double window) : window_(window) {}
    // Simbody's event localization window for an integrator at `accuracy`: accuracy x the
    // System's time scale x an event trigger's default window (0.1 of the time scale); 10 us at
    // accuracy 1e-3 and the default time scale 0.1 s.
    static double findWindow(const SimTK::System& system, double accuracy);
    // The terms of `start` missing from `end` (both as the stepper collects them, each term tagged
    // with its contributor; counted with multiplicity), sorted; empty when no term is lost.
    static std::vector<std::int64_t> findLostTerms(std::vector<std::int64_t> start, std::vector<std::int64_t> end);

    double getWindow() const { return window_; }
    // The step from t (s), at most h (s), with a switch bracketed ahead: with an estimate of the
    // switch's time (setEstimate) ahead, to half a window short of it and then one window across
    // it; without one, half the way to the bracket's end while that is longer than the window;
    // then the rest of the way.
    double limitStep(double t, double h) const;
    // After a step of h from t that lost a term: true if it is to be taken again (the switch is now
    // bracketed in (t, t + h]); false when h is within the window (localized: the step stands).
    bool crossed(double t, double h);
    // After crossed() returned true: the switch's estimated time (s), interpolated from the lost
    // terms' margins at the step's two ends; NaN for none. Up to kMaxEstimates per switch; past
    // them (a margin that is far from linear over the bracket) the bracket is bisected.
    void setEstimate(double time);
    void clear() {
        end_ = -SimTK::Infinity;
        estimate_ = SimTK::NaN;
        estimates_ = 0;
    }

    static constexpr int kMaxEstimates = 3;

private:
    double window_;
    double end_ = -SimTK::Infinity;  // s, the bracket's end; none once passed
    double estimate_ = SimTK::NaN;   // s
    int estimates_ = 0;              // for the switch bracketed now
};

}  // namespace graspsim::integration
