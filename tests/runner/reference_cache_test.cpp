// The CPU reference image is rendered once per run, whatever the number of
// backends: a second worker of the same run reads the first one's, bit for
// bit; another run, or a damaged file, renders it again.
#include "runner/reference_cache.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>

#include "runner/case_runner.h"

namespace snell {
namespace {

namespace fs = std::filesystem;

class SharedReference : public ::testing::Test {
 protected:
  void SetUp() override {
    out_ = fs::temp_directory_path() / ("snell-reference-cache-" + std::to_string(getpid()));
    fs::remove_all(out_);
    manifests_ = loadManifests(SNELL_SOURCE_ROOT "/shaders/orange-book/14.1-fresnel");
    for (Case& c : expandCases(manifests_, "*/sphere")) case_ = c;
    ASSERT_EQ(case_.id, "orange-book/14.1-fresnel/sphere");
  }
  void TearDown() override { fs::remove_all(out_); }

  const ReferenceImage& reference(ReferenceCache& cache) {
    const Scene& scene = scenes_.get(case_.spec.scene);
    bindings_.push_back(resolveBindings(*case_.manifest, scene));
    return cache.get(case_, scene, bindings_.back());
  }

  fs::path out_;
  std::vector<Manifest> manifests_;
  Case case_;
  SceneCache scenes_;
  std::vector<ResolvedBindings> bindings_;
};

TEST_F(SharedReference, SecondWorkerOfTheRunReadsTheFirstOnesBitForBit) {
  ReferenceCache first(out_, "run-1"), second(out_, "run-1");
  const ReferenceImage& a = reference(first);
  const ReferenceImage& b = reference(second);
  EXPECT_EQ(first.rendered(), 1u);
  EXPECT_EQ(second.rendered(), 0u);
  EXPECT_EQ(a.color.pixels, b.color.pixels);
  EXPECT_EQ(a.mask, b.mask);
  reference(second);  // then from memory
  EXPECT_EQ(second.rendered(), 0u);
}

TEST_F(SharedReference, AnotherRunRendersItsOwn) {
  ReferenceCache earlier(out_, "run-1"), later(out_, "run-2");
  const ReferenceImage& a = reference(earlier);
  const ReferenceImage& b = reference(later);
  EXPECT_EQ(later.rendered(), 1u);
  EXPECT_EQ(a.color.pixels, b.color.pixels);
}

TEST_F(SharedReference, ADamagedSharedFileIsRenderedAgain) {
  ReferenceCache first(out_, "run-1"), second(out_, "run-1");
  const ReferenceImage& a = reference(first);
  const fs::path exr = out_ / case_.id / "reference.exr";
  fs::resize_file(exr, fs::file_size(exr) / 2);
  const ReferenceImage& b = reference(second);
  EXPECT_EQ(second.rendered(), 1u);
  EXPECT_EQ(a.color.pixels, b.color.pixels);
}

// Across runs through the oracle store: a later run reads the reference the
// first one rendered, bit for bit, for a hand-written listing's drawing
// oracle and for one derived from the listing's text.
TEST_F(SharedReference, ALaterRunReadsTheStoredReferenceBitForBit) {
  const OracleStore store(out_ / "store");
  ReferenceCache first(out_, "run-1", store), later(out_, "run-2", store);
  const ReferenceImage& a = reference(first);
  EXPECT_EQ(first.rendered(), 1u);
  EXPECT_EQ(first.fromStore(), 0u);
  const ReferenceImage& b = reference(later);
  EXPECT_EQ(later.rendered(), 0u);
  EXPECT_EQ(later.fromStore(), 1u);
  ASSERT_EQ(a.color.pixels.size(), b.color.pixels.size());
  EXPECT_EQ(std::memcmp(a.color.pixels.data(), b.color.pixels.data(),
                        a.color.pixels.size() * sizeof(float)),
            0);
  EXPECT_EQ(a.mask, b.mask);
}

TEST(DrawingOracleIdentity, DerivedOnesFollowTheListingsText) {
  const std::vector<Manifest> reflection =
      loadManifests(SNELL_SOURCE_ROOT "/shaders/learnopengl/reflection");
  const std::vector<Manifest> refraction =
      loadManifests(SNELL_SOURCE_ROOT "/shaders/learnopengl/refraction");
  const DrawingOracles a = drawingOracles(reflection.at(0));
  const DrawingOracles b = drawingOracles(refraction.at(0));
  ASSERT_EQ(a.label, "derived");
  EXPECT_FALSE(a.identity.empty());
  EXPECT_NE(a.identity, b.identity);
  EXPECT_NE(a.identity.find("reflection"), std::string::npos) << "names the listing's files";
}

}  // namespace
}  // namespace snell
