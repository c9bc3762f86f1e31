#include "oracle/listings/shadertoy_lens.h"

#include "oracle/listings/listing_oracle.h"

namespace snell::listings {

template struct ShadertoyLens<double>;
template struct ShadertoyLens<float>;
template struct ShadertoyLens<Interval>;

std::unique_ptr<VertexOracle> makeShadertoyLensOracle() {
  return makeListingOracle<ShadertoyLens>(kShadertoyLensName);
}

}  // namespace snell::listings
