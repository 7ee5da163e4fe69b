#pragma once
/// @file
/// Whether a YAML text holds more than one document. yaml-cpp's YAML::Load reads the first
/// document and silently drops the rest; its YAML::LoadAll, which would count them, loops for
/// good on some malformed texts (found by the scenario file fuzzer). So the count is read from
/// the text's document markers instead.

#include <string>

namespace graspsim::scenario {

/// The 1-based line at which a second document starts in `yamlText`: a document-start marker
/// ("---" alone or followed by a space or tab, at the start of a line) after content, or content
/// after a document-end marker ("..."). Comments, blank lines and directives ('%') are not
/// content. 0 if the text holds at most one document.
int findSecondYamlDocument(const std::string& yamlText);

}  // namespace graspsim::scenario
