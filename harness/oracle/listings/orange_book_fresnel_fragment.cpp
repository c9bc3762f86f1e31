#include "oracle/listings/orange_book_fresnel_fragment.h"

#include "oracle/listings/fragment_listing_oracle.h"

namespace snell::listings {

std::unique_ptr<FragmentOracle> makeOrangeBookFresnelFragmentOracle() {
  return makeFragmentListingOracle<OrangeBookFresnelFragment>();
}

}  // namespace snell::listings
