#include "oracle/listings/shadertoy_bubble.h"

#include "oracle/listings/listing_oracle.h"

namespace snell::listings {

template struct ShadertoyBubble<double>;
template struct ShadertoyBubble<float>;
template struct ShadertoyBubble<Interval>;

std::unique_ptr<VertexOracle> makeShadertoyBubbleOracle() {
  return makeListingOracle<ShadertoyBubble>(kShadertoyBubbleName);
}

}  // namespace snell::listings
