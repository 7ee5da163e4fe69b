#include "graspsim/integration/point_jacobian.h"

namespace graspsim::integration {

void addPointJacobian(const SimTK::SimbodyMatterSubsystem& matter, const SimTK::State& state,
                      SimTK::MobilizedBodyIndex body, const SimTK::Vec3& p_G, double sign, int rows,
                      std::vector<double>& J) {
    const int linear = rows == 6 ? 3 : 0;  // first row of the point's velocity
    for (SimTK::MobilizedBodyIndex k = body; k != SimTK::GroundIndex;) {
        const SimTK::MobilizedBody& mobod = matter.getMobilizedBody(k);
        const SimTK::Vec3 r = p_G - mobod.getBodyOriginLocation(state);
        const int first = mobod.getFirstUIndex(state);
        for (int i = 0; i < mobod.getNumU(state); ++i) {
            const SimTK::SpatialVec H = mobod.getHCol(state, SimTK::MobilizerUIndex(i));
            const SimTK::Vec3 velocity = H[1] + H[0] % r;
            double* column = &J[static_cast<std::size_t>(rows) * static_cast<std::size_t>(first + i)];
            for (int row = 0; row < 3; ++row) {
                column[linear + row] += sign * velocity[row];
                if (linear) column[row] += sign * H[0][row];
            }
        }
        k = mobod.getParentMobilizedBody().getMobilizedBodyIndex();
    }
}

void findNonzeroColumns(const std::vector<double>& J, int rows, int nu, std::vector<int>& columns) {
    columns.clear();
    for (int c = 0; c < nu; ++c) {
        for (int r = 0; r < rows; ++r) {
            if (J[r + static_cast<std::size_t>(rows) * c] != 0) {
                columns.push_back(c);
                break;
            }
        }
    }
}

}  // namespace graspsim::integration
