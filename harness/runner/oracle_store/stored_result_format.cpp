#include "runner/oracle_store/stored_result_format.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace snell {
namespace {

constexpr char kMagic[8] = {'s', 'n', 'e', 'l', 'l', 'o', 'r', 'c'};

class Writer {
 public:
  template <typename T>
  requires std::is_trivially_copyable_v<T>
  void put(const T& value) { out_.append(reinterpret_cast<const char*>(&value), sizeof value); }
  void put(const std::string& text) {
    put(static_cast<std::uint64_t>(text.size()));
    out_ += text;
  }
  template <typename T>
  void putArray(const std::vector<T>& values) {
    put(static_cast<std::uint64_t>(values.size()));
    out_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  }
  // Interval bounds are floats or infinities: stored in four bytes when
  // every one converts back to the same double, else in eight.
  void putBounds(const std::vector<double>& values) {
    bool narrow = true;
    for (double v : values)
      if (std::isnan(v) || static_cast<double>(static_cast<float>(v)) != v) narrow = false;
    put(static_cast<std::uint8_t>(narrow));
    if (!narrow) return putArray(values);
    std::vector<float> floats(values.begin(), values.end());
    putArray(floats);
  }
  std::string take() { return std::move(out_); }

 private:
  std::string out_;
};

// Every read is checked against the end: damaged bytes make `ok` false,
// never an out-of-bounds read or a huge allocation.
class Reader {
 public:
  explicit Reader(std::string_view bytes) : at_(bytes.data()), end_(bytes.data() + bytes.size()) {}
  bool ok() const { return ok_; }
  bool atEnd() const { return at_ == end_; }

  template <typename T>
  requires std::is_trivially_copyable_v<T> T get() {
    T value{};
    if (!take(&value, sizeof value)) return T{};
    return value;
  }
  std::string getString() {
    const auto size = get<std::uint64_t>();
    if (!fits(size, 1)) return {};
    std::string text(at_, size);
    at_ += size;
    return text;
  }
  template <typename T>
  std::vector<T> getArray() {
    const auto count = get<std::uint64_t>();
    if (!fits(count, sizeof(T))) return {};
    std::vector<T> values(count);
    take(values.data(), count * sizeof(T));
    return values;
  }
  std::vector<double> getBounds() {
    const auto narrow = get<std::uint8_t>();
    if (narrow > 1) ok_ = false;
    if (narrow != 1) return getArray<double>();
    const std::vector<float> floats = getArray<float>();
    return {floats.begin(), floats.end()};
  }

 private:
  bool fits(std::uint64_t count, std::size_t size) {
    if (ok_ && count <= static_cast<std::uint64_t>(end_ - at_) / size) return true;
    ok_ = false;
    return false;
  }
  bool take(void* out, std::size_t size) {
    if (!fits(size, 1)) return false;
    std::memcpy(out, at_, size);
    at_ += size;
    return true;
  }
  const char* at_;
  const char* end_;
  bool ok_ = true;
};

void putAlternative(Writer& w, const OracleAlternative& way) {
  w.putArray(way.reference);
  w.putArray(way.lo);
  w.putArray(way.hi);
  w.putArray(way.undefined);
}

OracleAlternative getAlternative(Reader& r) {
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

void put(Writer& w, const std::vector<OracleVarying>& result) {
  w.put(static_cast<std::uint64_t>(result.size()));
  for (const OracleVarying& v : result) {
    w.put(v.name);
    w.put(static_cast<std::int32_t>(v.components));
    w.put(static_cast<std::uint64_t>(v.mergedToHull));
    w.putArray(v.reference);
    w.putArray(v.strict);
    w.putBounds(v.lo);
    w.putBounds(v.hi);
    w.putArray(v.undefined);
    w.put(static_cast<std::uint64_t>(v.alternatives.size()));
    for (const SampleAlternatives& sample : v.alternatives) {
      w.put(static_cast<std::uint64_t>(sample.sample));
      w.put(static_cast<std::uint64_t>(sample.ways.size()));
      for (const OracleAlternative& way : sample.ways) putAlternative(w, way);
    }
  }
}

bool get(Reader& r, std::vector<OracleVarying>& result) {
  const auto count = r.get<std::uint64_t>();
  for (std::uint64_t k = 0; r.ok() && k < count; ++k) {
    OracleVarying v;
    v.name = r.getString();
    v.components = r.get<std::int32_t>();
    v.mergedToHull = r.get<std::uint64_t>();
    v.reference = r.getArray<double>();
    v.strict = r.getArray<float>();
    v.lo = r.getBounds();
    v.hi = r.getBounds();
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

void put(Writer& w, const Image& image) {
  w.put(static_cast<std::int32_t>(image.width));
  w.put(static_cast<std::int32_t>(image.height));
  w.putArray(image.pixels);
}

bool get(Reader& r, Image& image) {
  image.width = r.get<std::int32_t>();
  image.height = r.get<std::int32_t>();
  image.pixels = r.getArray<float>();
  return image.width >= 0 && image.height >= 0 &&
         image.pixels.size() ==
             static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4;
}

void put(Writer& w, const ReferenceImage& reference) {
  put(w, reference.color);
  w.putArray(reference.mask);
}

bool get(Reader& r, ReferenceImage& reference) {
  const bool whole = get(r, reference.color);
  reference.mask = r.getArray<PixelMask>();
  return whole && reference.mask.size() == reference.color.pixels.size() / 4;
}

void put(Writer& w, const ImageComparison& c) {
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

bool get(Reader& r, ImageComparison& c) {
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

struct Header {
  char magic[8];
  std::uint32_t format;
  Kind kind;
  Digest key;
  Digest payloadDigest;
  std::uint64_t payloadSize;
};
static_assert(std::is_trivially_copyable_v<Header>);

template <typename T>
std::string encode(const Digest& key, Kind kind, const T& value) {
  Writer w;
  put(w, value);
  const std::string payload = w.take();
  Header header{};
  std::memcpy(header.magic, kMagic, sizeof kMagic);
  header.format = kStoredResultFormat;
  header.kind = kind;
  header.key = key;
  header.payloadDigest = digestOf(payload);
  header.payloadSize = payload.size();
  std::string bytes(reinterpret_cast<const char*>(&header), sizeof header);
  return bytes + payload;
}

// The value, when the header is this format's, of this kind and key, the
// payload is whole, and it reads to its end.
template <typename T>
std::optional<T> decode(const Digest& key, Kind kind, std::string_view bytes) {
  Header header;
  if (bytes.size() < sizeof header) return std::nullopt;
  std::memcpy(&header, bytes.data(), sizeof header);
  const std::string_view payload = bytes.substr(sizeof header);
  if (std::memcmp(header.magic, kMagic, sizeof kMagic) != 0 ||
      header.format != kStoredResultFormat || header.kind != kind || !(header.key == key) ||
      header.payloadSize != payload.size() || !(digestOf(payload) == header.payloadDigest))
    return std::nullopt;
  Reader r(payload);
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
