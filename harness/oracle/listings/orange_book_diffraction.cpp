#include "oracle/listings/orange_book_diffraction.h"

#include "oracle/listings/listing_oracle.h"

namespace snell::listings {

template struct OrangeBookDiffraction<double>;
template struct OrangeBookDiffraction<float>;
template struct OrangeBookDiffraction<Interval>;

std::unique_ptr<VertexOracle> makeOrangeBookDiffractionOracle() {
  return makeListingOracle<OrangeBookDiffraction>(kOrangeBookDiffractionName);
}

}  // namespace snell::listings
