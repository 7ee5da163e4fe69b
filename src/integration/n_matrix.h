#pragma once
// N(q) of qdot = N(q) u, captured at one configuration as its per-mobilizer blocks, so that it can
// be applied after the State has moved on: the ROS2 step needs N(q0) for its final combination
// after its second stage has realized the State elsewhere, and realizing Stage::Position at q0
// again only for that cost about a twentieth of a step.

#include "graspsim/simbody.h"

#include <vector>

namespace graspsim::integration {

class NMatrix {
public:
    // N at `state` (realized through Position): max(nu) products N e with unit speeds set in every
    // mobilizer at once (N is block diagonal by mobilizer), each an O(bodies) pass.
    void capture(const SimTK::SimbodyMatterSubsystem& matter, const SimTK::State& state);
    // N u with the N captured; `qdot` gets nq entries.
    void multiply(const std::vector<double>& u, SimTK::Vector& qdot) const;

private:
    struct Block {
        int firstQ = 0, nq = 0, firstU = 0, nu = 0;
        std::vector<double> n;  // nq x nu, column-major
    };
    std::vector<Block> blocks_;
    int nq_ = 0;
    SimTK::Vector unit_, column_;  // reused by capture()
};

}  // namespace graspsim::integration
