#include "oracle/listings/cg_refraction.h"

#include "oracle/listings/listing_oracle.h"

namespace snell::listings {

template struct CgRefraction<double>;
template struct CgRefraction<float>;
template struct CgRefraction<Interval>;

std::unique_ptr<VertexOracle> makeCgRefractionOracle() {
  return makeListingOracle<CgRefraction>(kCgRefractionName);
}

}  // namespace snell::listings
