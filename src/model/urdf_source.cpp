#include "urdf_source.h"

#include "graspsim/error.h"

namespace graspsim::model {

void UrdfSource::reject(int line, const std::string& field, const std::string& value,
                        const std::string& accepted) const {
    fail(line, field + " = " + value + " is not accepted; " + accepted);
}

void UrdfSource::fail(int line, const std::string& message) const {
    const std::string where = line > 0 ? name + ":" + std::to_string(line) : name;
    throw InputError(where + ": " + message);
}

std::string quoted(const std::string& text) { return "'" + text + "'"; }

}  // namespace graspsim::model
