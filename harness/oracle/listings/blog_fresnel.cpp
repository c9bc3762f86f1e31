#include "oracle/listings/blog_fresnel.h"

#include "oracle/listings/legacy_listing_oracle.h"

namespace snell::listings {

template struct BlogFresnel<double>;
template struct BlogFresnel<float>;
template struct BlogFresnel<Interval>;

std::unique_ptr<VertexOracle> makeBlogFresnelOracle() {
  return makeLegacyListingOracle<BlogFresnel>(kBlogFresnelName);
}

}  // namespace snell::listings
