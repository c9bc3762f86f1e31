#include "runner/oracle_store/stored_result_format.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>

#include "core/sealed_record.h"

namespace snell {
namespace {

// Interval bounds are floats or infinities: stored in four bytes when every
// one converts back to the same double, else in eight.
void putBounds(ByteWriter& w, const std::vector<double>& values) {
  bool narrow = true;
  for (double v : values)
    if (std::isnan(v) || static_cast<double>(static_cast<float>(v)) != v) narrow = false;
  w.put(static_cast<std::uint8_t>(narrow));
  if (!narrow) return w.putArray(values);
  const std::vector<float> floats(values.begin(), values.end());
  w.putArray(floats);
}

std::vector<double> getBounds(ByteReader& r) {
  const auto narrow = r.get<std::uint8_t>();
  if (narrow > 1) r.fail();
  if (narrow != 1) return r.getArray<double>();
  return r.getArrayAs<float, double>();
}

void putAlternative(ByteWriter& w, const OracleAlternative& way) {
  w.putArray(way.reference);
  w.putArray(way.lo);
  w.putArray(way.hi);
  w.putArray(way.undefined);
}

OracleAlternative getAlternative(ByteReader& r) {
  OracleAlternative way;
  way.reference = r.getArray<double>();
  way.lo = r.getArray<double>();
  way.hi = r.getArray<double>();
  way.undefined = r.getArray<std::uint8_t>();
  return way;
}

// Each kind of result: its tag in the header, how it is written, and how
// it is read back (false when what was read does not hold together).
enum class Kind : std::uint32_t { Vectors = 1, ReferenceImage = 2, Image = 3, Comparison = 4 };

void put(ByteWriter& w, const std::vector<OracleVarying>& result) {
  w.put(static_cast<std::uint64_t>(result.size()));
  for (const OracleVarying& v : result) {
    w.put(v.name);
    w.put(static_cast<std::int32_t>(v.components));
    w.put(static_cast<std::uint64_t>(v.mergedToHull));
    w.putArray(v.reference);
    w.putArray(v.strict);
    putBounds(w, v.lo);
    putBounds(w, v.hi);
    w.putArray(v.undefined);
    w.put(static_cast<std::uint64_t>(v.alternatives.size()));
    for (const SampleAlternatives& sample : v.alternatives) {
      w.put(static_cast<std::uint64_t>(sample.sample));
      w.put(static_cast<std::uint64_t>(sample.ways.size()));
      for (const OracleAlternative& way : sample.ways) putAlternative(w, way);
    }
  }
}

bool get(ByteReader& r, std::vector<OracleVarying>& result) {
  const auto count = r.get<std::uint64_t>();
  for (std::uint64_t k = 0; r.ok() && k < count; ++k) {
    OracleVarying v;
    v.name = r.getString();
    v.components = r.get<std::int32_t>();
    v.mergedToHull = r.get<std::uint64_t>();
    v.reference = r.getArray<double>();
    v.strict = r.getArray<float>();
    v.lo = getBounds(r);
    v.hi = getBounds(r);
    v.undefined = r.getArray<std::uint8_t>();
    const auto samples = r.get<std::uint64_t>();
    for (std::uint64_t s = 0; r.ok() && s < samples; ++s) {
      SampleAlternatives sample;
      sample.sample = r.get<std::uint64_t>();
      const auto ways = r.get<std::uint64_t>();
      for (std::uint64_t w = 0; r.ok() && w < ways; ++w) sample.ways.push_back(getAlternative(r));
      v.alternatives.push_back(std::move(sample));
    }
    result.push_back(std::move(v));
  }
  return true;
}

void put(ByteWriter& w, const Image& image) {
  w.put(static_cast<std::int32_t>(image.width));
  w.put(static_cast<std::int32_t>(image.height));
  w.putArray(image.pixels);
}

bool get(ByteReader& r, Image& image) {
  image.width = r.get<std::int32_t>();
  image.height = r.get<std::int32_t>();
  image.pixels = r.getArray<float>();
  return image.width >= 0 && image.height >= 0 &&
         image.pixels.size() ==
             static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4;
}

void put(ByteWriter& w, const ReferenceImage& reference) {
  put(w, reference.color);
  w.putArray(reference.mask);
}

bool get(ByteReader& r, ReferenceImage& reference) {
  const bool whole = get(r, reference.color);
  reference.mask = r.getArray<PixelMask>();
  return whole && reference.mask.size() == reference.color.pixels.size() / 4;
}

void put(ByteWriter& w, const ImageComparison& c) {
  w.put(c.against);
  w.put(static_cast<std::uint8_t>(c.verdict));
  for (double v : {c.maxError, c.meanError, c.rmsError, c.psnr}) w.put(v);
  w.put(static_cast<std::int32_t>(c.maxX));
  w.put(static_cast<std::int32_t>(c.maxY));
  for (std::size_t n : {c.compared, c.failed, c.warned}) w.put(static_cast<std::uint64_t>(n));
  w.put(static_cast<std::uint64_t>(c.masked.size()));
  for (const auto& [reason, count] : c.masked) {
    w.put(reason);
    w.put(static_cast<std::uint64_t>(count));
  }
  w.put(c.problem);
}

bool get(ByteReader& r, ImageComparison& c) {
  c.against = r.getString();
  const auto verdict = r.get<std::uint8_t>();
  c.verdict = static_cast<ImageVerdict>(verdict);
  for (double* v : {&c.maxError, &c.meanError, &c.rmsError, &c.psnr}) *v = r.get<double>();
  c.maxX = r.get<std::int32_t>();
  c.maxY = r.get<std::int32_t>();
  for (std::size_t* n : {&c.compared, &c.failed, &c.warned}) *n = r.get<std::uint64_t>();
  const auto reasons = r.get<std::uint64_t>();
  for (std::uint64_t k = 0; r.ok() && k < reasons; ++k) {
    std::string reason = r.getString();
    c.masked[reason] = r.get<std::uint64_t>();
  }
  c.problem = r.getString();
  return verdict <= static_cast<std::uint8_t>(ImageVerdict::Fail);
}

RecordTag tagOf(Kind kind) {
  return recordTag("snellorc", kStoredResultFormat, static_cast<std::uint32_t>(kind));
}

template <typename T>
std::string encode(const Digest& key, Kind kind, const T& value) {
  ByteWriter w;
  put(w, value);
  return sealRecord(tagOf(kind), key, w.take());
}

// The value, when the record is this format's, of this kind and key, the
// payload is whole, and it reads to its end.
template <typename T>
std::optional<T> decode(const Digest& key, Kind kind, std::string_view bytes) {
  const std::optional<std::string_view> payload = openRecord(tagOf(kind), key, bytes);
  if (!payload) return std::nullopt;
  ByteReader r(*payload);
  T value{};
  const bool consistent = get(r, value);
  if (!consistent || !r.ok() || !r.atEnd()) return std::nullopt;
  return value;
}

}  // namespace

std::string encodeStoredResult(const Digest& key, const std::vector<OracleVarying>& result) {
  return encode(key, Kind::Vectors, result);
}
std::optional<std::vector<OracleVarying>> decodeStoredResult(const Digest& key,
                                                             std::string_view bytes) {
  return decode<std::vector<OracleVarying>>(key, Kind::Vectors, bytes);
}

std::string encodeStoredReference(const Digest& key, const ReferenceImage& reference) {
  return encode(key, Kind::ReferenceImage, reference);
}
std::optional<ReferenceImage> decodeStoredReference(const Digest& key, std::string_view bytes) {
  return decode<ReferenceImage>(key, Kind::ReferenceImage, bytes);
}

std::string encodeStoredImage(const Digest& key, const Image& image) {
  return encode(key, Kind::Image, image);
}
std::optional<Image> decodeStoredImage(const Digest& key, std::string_view bytes) {
  return decode<Image>(key, Kind::Image, bytes);
}

std::string encodeStoredComparison(const Digest& key, const ImageComparison& comparison) {
  return encode(key, Kind::Comparison, comparison);
}
std::optional<ImageComparison> decodeStoredComparison(const Digest& key, std::string_view bytes) {
  return decode<ImageComparison>(key, Kind::Comparison, bytes);
}

}  // namespace snell
