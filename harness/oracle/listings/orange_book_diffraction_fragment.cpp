#include "oracle/listings/orange_book_diffraction_fragment.h"

#include "oracle/listings/fragment_listing_oracle.h"

namespace snell::listings {

std::unique_ptr<FragmentOracle> makeOrangeBookDiffractionFragmentOracle() {
  return makeFragmentListingOracle<OrangeBookDiffractionFragment>();
}

}  // namespace snell::listings
