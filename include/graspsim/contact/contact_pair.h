#pragma once
/// @file
/// What may touch what: a contact surface is a shape fixed on a mobilized body; a contact pair
/// is two surfaces that CompliantContactForce (or RigidContactSet) checks against each other,
/// with the pair's contact parameters.

#include "graspsim/simbody.h"

#include <string>

#include "graspsim/contact/contact_parameters.h"
#include "graspsim/contact/contact_shape.h"
#include "graspsim/model/model_description.h"

namespace graspsim::contact {

/// A shape S fixed on body B (use the matter subsystem's Ground for floors and tables).
struct ContactSurface {
    SimTK::MobilizedBody body;  ///< the body carrying the shape (a handle referring to it)
    std::string bodyName;       ///< for reports and messages
    std::string shapeName;      ///< for reports and messages (e.g. the model geometry's name)
    ContactShape shape;
    SimTK::Transform X_BS;  ///< pose of the shape frame S in the body frame B (m)

    /// The surface of a model geometry on `body`: shape and pose X_BS = geometry.X_BG.
    /// @throws graspsim::InputError for a Mesh without loaded triangles or not closed and
    ///         convex, a bad size or a bad rotation.
    static ContactSurface fromGeometry(const SimTK::MobilizedBody& body,
                                       const std::string& bodyName, const model::Geometry& geometry);
};

/// Two surfaces that may touch. Normals, reports and friction are oriented from a to b.
struct ContactPair {
    ContactSurface a;
    ContactSurface b;
    /// The pair's stiffness, dissipation and friction (validated by the contact element that
    /// takes the pair).
    ContactParameters parameters;
    /// Whether the pair is active in the default state (see
    /// CompliantContactForce::setPairEnabled()).
    bool enabledByDefault = true;

    /// "<bodyA>/<shapeA> vs <bodyB>/<shapeB>", for messages.
    std::string describe() const;
};

}  // namespace graspsim::contact
