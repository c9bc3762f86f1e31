#include "oracle/listings/method_empirical.h"

#include "oracle/listings/listing_oracle.h"

namespace snell::listings {

template struct MethodEmpirical<double>;
template struct MethodEmpirical<float>;
template struct MethodEmpirical<Interval>;

std::unique_ptr<VertexOracle> makeMethodEmpiricalOracle() {
  return makeListingOracle<MethodEmpirical>(kMethodEmpiricalName);
}

}  // namespace snell::listings
