#pragma once
/// @file
/// The files of `graspsim capacity --out DIR`:
/// - capacity.json: scenario, then one entry per measurement: direction (name and unit vector in
///   G), load ("force" or "torque"), method, contact, mode, realization (null in full mode),
///   load_start_s, rate (N/s or N m/s, ramp), slip_threshold_m, drop_threshold_m, and either
///   slip_onset_n / drop_n (force) or slip_onset_nm / drop_nm (torque), with slip_onset_time_s and
///   drop_time_s; null where the object did not slip or drop within the ramp. Bisection entries
///   give the slip onset as the bracket's middle, and bracket_held / bracket_slipped, and no drop.
///   Approx-mode entries add release_n / release_nm and release_time_s: when the approximation
///   handed the object back to full contact during the load (null if it did not).
///   Constant-load entries (method "constant", overload.h) give load_n / load_nm and hold_s instead
///   of the onset and drop loads, and slip_onset_time_s, drop_time_s and (approx) release_time_s as
///   seconds AFTER the load's start (load_start_s), null where it did not happen within the hold.
///   Ramp and constant-load entries give grip_force_start_n and grip_force_onset_n (N, the summed
///   normal forces of the finger-object contacts at the load's start and at the slip onset; null
///   where the approximation was engaged, or without slip).
/// - capacity.csv: the ramps' and constant loads' time series: direction, load kind, time (s), load (N or N m), slip
///   (m), rotation relative to the palm (rad), held (1/0), engaged (1/0 in approx mode, -1 in full mode),
///   grip_force_n (N; empty while the approximation is engaged).
/// Each file is written whole to a temporary name and renamed.

#include "graspsim/capacity/grasp_capacity.h"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace graspsim::capacity {

std::string formatCapacityJson(const std::string& scenario, const std::vector<GraspCapacity>& measurements);
std::string formatCapacityCsv(const std::vector<GraspCapacity>& measurements);
/// The one-line statement of a measurement's figures, e.g. "-y force (ramp): slips at 1.2 N, drops at 1.5 N".
std::string describeCapacity(const GraspCapacity& c);
/// The figures of one entry of capacity.json's "measurements", as formatCapacityJson writes it, in
/// the words of describeCapacity (without its direction, failure and release): "slips at 1.2 N,
/// drops at 1.5 N", "no slip up to 3 N", "not measured" (a ramp without samples), "slips after
/// 0.12 s, drops after 0.4 s of 2.5 N held 1 s" (constant), "slips from 2.1 N (held 2, slipped
/// 2.2)" (bisection). A figure that is absent or null was not reached.
std::string describeMeasuredFigures(const nlohmann::json& measurement);

/// Writes capacity.json and capacity.csv into `folder`, which must exist.
/// @throws graspsim::InputError naming the file when it cannot be written.
void writeCapacityFiles(const std::string& folder, const std::string& scenario, const std::vector<GraspCapacity>& measurements);

}  // namespace graspsim::capacity
