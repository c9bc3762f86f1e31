#include "runner/oracle_store/oracle_store.h"

#include <cstdlib>
#include <string>

#include "runner/oracle_store/stored_result_format.h"

namespace snell {
namespace fs = std::filesystem;

std::optional<std::vector<OracleVarying>> OracleStore::load(const Digest& key) const {
  return kept(key, decodeStoredResult);
}

std::optional<ReferenceImage> OracleStore::loadReference(const Digest& key) const {
  return kept(key, decodeStoredReference);
}

bool OracleStore::save(const Digest& key, const std::vector<OracleVarying>& result) const {
  return write(key, encodeStoredResult(key, result));
}

bool OracleStore::saveReference(const Digest& key, const ReferenceImage& reference) const {
  return write(key, encodeStoredReference(key, reference));
}

fs::path defaultOracleStoreDir() {
  const auto env = [](const char* name) -> std::string {
    const char* value = std::getenv(name);
    return value ? value : "";
  };
  if (const std::string chosen = env("SNELL_ORACLE_CACHE"); !chosen.empty())
    return chosen == "off" ? fs::path() : fs::path(chosen);
  if (const std::string xdg = env("XDG_CACHE_HOME"); !xdg.empty())
    return fs::path(xdg) / "snell" / "oracle";
  if (const std::string home = env("HOME"); !home.empty())
    return fs::path(home) / ".cache" / "snell" / "oracle";
  return {};
}

}  // namespace snell
