#include "step_interpolation.h"

namespace graspsim::integration {

void StepInterpolation::captureStart(const SimTK::State& start) {
    t0_ = start.getTime();
    y0_ = start.getY();
    yDot0_ = start.getYDot();
}

void StepInterpolation::interpolate(const SimTK::State& end, double t, SimTK::Vector& y) const {
    const double h = end.getTime() - t0_;
    const double s = h > 0 ? (t - t0_) / h : 1;
    const double s2 = s * s, s3 = s2 * s;
    const double h00 = 2 * s3 - 3 * s2 + 1, h10 = (s3 - 2 * s2 + s) * h, h01 = 3 * s2 - 2 * s3, h11 = (s3 - s2) * h;
    const SimTK::Vector& y1 = end.getY();
    const SimTK::Vector& yDot1 = end.getYDot();
    y.resize(y1.size());
    for (int i = 0; i < y1.size(); ++i) y[i] = h00 * y0_[i] + h10 * yDot0_[i] + h01 * y1[i] + h11 * yDot1[i];
}

DiscreteVariableKeys findReportVariables(const SimTK::State& state) {
    DiscreteVariableKeys keys;
    for (SimTK::SubsystemIndex s(0); s < state.getNumSubsystems(); ++s) {
        for (SimTK::DiscreteVariableIndex d(0); state.hasDiscreteVar({s, d}); ++d) {
            if (state.getDiscreteVarInvalidatesStage(s, d) >= SimTK::Stage::Report) keys.emplace_back(s, d);
        }
    }
    return keys;
}

bool hasAutoUpdateVariables(const SimTK::State& state) {
    for (SimTK::SubsystemIndex s(0); s < state.getNumSubsystems(); ++s) {
        for (SimTK::DiscreteVariableIndex d(0); state.hasDiscreteVar({s, d}); ++d) {
            if (state.getDiscreteVarUpdateIndex(s, d).isValid()) return true;
        }
    }
    return false;
}

void copyReportVariables(const DiscreteVariableKeys& keys, const SimTK::State& source, SimTK::State& target) {
    for (const auto& [s, d] : keys) target.updDiscreteVariable(s, d) = source.getDiscreteVariable(s, d);
}

}  // namespace graspsim::integration
