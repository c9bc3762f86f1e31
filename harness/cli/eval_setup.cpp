#include "cli/eval_setup.h"

#include <fmt/format.h>

#include <charconv>
#include <cstdlib>
#include <string_view>

#include "core/errors.h"
#include "runner/block_pool.h"
#include "runner/oracle_store/oracle_store.h"

namespace snell::cli {
namespace {

// A whole number of at least 1 from the environment (a tuning knob for
// tests and benchmarks), or `fallback` when it is not set.
std::size_t positiveFromEnvironment(const char* name, std::size_t fallback) {
  const char* text = std::getenv(name);
  if (!text || !*text) return fallback;
  const std::string_view view(text);
  std::size_t value = 0;
  const auto [end, error] = std::from_chars(view.data(), view.data() + view.size(), value);
  if (error != std::errc() || end != view.data() + view.size() || value == 0)
    throw UsageError(
        fmt::format("{}={}: give a whole number of at least 1, or unset it", name, view));
  return value;
}

}  // namespace

std::unique_ptr<Backend> makeEvalBackend(const std::string& backend, const std::string& device,
                                         const std::string& glProvider) {
  BackendOptions options;
  options.device = device;
  options.glProvider = glProvider;
  options.cacheDir = defaultOracleStoreDir().string();
  return makeBackend(backend, options);
}

EvalOptions evalOptionsFromEnvironment() {
  EvalOptions options;
  options.chunkLines = positiveFromEnvironment("SNELL_EVAL_CHUNK", options.chunkLines);
  options.threads =
      static_cast<unsigned>(positiveFromEnvironment("SNELL_EVAL_THREADS", defaultEvalThreads()));
  return options;
}

}  // namespace snell::cli
