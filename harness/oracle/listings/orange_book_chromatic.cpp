#include "oracle/listings/orange_book_chromatic.h"

#include "oracle/listings/listing_oracle.h"

namespace snell::listings {

template struct OrangeBookChromatic<double>;
template struct OrangeBookChromatic<float>;
template struct OrangeBookChromatic<Interval>;

std::unique_ptr<VertexOracle> makeOrangeBookChromaticOracle() {
  return makeListingOracle<OrangeBookChromatic>(kOrangeBookChromaticName);
}

}  // namespace snell::listings
