#pragma once
// A digest of the listing a case ran: its manifest and its stage files,
// byte for byte. Results records carry it, so that a merge can tell a
// shard run on another catalog (an edited listing, another commit's) from
// a shard of the same run.
#include <string>

#include "core/manifest.h"

namespace snell {

// 32 hex digits; a file that cannot be read counts as empty (the run
// itself says why it could not read it).
std::string listingDigest(const Manifest& manifest);

// What a record carries in place of a digest when its listing was edited
// while the run was in progress: which text the case compiled is unknown.
// A resumed run runs the case again, merge refuses its shard, and compare
// lists it as edited.
inline constexpr const char* kListingEditedDuringRun = "edited during the run";

}  // namespace snell
