#pragma once
// `snell init`: a first manifest for a folder of GLSL files, drafted from
// the listing's declarations, so a user gates a shader without writing the
// manifest from nothing. Inputs and uniforms are bound to scene semantics
// where the names and types say which (core/shader_conventions.h); every
// other one is written as a `"FILL IN: <type>"` line that loadManifest
// refuses, naming its line, until the author replaces it. No `oracle` line:
// the derived oracle follows the listing's own text.
#include <filesystem>
#include <functional>
#include <string>

namespace snell {

struct DraftRequest {
  std::filesystem::path dir;
  std::string vertexFile;    // relative to dir; empty: the one *.vert file there
  std::string fragmentFile;  // relative to dir; empty: the one *.frag file there, if any
  std::string id;            // empty: the folder's parent and name ("learnopengl/refraction")
  // Why the oracle could not gate the value `name` of a stage after `line`
  // (0: at the end of main()), or "" when it can: a value that goes
  // through inverse(), whose precision GLSL leaves undefined, is not
  // captured. The command asks the derived oracle (harness/derived), which
  // core does not know; unset, every candidate is captured.
  std::function<std::string(const std::string& file, const std::string& text, bool fragment,
                            const std::string& name, int line)>
      whyNotGated = {};
};

// The manifest text for the listing in request.dir. Throws UsageError (one
// line: what is wrong, what to do) for a missing folder, no or several
// candidate stage files, a stage without main(), or nothing to read back.
std::string draftManifest(const DraftRequest& request);

// The text, and whether its cases compare images (a fragment stage): a new
// listing's image case needs its golden blessed before it runs.
struct Draft {
  std::string text;
  bool imageCases = false;
};
Draft draftOf(const DraftRequest& request);

// Writes the draft to dir/manifest.toml; an existing manifest is a
// UsageError unless `force`.
struct DraftWritten {
  std::filesystem::path path;
  bool imageCases = false;
};
DraftWritten writeDraftManifest(const DraftRequest& request, bool force);

}  // namespace snell
