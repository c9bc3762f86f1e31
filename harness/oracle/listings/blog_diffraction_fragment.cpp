#include "oracle/listings/blog_diffraction_fragment.h"

#include "oracle/listings/fragment_listing_oracle.h"

namespace snell::listings {

std::unique_ptr<FragmentOracle> makeBlogDiffractionFragmentOracle() {
  return makeFragmentListingOracle<BlogDiffractionFragment>();
}

}  // namespace snell::listings
