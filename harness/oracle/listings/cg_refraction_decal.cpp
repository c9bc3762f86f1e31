#include "oracle/listings/cg_refraction_decal.h"

#include "oracle/listings/listing_oracle.h"

namespace snell::listings {

template struct CgRefractionDecal<double>;
template struct CgRefractionDecal<float>;
template struct CgRefractionDecal<Interval>;

std::unique_ptr<VertexOracle> makeCgRefractionDecalOracle() {
  return makeListingOracle<CgRefractionDecal>(kCgRefractionDecalName);
}

}  // namespace snell::listings
