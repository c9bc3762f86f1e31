#pragma once
// The bookkeeping GL's texture caches share (cube maps, 2D textures): a
// texture per source object, found by the source's address and trusted only
// while a hash of its content still matches, so a source freed and another
// allocated at the same address is uploaded afresh; kept across jobs, with
// the least recently used one not bound by the current job evicted when the
// cache is full. Must be destroyed while its context is current.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <map>
#include <span>

#include "backends/gl/gl_api.h"
#include "backends/gl/gl_error_check.h"

namespace snell {

// A hash of sizes and every float's bits: cheap next to an upload, and it
// sees any change, not just a sample. Four independent lanes, so that the
// multiplies overlap instead of waiting on each other (the faces of a 512
// environment are 25 MB).
class TexelHash {
 public:
  void mix(std::uint64_t value) { lanes_[next_++ % 4] ^= value; }
  void mix(std::span<const float> floats) {
    mix(floats.size());
    std::size_t i = 0;
    for (; i + 4 <= floats.size(); i += 4)
      for (std::size_t lane = 0; lane < 4; ++lane)
        lanes_[lane] = (lanes_[lane] ^ bits(floats[i + lane])) * kPrime;
    for (; i < floats.size(); ++i) lanes_[0] = (lanes_[0] ^ bits(floats[i])) * kPrime;
  }
  std::uint64_t value() const {
    std::uint64_t hash = 0;
    for (std::uint64_t lane : lanes_) hash = (hash ^ lane) * kPrime + (hash >> 29);
    return hash;
  }

 private:
  static constexpr std::uint64_t kPrime = 0x100000001b3ull;
  static std::uint32_t bits(float f) {
    std::uint32_t out;
    std::memcpy(&out, &f, sizeof out);
    return out;
  }
  std::uint64_t lanes_[4] = {0xcbf29ce484222325ull, 0x84222325cbf29ce4ull, 0x9e3779b97f4a7c15ull,
                             0xbf58476d1ce4e5b9ull};
  std::size_t next_ = 0;
};

template <class Source>
class GlTextureCache {
 public:
  struct Entry {
    GLuint id = 0;
    bool uploaded = false;  // false until an upload finished: a failed one is never trusted
    std::uint64_t hash = 0;
    std::uint64_t lastJob = 0;
  };

  GlTextureCache() = default;
  GlTextureCache(const GlTextureCache&) = delete;
  GlTextureCache& operator=(const GlTextureCache&) = delete;
  ~GlTextureCache() {
    for (auto& [source, entry] : entries_) glDeleteTextures(1, &entry.id);
  }

  // Starts a job: textures used from here on are kept until it ends.
  void beginJob() { ++job_; }

  // The entry for `source`, made on first use; marks it used by this job.
  Entry& entryFor(const Source& source) {
    auto found = entries_.find(&source);
    if (found == entries_.end()) {
      if (entries_.size() >= kCapacity) evictOneUnusedThisJob();
      Entry entry;
      glGenTextures(1, &entry.id);
      throwOnGlError("glGenTextures");
      found = entries_.emplace(&source, entry).first;
    }
    found->second.lastJob = job_;
    return found->second;
  }

 private:
  // Kept across jobs; one job that samples more still gets them all.
  static constexpr std::size_t kCapacity = 8;

  void evictOneUnusedThisJob() {
    auto oldest = entries_.end();
    for (auto entry = entries_.begin(); entry != entries_.end(); ++entry) {
      if (entry->second.lastJob == job_) continue;
      if (oldest == entries_.end() || entry->second.lastJob < oldest->second.lastJob)
        oldest = entry;
    }
    if (oldest == entries_.end()) return;  // every texture serves this job
    glDeleteTextures(1, &oldest->second.id);
    entries_.erase(oldest);
  }

  std::map<const Source*, Entry> entries_;
  std::uint64_t job_ = 0;
};

}  // namespace snell
