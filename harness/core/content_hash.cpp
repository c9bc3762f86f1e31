#include "core/content_hash.h"

#include <fmt/format.h>
#include <xxhash.h>

#include <stdexcept>

namespace snell {

struct ContentHash::State {
  XXH3_state_t* xxh = XXH3_createState();
  ~State() { XXH3_freeState(xxh); }
};

ContentHash::ContentHash() : state_(std::make_unique<State>()) {
  if (!state_->xxh || XXH3_128bits_reset(state_->xxh) != XXH_OK) throw std::bad_alloc();
}

ContentHash::~ContentHash() = default;

void ContentHash::addBytes(const void* data, std::size_t size) {
  if (size) XXH3_128bits_update(state_->xxh, data, size);
}

void ContentHash::add(std::string_view text) {
  add(static_cast<std::uint64_t>(text.size()));
  addBytes(text.data(), text.size());
}

Digest ContentHash::finish() const {
  XXH128_canonical_t canonical;
  XXH128_canonicalFromHash(&canonical, XXH3_128bits_digest(state_->xxh));
  Digest d;
  static_assert(sizeof canonical.digest == sizeof d.bytes);
  for (std::size_t k = 0; k < d.bytes.size(); ++k) d.bytes[k] = canonical.digest[k];
  return d;
}

std::string Digest::hex() const {
  std::string text;
  text.reserve(32);
  for (std::uint8_t b : bytes) text += fmt::format("{:02x}", b);
  return text;
}

Digest digestOf(std::string_view bytes) {
  ContentHash hash;
  hash.addBytes(bytes.data(), bytes.size());
  return hash.finish();
}

}  // namespace snell
