#pragma once
/// @file
/// A load on a body that grows linearly in time: the holding-capacity protocol's pull
/// (capacity/grasp_capacity.h), and with a zero rate its constant-load cross-check.

#include "graspsim/simbody.h"

namespace graspsim::simulation {

/// What the load is. Its magnitude is 0 before `start` and initial + rate (t - start) from it on.
struct LoadRampSpec {
    SimTK::UnitVec3 direction{1, 0, 0};  ///< in G
    bool torque = false;  ///< false: a force (N) at the centre of mass; true: a torque (N m) on the body
    double start = 0;     ///< s
    double initial = 0;   ///< N or N m at `start` (a step when non-zero: sample at `start`)
    double rate = 0;      ///< N/s or N m/s
};

/// Applies the load of a LoadRampSpec to body B: a force through B's centre of mass, or a pure
/// torque (a couple, so it turns B about its centre of mass without pushing it).
class RampLoad {
public:
    RampLoad(SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& body, const LoadRampSpec& spec);
    // The Simbody force element refers back to this object.
    RampLoad(const RampLoad&) = delete;
    RampLoad& operator=(const RampLoad&) = delete;

    /// The load's magnitude at time t (N or N m).
    double findMagnitudeAt(double t) const;
    const LoadRampSpec& getSpec() const { return spec_; }
    /// Sets the load anew (its start too): between runs of one system that share the stretch before
    /// the load (capacity/settled_grasps.h). A State realized past Stage::Time under the old load
    /// must have its Dynamics-stage cache invalidated.
    void setSpec(const LoadRampSpec& spec) { spec_ = spec; }

private:
    LoadRampSpec spec_;
};

}  // namespace graspsim::simulation
