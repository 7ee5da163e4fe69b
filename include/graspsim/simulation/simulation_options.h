#pragma once
/// @file
/// What a user chooses per simulation run, on top of the scenario.

#include <string>

namespace graspsim::simulation {

/// How finger-object contact is modelled.
enum class ContactModel {
    Compliant,  ///< Hunt-Crossley normal force with Stribeck friction (contact::CompliantContactForce)
    Rigid       ///< unilateral contact with Coulomb friction (SemiExplicitEulerTimeStepper)
};

/// Whether the grasp approximation may replace the contacts.
enum class SimulationMode {
    Full,   ///< every contact solved all the time (the ground truth)
    Approx  ///< the grasp approximation (one 6-DOF constraint once the grasp is firm)
};

/// Per-run choices. Defaults: compliant full contact, no perturbation, the scenario's duration.
struct SimulationOptions {
    ContactModel contact = ContactModel::Compliant;
    SimulationMode mode = SimulationMode::Full;
    std::string perturbation = "none";  ///< "none" or the name of one of the scenario's perturbations
    double duration = 0;                ///< simulated time (s); 0 takes the scenario's
};

/// Parses "compliant" or "rigid". @throws graspsim::InputError naming `source`, the value and the choices.
ContactModel parseContactModel(const std::string& text, const std::string& source);
/// Parses "full" or "approx". @throws graspsim::InputError naming `source`, the value and the choices.
SimulationMode parseSimulationMode(const std::string& text, const std::string& source);
std::string toString(ContactModel model);
std::string toString(SimulationMode mode);

}  // namespace graspsim::simulation
