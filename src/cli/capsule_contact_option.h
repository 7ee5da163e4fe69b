#pragma once
// --capsule-contact of simulate and capacity: where a capsule touches a solid in compliant
// contact, overriding the scenario's contact.capsule_contact.

#include "graspsim/contact/contact_parameters.h"
#include "graspsim/simulation/simulation_options.h"

#include <optional>
#include <string>

namespace graspsim::cli {

// The rule `text` names (deepest or ends); none if `text` is empty. Throws InputError for another
// word, and for any rule with rigid contact (which always touches at the deepest point).
std::optional<contact::CapsuleContact> parseCapsuleContactOption(const std::string& text, simulation::ContactModel contact);

}  // namespace graspsim::cli
