#pragma once
// The key a stored oracle result is kept under: a digest of everything the
// result depends on. `identity` says which oracle computes it and from
// what (runner/listing_oracles.h: the build of the oracle's code, the
// listing's text for a derived oracle); the input is taken whole: the
// precision rules, every uniform, constant and per-invocation input, bit
// for bit.
#include <string_view>

#include "core/content_hash.h"
#include "oracle/vertex_oracle.h"

namespace snell {

Digest oracleResultKey(std::string_view identity, const OracleInput& input);

}  // namespace snell
