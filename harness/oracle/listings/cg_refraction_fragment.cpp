#include "oracle/listings/cg_refraction_fragment.h"

#include "oracle/listings/fragment_listing_oracle.h"

namespace snell::listings {

std::unique_ptr<FragmentOracle> makeCgRefractionFragmentOracle() {
  return makeFragmentListingOracle<CgRefractionFragment>();
}

}  // namespace snell::listings
