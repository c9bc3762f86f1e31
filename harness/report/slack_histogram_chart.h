#pragma once
// The slack distribution of a case's outputs as an SVG bar chart (gnuplot):
// one bar group per slack bin, one bar per output, counts on a log axis so
// a single component outside the spec shows beside thousands inside it.
#include <filesystem>
#include <vector>

#include "compare/vector_check.h"
#include "report/gnuplot_batch.h"

namespace snell {

// Returns the SVG it will write; nothing is added for outputs that checked nothing.
std::filesystem::path addSlackHistogram(GnuplotBatch& batch,
                                        const std::vector<VaryingCheck>& varyings);

// The label of each bin: "0", "≤1/64", ... "≤2", ">2".
std::vector<std::string> slackBinLabels();

}  // namespace snell
