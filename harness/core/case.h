#pragma once
// A case is one [[case]] of one manifest: a listing in a scene. Its id is
// "<manifest id>/<scene>", which is what --filter matches.
#include <string>
#include <vector>

#include "core/manifest.h"
#include "core/scene.h"

namespace snell {

struct Case {
  std::string id;
  const Manifest* manifest = nullptr;
  CaseSpec spec;
};

// Cases of every manifest whose id matches the shell-style glob (empty: all).
std::vector<Case> expandCases(const std::vector<Manifest>& manifests, const std::string& glob);

// The concrete values a case binds: the manifest's names, the scene's floats.
struct ResolvedBindings {
  UniformMap uniforms;
  AttributeMap attributes;
  std::size_t vertexCount = 0;
};

// Throws UsageError (manifest file and line) for a semantic the scene lacks.
ResolvedBindings resolveBindings(const Manifest& manifest, const Scene& scene);

}  // namespace snell
