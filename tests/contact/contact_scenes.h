#pragma once
// Small Simbody scenes for the contact force tests: a system, its subsystems, and helpers for
// bodies that slide along one Ground axis. Frames: Ground G, y up.

#include <simbody/Simbody.h>

#include <cmath>
#include <string>
#include <vector>

#include "graspsim/contact/compliant_contact_force.h"
#include "graspsim/contact/contact_force_law.h"

namespace graspsim::contact::test {

/// Ground pose of a half-space whose outward normal z_S is Ground's +y (a floor at y = 0).
inline SimTK::Transform makeFloorPose() {
    return SimTK::Transform(SimTK::Rotation(-SimTK::Pi / 2, SimTK::XAxis), SimTK::Vec3(0));
}

/// A pair's parameters: effective stiffness E* (Pa), dissipation (s/m), friction, no viscous
/// friction, transition velocity (m/s).
inline ContactParameters makeParameters(double effectiveStiffness, double dissipation,
                                        double staticFriction = 0, double dynamicFriction = 0,
                                        double transitionVelocity = 0.01) {
    ContactParameters p;
    p.effectiveStiffness = effectiveStiffness;
    p.dissipation = dissipation;
    p.staticFriction = staticFriction;
    p.dynamicFriction = dynamicFriction;
    p.viscousFriction = 0;
    p.transitionVelocity = transitionVelocity;
    return p;
}

/// Static Hertz depth (m) at which a normal load (N) is carried: (3 load / (4 E* sqrt R))^(2/3).
inline double calcStaticHertzDepth(double load, double effectiveStiffness, double radius) {
    return std::pow(3 * load / (4 * effectiveStiffness * std::sqrt(radius)), 2.0 / 3.0);
}

/// A system with matter and forces and nothing else (gravity is added by the tests needing it).
struct Scene {
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter{system};
    SimTK::GeneralForceSubsystem forces{system};

    /// A body of mass m (kg, central inertia of a solid sphere of radius r) on a Slider along
    /// Ground axis `axis`, its q measuring the body origin's coordinate along that axis.
    SimTK::MobilizedBody::Slider addSlider(SimTK::CoordinateAxis axis, double mass, double radius) {
        // A Slider translates along its frames' x axis: turn x onto the wanted Ground axis.
        const SimTK::Rotation R_GF(SimTK::UnitVec3(axis), SimTK::XAxis);
        return SimTK::MobilizedBody::Slider(matter.updGround(), SimTK::Transform(R_GF),
                                            makeBody(mass, radius), SimTK::Transform(R_GF));
    }

    /// A body of mass m (kg) on a Free mobilizer.
    SimTK::MobilizedBody::Free addFree(double mass, double radius) {
        return SimTK::MobilizedBody::Free(matter.updGround(), makeBody(mass, radius));
    }

    static SimTK::Body::Rigid makeBody(double mass, double radius) {
        return SimTK::Body::Rigid(
            SimTK::MassProperties(mass, SimTK::Vec3(0), mass * SimTK::UnitInertia::sphere(radius)));
    }

    /// The floor (a half-space on Ground) as a contact surface.
    ContactSurface makeFloor() {
        return {matter.updGround(), "ground", "floor", ContactShape::halfSpace(), makeFloorPose()};
    }
};

/// A surface: `shape` at the origin of `body`.
inline ContactSurface makeSurface(const SimTK::MobilizedBody& body, const std::string& name,
                                  const ContactShape& shape) {
    return {body, name, name + "_shape", shape, SimTK::Transform()};
}

}  // namespace graspsim::contact::test
