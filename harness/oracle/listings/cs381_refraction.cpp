#include "oracle/listings/cs381_refraction.h"

#include "oracle/listings/listing_oracle.h"

namespace snell::listings {

template struct Cs381Refraction<double>;
template struct Cs381Refraction<float>;
template struct Cs381Refraction<Interval>;

std::unique_ptr<VertexOracle> makeCs381RefractionOracle() {
  return makeListingOracle<Cs381Refraction>(kCs381RefractionName);
}

}  // namespace snell::listings
