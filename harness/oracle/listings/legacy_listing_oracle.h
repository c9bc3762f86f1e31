#pragma once
// The oracle of a legacy listing, one that reads OpenGL's fixed-function
// state (gl_ModelViewMatrix, gl_NormalMatrix, ftransform()). A manifest
// binds only what an application sets (gl_ModelViewMatrix,
// gl_ProjectionMatrix, gl_TextureMatrix[k]); GL derives gl_NormalMatrix and
// gl_ModelViewProjectionMatrix from them. The oracle gets those derived
// values from the same function the Vulkan backend binds them from
// (core/legacy_builtins.h), so both are held to the listing with the same
// fp32 inputs; Mesa's OpenGL derives the same bits (tests/gl).
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/legacy_builtins.h"
#include "oracle/listings/listing_oracle.h"

namespace snell::listings {

template <template <class> class Shader>
class LegacyListingOracle final : public VertexOracle {
 public:
  explicit LegacyListingOracle(std::string name) : inner_(std::move(name)) {}

  std::vector<std::string> outputs() const override { return inner_.outputs(); }

  std::vector<OracleVarying> evaluate(const OracleInput& input) const override {
    const UniformMap uniforms = withDerivedLegacyState(input.uniforms);
    return inner_.evaluate(
        {uniforms, input.constants, input.attributes, input.vertexCount, input.rules});
  }

 private:
  ListingOracle<Shader> inner_;
};

template <template <class> class Shader>
std::unique_ptr<VertexOracle> makeLegacyListingOracle(std::string name) {
  return std::make_unique<LegacyListingOracle<Shader>>(std::move(name));
}

}  // namespace snell::listings
