#include "cli/case_filter.h"

#include <fmt/format.h>
#include <fnmatch.h>

#include <algorithm>
#include <set>

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
  // The listings whose id the filter matches: a glob may match several.
  std::vector<const Manifest*> listings;
  for (const Manifest& manifest : manifests)
    if (fnmatch(glob.c_str(), manifest.id.c_str(), 0) == 0) listings.push_back(&manifest);
  if (!listings.empty()) {
    const bool one = listings.size() == 1;
    const std::string which =
        one ? fmt::format("which is listing {}'s id", listings.front()->id)
            : fmt::format("which matches the ids of listings {}{}", listings.front()->id,
                          listings.size() == 2 ? fmt::format(" and {}", listings.back()->id)
                                               : fmt::format(", {} and {} more", listings[1]->id,
                                                             listings.size() - 2));
    // The filter that works, where it does: a listing with no image case
    // is no better matched by its cases' glob, and is said to have none.
    const auto casesOf = [](const Manifest& m) { return expandCases({m}, m.id + "/*"); };
    if (kind == "image " && std::none_of(listings.begin(), listings.end(), [&](const Manifest* m) {
          const std::vector<Case> cases = casesOf(*m);
          return std::any_of(cases.begin(), cases.end(),
                             [](const Case& c) { return c.spec.has("image"); });
        }))
      return fmt::format(
          "no image case matches --filter '{}', {}, and none of {} cases is an image case; "
          "`snell list` shows each case's checks",
          glob, which, one ? "its" : "their");
    if (one)
      return fmt::format(
          "no {}case matches --filter '{}', {}: a case's id adds its scene; use --filter '{}/*' "
          "for all of its cases",
          kind, glob, which, listings.front()->id);
    // `GLOB/*` where it matches those listings' cases and no others (a `*`
    // also matches a '/', so it may reach into other listings).
    std::set<std::string> theirs, viaGlob;
    for (const Manifest* m : listings)
      for (const Case& c : casesOf(*m)) theirs.insert(c.id);
    for (const Case& c : expandCases(manifests, glob + "/*")) viaGlob.insert(c.id);
    return fmt::format(
        "no {}case matches --filter '{}', {}: a case's id adds its scene; {}", kind, glob, which,
        theirs == viaGlob ? fmt::format("use --filter '{}/*' for their cases", glob)
                          : std::string("use --filter 'ID/*' for each listing's cases"));
  }
  return fmt::format("no {}case matches --filter '{}'; `snell list` shows the ids", kind, glob);
}

}  // namespace snell::cli
