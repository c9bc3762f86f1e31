#include "widths/listing_runs_impl.h"

namespace snell::widths {
template std::vector<Sampled> runListing<Sampled>(const std::string&, const ListingBindings&,
                                                  std::size_t);
}  // namespace snell::widths
