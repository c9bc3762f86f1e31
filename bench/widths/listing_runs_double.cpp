#include "widths/listing_runs_impl.h"

namespace snell::widths {
template std::vector<double> runListing<double>(const std::string&, const ListingBindings&,
                                                std::size_t);
}  // namespace snell::widths

namespace snell::widths {
std::vector<std::string> listingOracleNames() {
  std::vector<std::string> names;
  for (const auto& [name, runner] : listing_runs_detail::runners<double>()) names.push_back(name);
  return names;
}

std::vector<ListingInput> listingInputs(const std::string& oracle) {
  return listing_runs_detail::runners<double>().at(oracle).inputs();
}
}  // namespace snell::widths
