// Simbody's CPodes behind the Stepper interface (the grasp simulations' default) on a pendulum. Oracles: a restart continues exactly as a
// stepper started fresh from the same state would (bit for bit), and restarting does not grow
// the heap (re-initializing one Simbody 3.7 CPodesIntegrator leaked ~8 kB each time).

#include "graspsim/integration/simbody_stepper.h"

#include "live_heap.h"

#include <simbody/Simbody.h>
#include <gtest/gtest.h>

using graspsim::integration::SimbodyCpodesStepper;

namespace {

struct Pendulum {
    Pendulum() : matter(system), forces(system), gravity(forces, matter, SimTK::Vec3(0, -9.81, 0)) {
        const SimTK::Body::Rigid body(SimTK::MassProperties(1.0, SimTK::Vec3(0), SimTK::Inertia(0.01)));
        pin = SimTK::MobilizedBody::Pin(matter.Ground(), SimTK::Transform(), body, SimTK::Vec3(0, 0.5, 0));
        system.realizeTopology();
    }
    SimTK::State makeState() const {
        SimTK::State s = system.getDefaultState();
        pin.setOneQ(s, 0, 1.0);  // rad
        return s;
    }
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter;
    SimTK::GeneralForceSubsystem forces;
    SimTK::Force::Gravity gravity;
    SimTK::MobilizedBody::Pin pin;
};

}  // namespace

TEST(SimbodyCpodesStepper, RestartContinuesLikeAFreshStepper) {
    const Pendulum p;
    SimbodyCpodesStepper restarted(p.system, 1e-6);
    restarted.initialize(p.makeState());
    restarted.stepTo(0.1);
    const SimTK::State atRestart = restarted.getState();
    restarted.initialize(atRestart);
    restarted.stepTo(0.3);
    SimbodyCpodesStepper fresh(p.system, 1e-6);
    fresh.initialize(atRestart);
    fresh.stepTo(0.3);
    EXPECT_EQ(restarted.getState().getTime(), fresh.getState().getTime());
    EXPECT_EQ(restarted.getState().getQ()[0], fresh.getState().getQ()[0]);
    EXPECT_EQ(restarted.getState().getU()[0], fresh.getState().getU()[0]);
    EXPECT_EQ(restarted.getNumStepsTaken(), fresh.getNumStepsTaken());
    EXPECT_GT(restarted.getNumStepsTaken(), 0);
}

TEST(SimbodyCpodesStepper, RestartsDoNotGrowTheHeap) {
    const Pendulum p;
    SimbodyCpodesStepper stepper(p.system, 1e-6);
    const SimTK::State start = p.makeState();
    const auto restart = [&] {
        stepper.initialize(start);
        stepper.stepTo(0.01);
    };
    for (int k = 0; k < 10; ++k) restart();  // first-use allocations
    const double before = graspsim::testing::findLiveHeapBytes();
    for (int k = 0; k < 100; ++k) restart();
    // 100 leaked vector sets would be several hundred kB; the bound leaves room for allocator noise.
    EXPECT_LT(graspsim::testing::findLiveHeapBytes() - before, 50e3);
}
