#include "oracle/listings/cs381_chromatic_aberration.h"

#include "oracle/listings/listing_oracle.h"

namespace snell::listings {

template struct Cs381ChromaticAberration<double>;
template struct Cs381ChromaticAberration<float>;
template struct Cs381ChromaticAberration<Interval>;

std::unique_ptr<VertexOracle> makeCs381ChromaticAberrationOracle() {
  return makeListingOracle<Cs381ChromaticAberration>(kCs381ChromaticAberrationName);
}

}  // namespace snell::listings
