#include "friction_option.h"

#include "graspsim/error.h"

namespace graspsim::cli {

std::optional<contact::FrictionModel> parseFrictionOption(const std::string& text, simulation::ContactModel contact) {
    if (text.empty()) return std::nullopt;
    const contact::FrictionModel model = contact::parseFrictionModel(text, "--friction");
    if (contact == simulation::ContactModel::Rigid) {
        throw InputError("--friction: '" + text + "' is not accepted with --contact rigid; it chooses the "
                         "compliant contact's friction law (rigid contact has Coulomb friction)");
    }
    return model;
}

}  // namespace graspsim::cli
