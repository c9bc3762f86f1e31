#include "widths/report.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace snell::widths {
namespace {

double ratio(double a, double b) { return b > 0 ? a / b : 0.0; }

}  // namespace

void printTable(std::ostream& out, const WidthReport& report) {
  fmt::print(
      out, "snell oracle: {}. Widths in ULPs of the result; escapes: conforming values outside.\n",
      report.oracle);
  fmt::print(out,
             "{:<58} {:<6} {:>5} {:>5} | {:>9} {:>9} | {:>9} {:>9} | {:>6} {:>6} | {:>7} {:>7}\n",
             "row", "rules", "n", "split", "snell med", "snell max", "dEQP med", "dEQP max",
             "r(med)", "r(max)", "esc snl", "esc dq");
  for (const RowStats& r : report.rows)
    fmt::print(
        out,
        "{:<58} {:<6} {:>5} {:>5} | {:>9.3g} {:>9.3g} | {:>9.3g} {:>9.3g} | {:>6.3g} {:>6.3g} | "
        "{:>7} {:>7}\n",
        r.row, r.rules, r.samples, r.split, r.snellMedian, r.snellMax, r.deqpMedian, r.deqpMax,
        ratio(r.snellMedian, r.deqpMedian), ratio(r.snellMax, r.deqpMax), r.snellEscapes,
        r.deqpEscapes);
  fmt::print(
      out, "\nWhere snell is widest beside the dEQP-style interval (rows with a ratio over 2):\n");
  for (const RowStats& r : report.rows)
    if (r.widestRatio > 2)
      fmt::print(out, "{} ({}): x{:.3g} at {}\n", r.row, r.rules, r.widestRatio, r.widest);
  for (const RowStats& r : report.rows) {
    if (r.snellEscapes)
      fmt::print(out, "snell escape, {} ({}): {}\n", r.row, r.rules, r.snellEscape);
    if (r.deqpEscapes)
      fmt::print(out, "dEQP-style escape, {} ({}): {}\n", r.row, r.rules, r.deqpEscape);
  }
}

void writeJson(const std::string& path, const WidthReport& report) {
  nlohmann::json rows = nlohmann::json::array();
  for (const RowStats& r : report.rows)
    rows.push_back({{"row", r.row},
                    {"rules", r.rules},
                    {"samples", r.samples},
                    {"measured", r.measured},
                    {"split", r.split},
                    {"undefined", r.undefined},
                    {"zero", r.zero},
                    {"snell_median", r.snellMedian},
                    {"snell_max", r.snellMax},
                    {"deqp_median", r.deqpMedian},
                    {"deqp_max", r.deqpMax},
                    {"conforming", r.conforming},
                    {"snell_escapes", r.snellEscapes},
                    {"deqp_escapes", r.deqpEscapes},
                    {"snell_escape", r.snellEscape},
                    {"deqp_escape", r.deqpEscape},
                    {"widest_ratio", r.widestRatio},
                    {"widest", r.widest}});
  std::ofstream file(path);
  file << nlohmann::json{{"oracle", report.oracle}, {"rows", rows}}.dump(1) << "\n";
  if (!file) throw std::runtime_error(fmt::format("{}: cannot write", path));
}

WidthReport readJson(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error(fmt::format("{}: cannot read", path));
  try {
    const nlohmann::json json = nlohmann::json::parse(file);
    WidthReport report;
    report.oracle = json.at("oracle").get<std::string>();
    for (const nlohmann::json& r : json.at("rows")) {
      RowStats s;
      s.row = r.at("row");
      s.rules = r.at("rules");
      s.samples = r.at("samples");
      s.measured = r.at("measured");
      s.split = r.at("split");
      s.undefined = r.at("undefined");
      s.zero = r.at("zero");
      s.snellMedian = r.at("snell_median");
      s.snellMax = r.at("snell_max");
      s.deqpMedian = r.at("deqp_median");
      s.deqpMax = r.at("deqp_max");
      s.conforming = r.at("conforming");
      s.snellEscapes = r.at("snell_escapes");
      s.deqpEscapes = r.at("deqp_escapes");
      s.snellEscape = r.at("snell_escape");
      s.deqpEscape = r.at("deqp_escape");
      s.widestRatio = r.at("widest_ratio");
      s.widest = r.at("widest");
      report.rows.push_back(std::move(s));
    }
    return report;
  } catch (const nlohmann::json::exception& error) {
    throw std::runtime_error(
        fmt::format("{}: not a widths JSON ({}); write one with --json", path, error.what()));
  }
}

void printComparison(std::ostream& out, const WidthReport& before, const WidthReport& after) {
  std::map<std::pair<std::string, std::string>, const RowStats*> earlier;
  for (const RowStats& r : before.rows) earlier[{r.row, r.rules}] = &r;
  fmt::print(out, "before: {}; after: {}. Widths in ULPs of the result.\n", before.oracle,
             after.oracle);
  fmt::print(out, "{:<58} {:<6} | {:>9} {:>9} {:>9} | {:>9} {:>9} {:>9} | {:>11} {:>11}\n", "row",
             "rules", "snl med<", "snl med>", "dEQP med", "snl max<", "snl max>", "dEQP max",
             "esc snl <>", "esc dq <>");
  for (const RowStats& r : after.rows) {
    const auto it = earlier.find({r.row, r.rules});
    if (it == earlier.end()) {
      fmt::print(out, "{:<58} {:<6} | (no before row)\n", r.row, r.rules);
      continue;
    }
    const RowStats& b = *it->second;
    fmt::print(
        out,
        "{:<58} {:<6} | {:>9.3g} {:>9.3g} {:>9.3g} | {:>9.3g} {:>9.3g} {:>9.3g} | {:>5} {:>5} | "
        "{:>4} {:>4}\n",
        r.row, r.rules, b.snellMedian, r.snellMedian, r.deqpMedian, b.snellMax, r.snellMax,
        r.deqpMax, b.snellEscapes, r.snellEscapes, b.deqpEscapes, r.deqpEscapes);
  }
}

std::vector<const RowStats*> unsoundRows(const WidthReport& report) {
  std::vector<const RowStats*> rows;
  for (const RowStats& r : report.rows)
    if (r.snellEscapes > 0 && r.deqpEscapes == 0) rows.push_back(&r);
  return rows;
}

}  // namespace snell::widths
