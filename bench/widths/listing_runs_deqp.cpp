#include "widths/listing_runs_impl.h"

namespace snell::widths {
template std::vector<Deqp> runListing<Deqp>(const std::string&, const ListingBindings&,
                                            std::size_t);
}  // namespace snell::widths
