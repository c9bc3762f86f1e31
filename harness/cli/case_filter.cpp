#include "cli/case_filter.h"

#include <fmt/format.h>
#include <fnmatch.h>

#include <algorithm>

#include "core/case.h"

namespace snell::cli {

std::string noCaseMatchesMessage(const std::vector<Manifest>& manifests, const std::string& glob,
                                 const std::string& kind,
                                 const std::vector<std::string>& otherKind) {
  if (!otherKind.empty())
    return fmt::format(
        "no {0}case matches --filter '{1}': the {2} case(s) it matches ({3}{4}) are not {0}cases; "
        "`snell list` shows each case's checks",
        kind, glob, otherKind.size(), otherKind.front(),
        otherKind.size() > 1 ? fmt::format(" and {} more", otherKind.size() - 1) : "");
  for (const Manifest& manifest : manifests) {
    if (fnmatch(glob.c_str(), manifest.id.c_str(), 0) != 0) continue;
    // The filter that works, where it does: a listing with no image case
    // is no better matched by its cases' glob, and is said to have none.
    const std::string cases = manifest.id + "/*";
    const std::vector<Case> matched = expandCases({manifest}, cases);
    if (kind == "image " && std::none_of(matched.begin(), matched.end(),
                                         [](const Case& c) { return c.spec.has("image"); }))
      return fmt::format(
          "no image case matches --filter '{}', which is listing {}'s id, and none of its "
          "cases is an image case; `snell list` shows each case's checks",
          glob, manifest.id);
    return fmt::format(
        "no {}case matches --filter '{}', which is listing {}'s id: a case's id adds its "
        "scene; use --filter '{}' for all of its cases",
        kind, glob, manifest.id, cases);
  }
  return fmt::format("no {}case matches --filter '{}'; `snell list` shows the ids", kind, glob);
}

}  // namespace snell::cli
