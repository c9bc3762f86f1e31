#pragma once
// Files embedded into the HTML report, so it opens with no network and no
// folder beside it.
#include <string>

namespace snell {

std::string base64(const std::string& bytes);
// "data:<mime>;base64,...".
std::string dataUri(const std::string& mime, const std::string& bytes);

}  // namespace snell
