#include "oracle/listings/orange_book_chromatic_fragment.h"

#include "oracle/listings/fragment_listing_oracle.h"

namespace snell::listings {

std::unique_ptr<FragmentOracle> makeOrangeBookChromaticFragmentOracle() {
  return makeFragmentListingOracle<OrangeBookChromaticFragment>();
}

}  // namespace snell::listings
