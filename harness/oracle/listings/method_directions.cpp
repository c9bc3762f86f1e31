#include "oracle/listings/method_directions.h"

#include "oracle/listings/listing_oracle.h"

namespace snell::listings {

template struct MethodDirections<double>;
template struct MethodDirections<float>;
template struct MethodDirections<Interval>;

std::unique_ptr<VertexOracle> makeMethodDirectionsOracle() {
  return makeListingOracle<MethodDirections>(kMethodDirectionsName);
}

}  // namespace snell::listings
