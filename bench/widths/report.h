#pragma once
// The width table on stdout, its JSON form, the before/after comparison
// with an earlier JSON, and the soundness verdict of --check.
#include <ostream>
#include <string>
#include <vector>

#include "widths/measure.h"

namespace snell::widths {

struct WidthReport {
  std::string oracle;  // which oracle the snell columns come from
  std::vector<RowStats> rows;
};

void printTable(std::ostream& out, const WidthReport& report);
void writeJson(const std::string& path, const WidthReport& report);
// Throws std::runtime_error naming the file for unreadable or malformed JSON.
WidthReport readJson(const std::string& path);
// Rows matched by (row, rules): snell's median and max before and after,
// beside the dEQP-style ones, and the escapes before and after.
void printComparison(std::ostream& out, const WidthReport& before, const WidthReport& after);
// The rows where snell lets a conforming value escape while the dEQP-style
// interval holds every one: where snell is unsound and need not be.
std::vector<const RowStats*> unsoundRows(const WidthReport& report);

}  // namespace snell::widths
