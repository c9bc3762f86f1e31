#include "core/sealed_record.h"

namespace snell {
namespace {

struct Header {
  RecordTag tag;
  Digest key;
  Digest payloadDigest;
  std::uint64_t payloadSize;
};
static_assert(std::is_trivially_copyable_v<Header>);

bool sameTag(const RecordTag& a, const RecordTag& b) {
  return std::memcmp(a.magic, b.magic, sizeof a.magic) == 0 && a.format == b.format &&
         a.kind == b.kind;
}

}  // namespace

std::string sealRecord(const RecordTag& tag, const Digest& key, std::string_view payload) {
  Header header{};
  header.tag = tag;
  header.key = key;
  header.payloadDigest = digestOf(payload);
  header.payloadSize = payload.size();
  std::string bytes(reinterpret_cast<const char*>(&header), sizeof header);
  bytes.append(payload);
  return bytes;
}

std::optional<std::string_view> openRecord(const RecordTag& tag, const Digest& key,
                                           std::string_view bytes) {
  Header header;
  if (bytes.size() < sizeof header) return std::nullopt;
  std::memcpy(&header, bytes.data(), sizeof header);
  const std::string_view payload = bytes.substr(sizeof header);
  if (!sameTag(header.tag, tag) || !(header.key == key) || header.payloadSize != payload.size() ||
      !(digestOf(payload) == header.payloadDigest))
    return std::nullopt;
  return payload;
}

}  // namespace snell
