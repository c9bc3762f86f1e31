#include "oracle/listings/cg_refraction_builtin.h"

#include "oracle/listings/listing_oracle.h"

namespace snell::listings {

template struct CgRefractionBuiltin<double>;
template struct CgRefractionBuiltin<float>;
template struct CgRefractionBuiltin<Interval>;

std::unique_ptr<VertexOracle> makeCgRefractionBuiltinOracle() {
  return makeListingOracle<CgRefractionBuiltin>(kCgRefractionBuiltinName);
}

}  // namespace snell::listings
