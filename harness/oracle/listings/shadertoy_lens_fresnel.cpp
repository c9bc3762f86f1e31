#include "oracle/listings/shadertoy_lens_fresnel.h"

#include "oracle/listings/listing_oracle.h"

namespace snell::listings {

template struct ShadertoyLensFresnel<double>;
template struct ShadertoyLensFresnel<float>;
template struct ShadertoyLensFresnel<Interval>;

std::unique_ptr<VertexOracle> makeShadertoyLensFresnelOracle() {
  return makeListingOracle<ShadertoyLensFresnel>(kShadertoyLensFresnelName);
}

}  // namespace snell::listings
