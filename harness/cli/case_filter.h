#pragma once
// What `run`, `bless` and `list` say when --filter matched no case.
#include <string>
#include <vector>

#include "core/manifest.h"

namespace snell::cli {

// A listing's id alone matches none of its cases ("<id>/*" does): that
// mistake is named with the filter that works. `kind` qualifies the cases
// ("image " for bless, else ""); `otherKind` is the cases the filter does
// match that are not of that kind (bless: cases with no image check), which
// are the reason, not the filter.
std::string noCaseMatchesMessage(const std::vector<Manifest>& manifests, const std::string& glob,
                                 const std::string& kind = "",
                                 const std::vector<std::string>& otherKind = {});

}  // namespace snell::cli
