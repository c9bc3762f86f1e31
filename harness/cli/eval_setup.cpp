#include "cli/eval_setup.h"

#include <fmt/format.h>

#include <charconv>
#include <cstdlib>
#include <string_view>

#include "backends/backend_registry.h"
#include "core/errors.h"
#include "core/message.h"
#include "runner/block_pool.h"
#include "runner/oracle_store/oracle_store.h"

namespace snell::cli {
namespace {

// A whole number from 1 to `most` from the environment (a tuning knob for
// tests and benchmarks), or `fallback` when it is not set.
std::size_t positiveFromEnvironment(const char* name, std::size_t fallback, std::size_t most) {
  const char* text = std::getenv(name);
  if (!text || !*text) return fallback;
  const std::string_view view(text);
  std::size_t value = 0;
  const auto [end, error] = std::from_chars(view.data(), view.data() + view.size(), value);
  if (error != std::errc() || end != view.data() + view.size() || value == 0 || value > most)
    throw UsageError(
        fmt::format("{}={}: give a whole number from 1 to {}, or unset it", name, view, most));
  return value;
}

}  // namespace

std::unique_ptr<Backend> makeEvalBackend(const std::string& backend, const std::string& device,
                                         const std::string& glProvider) {
  BackendOptions options;
  options.device = device;
  options.glProvider = glProvider;
  // Only vk keeps anything there (its compiled probe programs).
  if (backendRegistry().find(backend).family == "vk") {
    const OracleStoreFolder folder = prepareOracleStoreDir(
        defaultOracleStoreDir(), "Set SNELL_ORACLE_CACHE to a folder, or to off to say so");
    if (!folder.note.empty()) printMessage(stderr, "snell: {}\n", folder.note);
    options.cacheDir = folder.dir.string();
  }
  return makeBackend(backend, options);
}

EvalOptions evalOptionsFromEnvironment() {
  EvalOptions options;
  // The limits keep a mistyped value from exhausting the machine: a
  // chunk's lines are held in memory together (a line of 4 components is
  // about 100 bytes), and each thread is one the process starts.
  constexpr std::size_t kMostChunkLines = std::size_t{1} << 24;
  constexpr std::size_t kMostThreads = 1024;
  options.chunkLines =
      positiveFromEnvironment("SNELL_EVAL_CHUNK", options.chunkLines, kMostChunkLines);
  options.threads = static_cast<unsigned>(
      positiveFromEnvironment("SNELL_EVAL_THREADS", defaultEvalThreads(), kMostThreads));
  return options;
}

}  // namespace snell::cli
