// The registered check kinds: adding one is its own files and a line here.
#include <fmt/format.h>

#include "core/errors.h"
#include "core/toml_keys.h"
#include "runner/checks/check_kind.h"
#include "runner/checks/image_check_kind.h"
#include "runner/checks/vector_check_kind.h"

namespace snell {

const std::vector<std::unique_ptr<CheckKind>>& checkKinds() {
  static const std::vector<std::unique_ptr<CheckKind>> kinds = [] {
    std::vector<std::unique_ptr<CheckKind>> all;
    all.push_back(std::make_unique<VectorCheckKind>());
    all.push_back(std::make_unique<ImageCheckKind>());
    return all;
  }();
  return kinds;
}

const CheckKind* findCheckKind(const std::string& name) {
  for (const auto& kind : checkKinds())
    if (kind->name() == name) return kind.get();
  return nullptr;
}

void requireKnownChecks(const Case& c) {
  std::vector<std::string> names;
  for (const auto& kind : checkKinds()) names.push_back(kind->name());
  for (const std::string& check : c.spec.checks) {
    if (findCheckKind(check)) continue;
    const std::string nearest = nearestKey(check, names);
    std::string known;
    for (const std::string& name : names) known += (known.empty() ? "\"" : ", \"") + name + "\"";
    throw UsageError(
        fmt::format("{}:{}: check `{}` is not known; {}known checks: {}", c.manifest->path.string(),
                    c.spec.line, check,
                    nearest.empty() ? "" : fmt::format("did you mean \"{}\"? ", nearest), known));
  }
}

}  // namespace snell
