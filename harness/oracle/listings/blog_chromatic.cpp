#include "oracle/listings/blog_chromatic.h"

#include "oracle/listings/legacy_listing_oracle.h"

namespace snell::listings {

template struct BlogChromatic<double>;
template struct BlogChromatic<float>;
template struct BlogChromatic<Interval>;

std::unique_ptr<VertexOracle> makeBlogChromaticOracle() {
  return makeLegacyListingOracle<BlogChromatic>(kBlogChromaticName);
}

}  // namespace snell::listings
