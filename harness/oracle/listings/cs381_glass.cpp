#include "oracle/listings/cs381_glass.h"

#include "oracle/listings/listing_oracle.h"

namespace snell::listings {

template struct Cs381Glass<double>;
template struct Cs381Glass<float>;
template struct Cs381Glass<Interval>;

std::unique_ptr<VertexOracle> makeCs381GlassOracle() {
  return makeListingOracle<Cs381Glass>(kCs381GlassName);
}

}  // namespace snell::listings
