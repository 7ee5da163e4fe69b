#include "n_matrix.h"

#include <algorithm>

namespace graspsim::integration {

void NMatrix::capture(const SimTK::SimbodyMatterSubsystem& matter, const SimTK::State& state) {
    // The blocks follow the mobilizers' q and u counts, which are Model-stage (quaternions or angles).
    if (state.getNQ() != nq_ || state.getNU() != unit_.size()) blocks_.clear();
    nq_ = state.getNQ();
    if (blocks_.empty()) {
        for (SimTK::MobilizedBodyIndex b(1); b < matter.getNumBodies(); ++b) {
            const SimTK::MobilizedBody& mobod = matter.getMobilizedBody(b);
            Block block{mobod.getFirstQIndex(state), mobod.getNumQ(state), mobod.getFirstUIndex(state), mobod.getNumU(state), {}};
            if (block.nu == 0) continue;
            block.n.assign(static_cast<std::size_t>(block.nq * block.nu), 0.0);
            blocks_.push_back(std::move(block));
        }
    }
    int widest = 0;
    for (const Block& b : blocks_) widest = std::max(widest, b.nu);
    unit_.resize(state.getNU());
    for (int k = 0; k < widest; ++k) {
        unit_ = 0;
        for (const Block& b : blocks_)
            if (k < b.nu) unit_[b.firstU + k] = 1;
        matter.multiplyByN(state, false, unit_, column_);
        for (Block& b : blocks_) {
            if (k >= b.nu) continue;
            for (int i = 0; i < b.nq; ++i) b.n[static_cast<std::size_t>(i + b.nq * k)] = column_[b.firstQ + i];
        }
    }
}

void NMatrix::multiply(const std::vector<double>& u, SimTK::Vector& qdot) const {
    qdot.resize(nq_);
    qdot = 0;
    for (const Block& b : blocks_) {
        for (int k = 0; k < b.nu; ++k) {
            const double uk = u[static_cast<std::size_t>(b.firstU + k)];
            for (int i = 0; i < b.nq; ++i) qdot[b.firstQ + i] += b.n[static_cast<std::size_t>(i + b.nq * k)] * uk;
        }
    }
}

}  // namespace graspsim::integration
