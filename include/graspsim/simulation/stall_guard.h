#pragma once
/// @file
/// The stall guard of a run: a stepper whose mean step over an advance of at least
/// kStallWindow falls below kStalledMeanStep has stalled. Contacts that chatter do this (the
/// planned key-lateral, once the key pivots into the index finger's crease: mean steps of
/// 0.5-0.9 us on the implicit stepper and on CPodes), and would hold a run for hours. The run then
/// ends with the failure named, as on an integrator failure (`simulate`: summary.json marked
/// incomplete, exit 3; `capacity`: the ramp's trace ends there).

#include <string>

namespace graspsim::simulation {

/// s: a mean step below this over kStallWindow is a stall. The thesis scenes' 18 capacity cells
/// give the same capacity.json and capacity.csv with the guard as without it, and no run of the
/// test suite (`validate --quick` among them) reaches it.
inline constexpr double kStalledMeanStep = 1e-6;
/// s: the shortest advance the mean is taken over.
inline constexpr double kStallWindow = 1e-3;

/// Throws graspsim::NumericalError "`who`: the integrator stalled between t = `from` and `to` s:
/// N steps, a mean step of ..." when `steps` steps advanced a run from `from` to `to` (s) at a
/// mean step below kStalledMeanStep, over at least kStallWindow; returns otherwise.
void checkNotStalled(const std::string& who, double from, double to, long steps);

}  // namespace graspsim::simulation
