#include "capsule_contact_option.h"

#include "graspsim/error.h"

namespace graspsim::cli {

std::optional<contact::CapsuleContact> parseCapsuleContactOption(const std::string& text, simulation::ContactModel contact) {
    if (text.empty()) return std::nullopt;
    const contact::CapsuleContact rule = contact::parseCapsuleContact(text, "--capsule-contact");
    if (contact == simulation::ContactModel::Rigid) {
        throw InputError("--capsule-contact: '" + text + "' is not accepted with --contact rigid; it chooses where a "
                         "capsule presses in compliant contact (rigid contact keeps the deepest point)");
    }
    return rule;
}

}  // namespace graspsim::cli
