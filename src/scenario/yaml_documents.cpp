#include "graspsim/scenario/yaml_documents.h"

#include <sstream>

namespace graspsim::scenario {

namespace {

bool isMarker(const std::string& line, const char* marker) {
    if (line.compare(0, 3, marker) != 0) return false;
    return line.size() == 3 || line[3] == ' ' || line[3] == '\t' || line[3] == '\r';
}

// Content: anything but blank space, a comment or a directive.
bool isContent(const std::string& line) {
    const std::size_t first = line.find_first_not_of(" \t\r");
    return first != std::string::npos && line[first] != '#' && !(first == 0 && line[0] == '%');
}

}  // namespace

int findSecondYamlDocument(const std::string& yamlText) {
    std::istringstream lines(yamlText);
    std::string line;
    bool content = false;  // the first document has content
    bool ended = false;    // and was closed by "..."
    for (int number = 1; std::getline(lines, line); ++number) {
        if (isMarker(line, "---")) {
            if (content) return number;
            continue;  // the first document's own start
        }
        if (isMarker(line, "...")) {
            ended = content;
            continue;
        }
        if (!isContent(line)) continue;
        if (ended) return number;
        content = true;
    }
    return 0;
}

}  // namespace graspsim::scenario
