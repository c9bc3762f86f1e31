#include "runner/eval_line_fast.h"

#include <charconv>
#include <cmath>
#include <cstdint>

namespace snell {
namespace {

// A cursor over one line; every reader returns false where the line leaves
// the common shape.
class Reader {
 public:
  explicit Reader(std::string_view text) : at_(text.data()), end_(text.data() + text.size()) {}

  bool atEnd() const { return at_ == end_; }

  void skipSpace() {
    while (at_ != end_ && (*at_ == ' ' || *at_ == '\t' || *at_ == '\n' || *at_ == '\r')) ++at_;
  }

  bool take(char c) {
    skipSpace();
    if (at_ == end_ || *at_ != c) return false;
    ++at_;
    return true;
  }

  // A string with no escapes (those go to nlohmann).
  bool string(std::string_view& out) {
    if (!take('"')) return false;
    const char* begin = at_;
    while (at_ != end_ && *at_ != '"') {
      const auto c = static_cast<unsigned char>(*at_);
      if (c == '\\' || c < 0x20 || c >= 0x80) return false;
      ++at_;
    }
    if (at_ == end_) return false;
    out = std::string_view(begin, static_cast<std::size_t>(at_ - begin));
    ++at_;
    return true;
  }

  // A JSON number, converted as nlohmann converts it and then as
  // parseEvalObject does: a whole number is read as a 64-bit integer where
  // it fits (so "-0" is +0), anything else as the nearest double; then the
  // nearest float.
  bool number(float& out) {
    skipSpace();
    const char* begin = at_;
    bool whole = true;
    if (at_ != end_ && *at_ == '-') ++at_;
    if (at_ == end_) return false;
    if (*at_ == '0') {
      ++at_;
    } else if (*at_ >= '1' && *at_ <= '9') {
      while (at_ != end_ && isDigit(*at_)) ++at_;
    } else {
      return false;
    }
    if (at_ != end_ && *at_ == '.') {
      whole = false;
      ++at_;
      if (!digits()) return false;
    }
    if (at_ != end_ && (*at_ == 'e' || *at_ == 'E')) {
      whole = false;
      ++at_;
      if (at_ != end_ && (*at_ == '+' || *at_ == '-')) ++at_;
      if (!digits()) return false;
    }
    if (whole) {
      if (*begin == '-') {
        std::int64_t value = 0;
        if (std::from_chars(begin, at_, value).ec == std::errc()) {
          out = static_cast<float>(static_cast<double>(value));
          return !std::isinf(out);
        }
      } else {
        std::uint64_t value = 0;
        if (std::from_chars(begin, at_, value).ec == std::errc()) {
          out = static_cast<float>(static_cast<double>(value));
          return !std::isinf(out);
        }
      }
    }
    // Out of range (nlohmann rejects an overflow; an underflow it reads as
    // strtod does): nlohmann decides. So does a number past the float
    // range, which the slow path refuses.
    double value = 0;
    const auto [end, error] = std::from_chars(begin, at_, value);
    if (error != std::errc() || end != at_) return false;
    out = static_cast<float>(value);
    return !std::isinf(out);
  }

  // [n, n, ...] with 1 to 4 numbers.
  bool vector(std::vector<float>& out) {
    if (!take('[')) return false;
    out.clear();
    do {
      if (out.size() == 4) return false;
      float x = 0;
      if (!number(x)) return false;
      out.push_back(x);
    } while (take(','));
    return take(']');
  }

 private:
  static bool isDigit(char c) { return c >= '0' && c <= '9'; }
  bool digits() {
    if (at_ == end_ || !isDigit(*at_)) return false;
    while (at_ != end_ && isDigit(*at_)) ++at_;
    return true;
  }

  const char* at_;
  const char* end_;
};

}  // namespace

std::optional<BuiltinCall> parseCommonEvalLine(std::string_view text) {
  Reader in(text);
  BuiltinCall call;
  bool hasFn = false, hasI = false, hasN = false, hasEta = false;
  if (!in.take('{')) return std::nullopt;
  do {
    std::string_view key;
    if (!in.string(key) || !in.take(':')) return std::nullopt;
    if (key == "fn" && !hasFn) {
      std::string_view fn;
      if (!in.string(fn) || (fn != "reflect" && fn != "refract")) return std::nullopt;
      call.fn = fn;
      hasFn = true;
    } else if (key == "I" && !hasI) {
      if (!in.vector(call.I)) return std::nullopt;
      hasI = true;
    } else if (key == "N" && !hasN) {
      if (!in.vector(call.N)) return std::nullopt;
      hasN = true;
    } else if (key == "eta" && !hasEta) {
      if (!in.number(call.eta)) return std::nullopt;
      hasEta = true;
    } else {
      return std::nullopt;
    }
  } while (in.take(','));
  if (!in.take('}')) return std::nullopt;
  in.skipSpace();
  if (!in.atEnd() || !hasFn || !hasI || !hasN || call.I.size() != call.N.size())
    return std::nullopt;
  if (call.fn == "refract" && !hasEta) return std::nullopt;
  if (call.fn == "reflect") call.eta = 1.0f;  // parseEvalObject leaves a reflect's eta alone
  return call;
}

}  // namespace snell
