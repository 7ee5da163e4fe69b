#pragma once
/// @file
/// The thesis's Table 5.1 measured on this machine (`graspsim bench`): what one step of full
/// contact costs (IK and dynamics apart), what the engaged approximation costs, the floor
/// (same model, no object, no contact), and how full contact grows with the end-effectors.
///
/// Two kinds of figures, both from one run each, measured in the same process:
///  - per integrator step and per simulated second, from the phases of a simulation
///    (SimulationSummary: full-contact phase vs first engagement; the approximation's per
///    simulated second figures over its first second engaged and over the 20 s of hold after
///    it, with the time spent timing evaluations during the run taken out; and the floor state
///    below integrated for 20 s the same way, in wall time and in dynamics evaluations, a count
///    that is the same on any machine). The variable-step integrator takes longer steps
///    once contact is gone, so per simulated second is the fair comparison: it is what a
///    fixed-step engine's cost per step (the thesis's) measures. Wall times on a shared machine
///    drift by tens of per cent over a minute, so the hold is also compared with its own floor
///    timed back to back with it, window by window (ApproxCost::holdOverOwnFloor);
///  - per dynamics evaluation (one realization of the system to Stage::Acceleration from
///    Stage::Time, i.e. one right-hand side of the ODE, what every integrator step pays at
///    least once): in the full-contact state just before the approximation engages, in the
///    engaged state, and in the floor state: the grasped hand with fingers and object locked
///    where they are and no contact (the same arm and merged hand with no object dynamics and
///    no contact), in the full-contact run's System (ExperimentCost) and, for comparison, in
///    the approximation run's own System with its constraint off (ApproxCost). This is the
///    thesis's "time to solve the contacts of one step".

#include "graspsim/validation/capacity_cost.h"
#include "graspsim/validation/stepper_cost.h"

#include <functional>
#include <string>
#include <vector>

namespace graspsim::validation {

/// The approximation's figures with one realization of its constraint.
struct ApproxCost {
    std::string constraint;              ///< "bushing" or "weld"
    double stepUs = 0;                   ///< µs per integrator step during the first engagement
    double wallPerSimSecond = 0;         ///< wall s per simulated s, first simulated second engaged
    double holdWallPerSimSecond = 0;     ///< wall s per simulated s over the 20 s of hold after that (median of 1-s windows)
    /// The floor state in this run's System (its constraint off), integrated one simulated second
    /// after each second of the hold (20 s), wall s per simulated s (median of 1-s windows).
    double ownFloorHoldWallPerSimSecond = 0;
    /// Hold / own floor, wall time: the median over the 20 pairs of windows timed back to back,
    /// the figure least moved by a machine that slows down for a while.
    double holdOverOwnFloor = 0;
    /// Dynamics evaluations (System realizations of Stage::Acceleration) per simulated s over the
    /// hold, and over the own floor's 20 s: counts, the same on any machine, unlike wall times.
    double holdEvaluationsPerSimSecond = 0;
    double ownFloorEvaluationsPerSimSecond = 0;
    double engageTime = -1;              ///< s; < 0 if it never engaged (then no figures)
    double fullRealizeUs = 0;            ///< one dynamics evaluation, full contact just before engaging (µs)
    double engagedRealizeUs = 0;         ///< one dynamics evaluation, engaged (µs)
    double ownFloorRealizeUs = 0;        ///< the floor state in this run's System, its constraint off (µs)
};

/// The figures of one experiment.
struct ExperimentCost {
    std::string scenario;
    // Full-contact run (IK every ik_interval, all contacts), per integrator step (µs).
    double fullStepUs = 0;
    double fullIkUsPerStep = 0;
    double fullDynamicsUsPerStep = 0;
    double fullWallPerSimSecond = 0;     ///< wall s per simulated s, after the object's release
    /// The floor in the full-contact run's System, which holds no approximation elements: its last
    /// state with fingers and object locked and every pair off, integrated for 20 s (wall s per
    /// simulated s, median of 1-s windows) and one dynamics evaluation of it (µs). Both rows'
    /// hold/floor use it; ApproxCost has the floor in the approximation's own System beside it.
    double floorHoldWallPerSimSecond = 0;
    double floorEvaluationsPerSimSecond = 0;  ///< the floor's dynamics evaluations per simulated s (a count)
    double floorRealizeUs = 0;
    std::vector<ApproxCost> approx;      ///< bushing, then weld
    /// Full contact per stepper (CPodes, the default; the linearly implicit stepper), each in a run
    /// of its own, then the approximations' holds and the floor, side by side (stepper_cost.h).
    std::vector<StepperCost> steppers;
};

/// Full-contact cost with `endEffectors` fingertip goals (thumb first, then index, middle, ...).
struct EndEffectorCost {
    int endEffectors = 0;
    double stepUs = 0, ikUsPerStep = 0, dynamicsUsPerStep = 0;
    double realizeUs = 0;                ///< one dynamics evaluation at the end of the run (µs)
};

struct CostTable {
    std::vector<ExperimentCost> experiments;
    std::vector<EndEffectorCost> scaling;  ///< ball-clutch with 2 .. 5 fingertip goals
    /// A capacity ramp against a 3 s simulation, both experiments, full and approx, CPodes and the
    /// linearly implicit stepper (capacity_cost.h).
    std::vector<CapacityCost> capacity;
    double wallTime = 0;                   ///< s, the whole measurement
};

/// Called before each of the table's measurements with how many are done, how many there are, and
/// what comes next (e.g. "ball-clutch", "3 end-effectors").
using CostProgress = std::function<void(std::size_t done, std::size_t total, const std::string& next)>;

/// Measures the table. `duration`: simulated s of each run (>= the settle time + 0.5 s so that
/// the approximation has engaged for a while); `realizations`: dynamics evaluations per timing;
/// `progress` (may be empty) is told before each measurement and once at the end.
CostTable measureCostTable(double duration = 2.0, int realizations = 400, const CostProgress& progress = {});

/// The table as text, with the thesis's Table 5.1 figures beside ours.
std::string formatCostTable(const CostTable& table);
/// The table as JSON (field names as in the structs, snake_case, units in the names).
std::string formatCostTableJson(const CostTable& table);

}  // namespace graspsim::validation
