#include "graspsim/io/shell_quote.h"

namespace graspsim::io {

std::string quoteForShell(const std::string& text) {
    std::string quoted = "'";
    for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

}  // namespace graspsim::io
