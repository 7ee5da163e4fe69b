#pragma once
/// @file
/// The friction law of a compliant contact element and the elastic anchor's parameters: which of
/// contact_force_law.h's regularized friction or anchor_friction.h's true stiction the element
/// uses. Plain data, so that the scenario layer can carry them as read from the file.

#include <string>

namespace graspsim::contact {

/// Which friction law the compliant contact element uses.
enum class FrictionModel {
    Regularized,  ///< mu(v) of contact_force_law.h: no state, creeps under any tangential load
    Anchor,       ///< the elastic anchor of anchor_friction.h: true stiction
};

/// "regularized" or "anchor".
std::string toString(FrictionModel model);

/// Parses "regularized" or "anchor".
/// @param source names the field or flag for the message (e.g. "--friction").
/// @throws graspsim::InputError "<source>: '<text>' is not accepted; use regularized or anchor".
FrictionModel parseFrictionModel(const std::string& text, const std::string& source);

/// The anchor model's parameters (anchor_friction.h explains their physics).
struct AnchorFrictionParameters {
    /// k_t / k_n (dimensionless), > 0: tangential over normal contact stiffness. Default 2/3,
    /// Mindlin's 2 (1 - nu) / (2 - nu) for nearly incompressible skin (nu = 0.5).
    double stiffnessRatio = 2.0 / 3.0;
    /// m_d (kg), > 0: the mass on which the anchor spring is critically damped, c = 2 sqrt(k m_d).
    /// Default 0.02, one finger segment of the thesis model.
    double dampingMass = 0.02;
    /// tau (s), > 0: time in which a sliding anchor catches up with the friction limit and an
    /// unloaded one relaxes to the current point. Default 1e-3 (a slide at 0.1 m/s overshoots
    /// the limit deflection by 0.1 mm; the friction force itself is capped at the limit).
    double relaxationTime = 1e-3;

    /// Checks every field: finite and > 0.
    /// @param source names the parameters for the message (e.g. "scenario.yaml: contact").
    /// @throws graspsim::InputError "<source>: <field> (<value>) must be finite and > 0 (<unit>)".
    void validate(const std::string& source) const;
};

/// The friction law of a compliant contact element, with the anchor's parameters.
struct FrictionSettings {
    FrictionModel model = FrictionModel::Regularized;
    AnchorFrictionParameters anchor;
};

}  // namespace graspsim::contact
