#include "oracle/listings/method_per_fragment.h"

#include "oracle/listings/listing_oracle.h"

namespace snell::listings {

template struct MethodPerFragment<double>;
template struct MethodPerFragment<float>;
template struct MethodPerFragment<Interval>;

std::unique_ptr<VertexOracle> makeMethodPerFragmentOracle() {
  return makeListingOracle<MethodPerFragment>(kMethodPerFragmentName);
}

}  // namespace snell::listings
