#include "oracle/listings/orange_book_fresnel.h"

#include "oracle/listings/listing_oracle.h"

namespace snell::listings {

template struct OrangeBookFresnel<double>;
template struct OrangeBookFresnel<float>;
template struct OrangeBookFresnel<Interval>;

std::unique_ptr<VertexOracle> makeOrangeBookFresnelOracle() {
  return makeListingOracle<OrangeBookFresnel>(kOrangeBookFresnelName);
}

}  // namespace snell::listings
