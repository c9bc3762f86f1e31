#include "cli/case_filter.h"

#include <fmt/format.h>
#include <fnmatch.h>

namespace snell::cli {

std::string noCaseMatchesMessage(const std::vector<Manifest>& manifests, const std::string& glob,
                                 const std::string& kind) {
  for (const Manifest& manifest : manifests)
    if (fnmatch(glob.c_str(), manifest.id.c_str(), 0) == 0)
      return fmt::format(
          "no {}case matches --filter '{}', which is listing {}'s id: a case's id adds its "
          "scene; use --filter '{}/*' for all of its cases",
          kind, glob, manifest.id, manifest.id);
  return fmt::format("no {}case matches --filter '{}'; `snell list` shows the ids", kind, glob);
}

}  // namespace snell::cli
