#include "oracle/listings/blog_diffraction.h"

#include "oracle/listings/legacy_listing_oracle.h"

namespace snell::listings {

template struct BlogDiffraction<double>;
template struct BlogDiffraction<float>;
template struct BlogDiffraction<Interval>;

std::unique_ptr<VertexOracle> makeBlogDiffractionOracle() {
  return makeLegacyListingOracle<BlogDiffraction>(kBlogDiffractionName);
}

}  // namespace snell::listings
