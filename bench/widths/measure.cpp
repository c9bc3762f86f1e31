#include "widths/measure.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

#include "widths/fp32_grid.h"
#include "widths/listing_runs.h"
#include "widths/number_types.h"

namespace snell::widths {

bool boxAllows(const std::vector<DeqpValue>& box, const std::vector<float>& vector) {
  for (std::size_t k = 0; k < vector.size(); ++k) {
    if (box[k].undefined) continue;
    if (!(vector[k] >= box[k].lo && vector[k] <= box[k].hi)) return false;
  }
  return true;
}

RowAccumulator::RowAccumulator(std::string row, PrecisionRules rules) {
  stats_.row = std::move(row);
  stats_.rules = precisionRulesName(rules);
}

namespace {

std::string describeEscape(const SampleRecord& record, const std::vector<float>& value) {
  std::string snellWays;
  for (const SnellWay& way : record.snell.ways)
    snellWays +=
        fmt::format(" [{:.9g}]..[{:.9g}]", fmt::join(way.lo, ", "), fmt::join(way.hi, ", "));
  std::string deqp;
  for (const DeqpValue& c : record.deqp) deqp += fmt::format(" [{:.9g}, {:.9g}]", c.lo, c.hi);
  return fmt::format("{} value [{:.9g}] snell{} deqp{}", record.input, fmt::join(value, ", "),
                     snellWays, deqp);
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

}  // namespace

void RowAccumulator::add(const SampleRecord& record) {
  ++stats_.samples;
  for (const std::vector<float>& value : record.conforming) {
    ++stats_.conforming;
    if (!record.snell.allows(value) && stats_.snellEscapes++ == 0)
      stats_.snellEscape = describeEscape(record, value);
    if (!boxAllows(record.deqp, value) && stats_.deqpEscapes++ == 0)
      stats_.deqpEscape = describeEscape(record, value);
  }
  if (record.snell.ways.size() > 1) {
    ++stats_.split;
    return;
  }
  const SnellWay& snell = record.snell.hull;
  for (std::size_t k = 0; k < record.deqp.size(); ++k) {
    if (snell.undefined[k] || record.deqp[k].undefined) {
      ++stats_.undefined;
      return;
    }
  }
  for (std::size_t k = 0; k < record.deqp.size(); ++k) {
    // A component both hold at exactly 0 (refract's total internal
    // reflection) says nothing about tightness.
    const bool zero =
        snell.lo[k] == 0 && snell.hi[k] == 0 && record.deqp[k].lo == 0 && record.deqp[k].hi == 0;
    if (zero) {
      ++stats_.zero;
      continue;
    }
    const double snellWidth = inUlps(snell.hi[k] - snell.lo[k], record.reference[k]);
    const double deqpWidth = inUlps(record.deqp[k].hi - record.deqp[k].lo, record.reference[k]);
    snellWidths_.push_back(snellWidth);
    deqpWidths_.push_back(deqpWidth);
    const double ratio = deqpWidth > 0 ? snellWidth / deqpWidth : 0.0;
    if (ratio > stats_.widestRatio) {
      stats_.widestRatio = ratio;
      stats_.widest = fmt::format(
          "{} component {}: exact {:.9g}, snell [{:.9g}, {:.9g}] ({:.3g} ULP), dEQP-style "
          "[{:.9g}, {:.9g}] ({:.3g} ULP)",
          record.input, k, record.reference[k], snell.lo[k], snell.hi[k], snellWidth,
          record.deqp[k].lo, record.deqp[k].hi, deqpWidth);
    }
  }
}

RowStats RowAccumulator::finish() const {
  RowStats stats = stats_;
  stats.measured = snellWidths_.size();
  stats.snellMedian = median(snellWidths_);
  stats.deqpMedian = median(deqpWidths_);
  if (!snellWidths_.empty()) {
    stats.snellMax = *std::max_element(snellWidths_.begin(), snellWidths_.end());
    stats.deqpMax = *std::max_element(deqpWidths_.begin(), deqpWidths_.end());
  }
  return stats;
}

std::vector<SamplerChoices> conformingChoices(std::uint64_t seed, std::size_t count) {
  std::vector<SamplerChoices> choices;
  const Rounding modes[] = {Rounding::Nearest, Rounding::Up, Rounding::Down, Rounding::TowardZero};
  for (std::size_t i = 0; i < count; ++i) {
    SamplerChoices c;
    c.seed = seed * 1000003u + i;
    if (i < 8) {
      c.rounding = modes[i % 4];
      c.mayFuse = i >= 4;
      c.edgeOfAllowance = i >= 4;
    } else {
      c.randomRoundingPerOperation = true;
      c.flushDenormals = true;
    }
    choices.push_back(c);
  }
  return choices;
}

namespace {

template <class T, int N>
glsl::vec<T, N> vecOf(const std::vector<float>& v) {
  glsl::vec<T, N> r;
  for (int k = 0; k < N; ++k) r[k] = T(v[static_cast<std::size_t>(k)]);
  return r;
}

template <class T>
std::vector<T> builtin(const std::string& fn, const std::vector<float>& I,
                       const std::vector<float>& N, float eta) {
  const auto i = vecOf<T, 3>(I);
  const auto n = vecOf<T, 3>(N);
  const glsl::vec3<T> r = fn == "reflect" ? glsl::reflect(i, n) : glsl::refract(i, n, T(eta));
  return {r[0], r[1], r[2]};
}

std::vector<float> floatsOf(const std::vector<Sampled>& values) {
  std::vector<float> r;
  for (const Sampled& v : values) r.push_back(v.value.v);
  return r;
}

std::vector<DeqpValue> boxOf(const std::vector<Deqp>& values) {
  std::vector<DeqpValue> r;
  for (const Deqp& v : values) r.push_back(v.value);
  return r;
}

}  // namespace

SampleRecord builtinRecord(const std::string& fn, const std::vector<float>& I,
                           const std::vector<float>& N, float eta, PrecisionRules rules,
                           std::size_t conformingPerInput, std::uint64_t seed) {
  const UsePrecisionRules use(rules);
  SampleRecord record;
  record.reference = builtin<double>(fn, I, N, eta);
  record.deqp = boxOf(builtin<Deqp>(fn, I, N, eta));
  record.snell = snellBuiltin(fn, I, N, eta, rules);
  for (const SamplerChoices& choices : conformingChoices(seed, conformingPerInput)) {
    const UseSamplerChoices machine(choices);
    record.conforming.push_back(floatsOf(builtin<Sampled>(fn, I, N, eta)));
  }
  record.input = fmt::format(
      R"({{"fn":"{}","I":[{:.9g}],"N":[{:.9g}]{}}})", fn, fmt::join(I, ","), fmt::join(N, ","),
      fn == "refract" ? fmt::format(R"(,"eta":{:.9g})", eta) : std::string());
  return record;
}

std::vector<std::vector<SampleRecord>> listingRecords(const std::string& oracle,
                                                      const ListingBindings& bindings,
                                                      PrecisionRules rules,
                                                      std::size_t conformingPerInput,
                                                      std::uint64_t seed) {
  const UsePrecisionRules use(rules);
  const std::vector<std::vector<SnellSample>> snell = snellListing(oracle, bindings, rules);
  std::vector<std::vector<SampleRecord>> records(snell.size());
  for (std::size_t vertex = 0; vertex < bindings.vertexCount; ++vertex) {
    const std::vector<double> reference = runListing<double>(oracle, bindings, vertex);
    const std::vector<DeqpValue> deqp = boxOf(runListing<Deqp>(oracle, bindings, vertex));
    std::vector<std::vector<float>> conforming;
    for (const SamplerChoices& choices : conformingChoices(seed + vertex, conformingPerInput)) {
      const UseSamplerChoices machine(choices);
      conforming.push_back(floatsOf(runListing<Sampled>(oracle, bindings, vertex)));
    }
    std::string input = fmt::format("{} vertex {}:", oracle, vertex);
    for (const auto& [name, stream] : bindings.attributes) {
      const auto c = static_cast<std::size_t>(stream.components);
      input += fmt::format(
          " {}=[{:.9g}]", name,
          fmt::join(stream.data.begin() + static_cast<std::ptrdiff_t>(vertex * c),
                    stream.data.begin() + static_cast<std::ptrdiff_t>(vertex * c + c), ","));
    }
    std::size_t offset = 0;
    for (std::size_t output = 0; output < snell.size(); ++output) {
      SampleRecord& record = records[output].emplace_back();
      record.snell = snell[output][vertex];
      const std::size_t components = record.snell.hull.lo.size();
      const auto slice = [&](const auto& all) {
        return std::vector(all.begin() + static_cast<std::ptrdiff_t>(offset),
                           all.begin() + static_cast<std::ptrdiff_t>(offset + components));
      };
      record.reference = slice(reference);
      record.deqp = slice(deqp);
      for (const std::vector<float>& values : conforming)
        record.conforming.push_back(slice(values));
      record.input = input;
      offset += components;
    }
  }
  return records;
}

}  // namespace snell::widths
