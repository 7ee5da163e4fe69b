#pragma once
// --friction of simulate and capacity: the compliant contact's friction law, overriding the
// scenario's contact.friction_model.

#include "graspsim/contact/friction_settings.h"
#include "graspsim/simulation/simulation_options.h"

#include <optional>
#include <string>

namespace graspsim::cli {

// The law `text` names (regularized or anchor); none if `text` is empty. Throws InputError for
// another word, and for any law with rigid contact (whose friction is Coulomb's).
std::optional<contact::FrictionModel> parseFrictionOption(const std::string& text, simulation::ContactModel contact);

}  // namespace graspsim::cli
