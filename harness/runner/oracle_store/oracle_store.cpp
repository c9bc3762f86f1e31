#include "runner/oracle_store/oracle_store.h"

#include <fmt/format.h>

#include <cctype>
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
    return isOracleStoreOff(chosen) ? fs::path() : fs::path(chosen);
  if (const std::string xdg = env("XDG_CACHE_HOME"); !xdg.empty())
    return fs::path(xdg) / "snell" / "oracle";
  if (const std::string home = env("HOME"); !home.empty())
    return fs::path(home) / ".cache" / "snell" / "oracle";
  return {};
}

bool isOracleStoreOff(const std::string& value) {
  return value.size() == 3 && std::tolower(value[0]) == 'o' && std::tolower(value[1]) == 'f' &&
         std::tolower(value[2]) == 'f';
}

OracleStoreFolder prepareOracleStoreDir(const fs::path& dir, const std::string& howToChoose) {
  if (dir.empty()) return {};
  std::error_code made, looked;
  fs::create_directories(dir, made);
  std::string why;
  // A folder this user may only read is still used: its results are read,
  // and new ones are not kept (KeyedFileStore).
  if (!fs::is_directory(dir, looked))
    why = fs::exists(dir, looked) ? "not a folder" : made ? made.message() : "cannot be made";
  if (why.empty()) return {fs::absolute(dir), ""};
  return {{},
          fmt::format("{}: cannot keep oracle results or compiled programs here ({}); each is "
                      "computed afresh. {}",
                      dir.string(), why, howToChoose)};
}

}  // namespace snell
