// snell init DIR: a first manifest for a folder of GLSL files
// (core/manifest_draft.h), for the author to finish and run.
#include <fmt/format.h>

#include <filesystem>

#include "cli/commands.h"
#include "cli/shell_word.h"
#include "core/errors.h"
#include "core/manifest.h"
#include "core/manifest_draft.h"
#include "derived/lower_glsl.h"

namespace snell::cli {

Command addInitCommand(CLI::App& app) {
  CLI::App* init = app.add_subcommand(
      "init", "Draft DIR/manifest.toml from the listing's GLSL files in DIR (derived oracle)");
  struct Options {
    DraftRequest request;
    std::string dir;
    bool force = false;
  };
  auto options = std::make_shared<Options>();
  init->add_option("dir", options->dir, "Folder holding the listing's .vert and .frag files")
      ->required();
  init->add_option("--vertex", options->request.vertexFile,
                   "The vertex stage file, relative to DIR (default: the one *.vert in DIR)");
  init->add_option("--fragment", options->request.fragmentFile,
                   "The fragment stage file, relative to DIR (default: the one *.frag in DIR, "
                   "if any)");
  init->add_option("--id", options->request.id,
                   "The listing's id (default: DIR's parent and name, \"parent/name\")")
      ->check(CLI::Validator([](const std::string& id) { return listingIdProblem(id); }, "ID"));
  init->add_flag("--force", options->force, "Replace an existing DIR/manifest.toml");
  return [options] {
    options->request.dir = options->dir;
    // Captured only what the derived oracle can gate; its refusal, without
    // the advice, says why not.
    options->request.whyNotGated = [](const std::string& file, const std::string& text,
                                      bool fragment, const std::string& name, int line) {
      try {
        derived::lowerOutputs(
            {file, text, fragment ? derived::Stage::Fragment : derived::Stage::Vertex},
            {{name, line}});
        return std::string();
      } catch (const UsageError& error) {
        const std::string what = error.what();
        return what.substr(0, what.find("; give the listing"));
      }
    };
    const DraftWritten written = writeDraftManifest(options->request, options->force);
    const std::string path = written.path.string();
    const std::string dir = shellWord(options->dir);
    // An image case of a new listing fails on its missing golden wherever
    // the driver has goldens for other listings: blessing comes first.
    // Their goldens go to a folder of the user's own: the default one is
    // the catalog's, in snell's source tree.
    const std::string golden = shellWord((std::filesystem::path(options->dir) / "golden").string());
    if (written.imageCases)
      fmt::print(
          "wrote {}: fill in the lines marked FILL IN, then `mkdir -p {} && snell bless --shaders "
          "{} --golden {}` to write the image cases' goldens into a folder of your own (only "
          "images that match the CPU reference are blessed), and `snell run --shaders {} "
          "--golden {}`\n",
          path, golden, dir, golden, dir, golden);
    else
      fmt::print("wrote {}: fill in the lines marked FILL IN, then run `snell run --shaders {}`\n",
                 path, dir);
    return 0;
  };
}

}  // namespace snell::cli
