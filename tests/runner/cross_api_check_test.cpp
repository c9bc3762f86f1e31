// Backend against backend (OpenGL against Vulkan, driver against driver):
// two images that differ beyond the warn threshold make both results
// CompatibilityWarning; equal images leave them Pass.
#include "runner/cross_api_check.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "compare/image_io.h"
#include "runner/image_check.h"

namespace snell {
namespace {

namespace fs = std::filesystem;

class CrossApi : public ::testing::Test {
 protected:
  void SetUp() override {
    out_ = fs::temp_directory_path() / ("snell-cross-api-" + std::to_string(getpid()));
    fs::create_directories(out_ / "a" / "sphere");
    manifest_.id = "a";
    spec_.scene = "sphere";
    spec_.checks = {"vectors", "image"};
    spec_.image = {0.004, 0.002, 0.0, 0.05};
    cases_.push_back({"a/sphere", &manifest_, spec_});
    Image flat(4, 4);
    std::fill(flat.pixels.begin(), flat.pixels.end(), 0.5f);
    gl_ = vk_ = flat;
    writeImageAtomically(maskImagePath(out_, "a/sphere"), Image(4, 4));  // nothing masked
  }
  void TearDown() override { fs::remove_all(out_); }

  std::vector<CaseResult> run() {
    writeImageAtomically(renderedImagePath(out_, "a/sphere", "gl"), gl_);
    writeImageAtomically(renderedImagePath(out_, "a/sphere", "vk"), vk_);
    std::vector<CaseResult> results(2);
    results[0].caseId = results[1].caseId = "a/sphere";
    results[0].backend = "gl";
    results[1].backend = "vk";
    checkAcrossApis(cases_, out_, results);
    return results;
  }

  // gl, gl:softpipe (drawing `softpipe`) and vk, their images written.
  std::vector<CaseResult> threeBackends(const Image& softpipe) {
    writeImageAtomically(renderedImagePath(out_, "a/sphere", "gl"), gl_);
    writeImageAtomically(renderedImagePath(out_, "a/sphere", "vk"), vk_);
    writeImageAtomically(renderedImagePath(out_, "a/sphere", "gl:softpipe"), softpipe);
    std::vector<CaseResult> results(3);
    for (CaseResult& r : results) r.caseId = "a/sphere";
    results[0].backend = "gl";
    results[1].backend = "gl:softpipe";
    results[2].backend = "vk";
    return results;
  }

  fs::path out_;
  Manifest manifest_;
  CaseSpec spec_;
  std::vector<Case> cases_;
  Image gl_, vk_;
};

TEST_F(CrossApi, EqualImagesStayPass) {
  for (const CaseResult& r : run()) {
    EXPECT_EQ(r.status, Status::Pass);
    ASSERT_EQ(r.images.size(), 1u);
    EXPECT_EQ(r.images[0].against, "other-backend:gl/vk");
  }
}

TEST_F(CrossApi, OnePixelBeyondWarnIsACompatibilityWarningOnBoth) {
  vk_.at(2, 1)[0] += 0.003f;
  for (const CaseResult& r : run()) {
    EXPECT_EQ(r.status, Status::CompatibilityWarning) << r.backend;
    EXPECT_NE(r.message.find("gl and vk differ"), std::string::npos) << r.message;
  }
}

TEST_F(CrossApi, AMissingImageIsReportedNotIgnored) {
  run();
  fs::remove(renderedImagePath(out_, "a/sphere", "vk"));
  std::vector<CaseResult> results(2);
  results[0].caseId = results[1].caseId = "a/sphere";
  results[0].backend = "gl";
  results[1].backend = "vk";
  checkAcrossApis(cases_, out_, results);
  EXPECT_EQ(results[0].status, Status::CompatibilityWarning);
  EXPECT_FALSE(results[0].images.at(0).problem.empty());
}

// Three backends make three pairs: each result is held against the two
// others, and only the pairs with the odd image out warn.
TEST_F(CrossApi, EveryPairOfBackendsIsCompared) {
  Image odd = gl_;
  odd.pixels[0] = 0.9f;
  std::vector<CaseResult> results = threeBackends(odd);
  checkAcrossApis(cases_, out_, results);
  for (const CaseResult& r : results) ASSERT_EQ(r.images.size(), 2u) << r.backend;
  EXPECT_EQ(results[0].status, Status::CompatibilityWarning);  // against gl:softpipe
  EXPECT_EQ(results[1].status, Status::CompatibilityWarning);
  EXPECT_EQ(results[2].status, Status::CompatibilityWarning);  // against gl:softpipe
  EXPECT_NE(results[1].message.find("gl and gl:softpipe differ"), std::string::npos)
      << results[1].message;
  EXPECT_EQ(results[0].message.find("gl and vk differ"), std::string::npos) << results[0].message;
}

// Shards merged: gl and vk ran in one job and were compared there;
// gl:softpipe ran in another. Only its two pairs are pending, and the gl/vk
// comparison is not made a second time.
TEST_F(CrossApi, APairComparedInItsOwnJobIsNotComparedAgain) {
  std::vector<CaseResult> results = threeBackends(gl_);
  ImageComparison done;
  done.against = "other-backend:gl/vk";
  results[0].images.push_back(done);
  results[2].images.push_back(done);
  const std::vector<BackendPair> pending = pendingBackendPairs(cases_, results);
  ASSERT_EQ(pending.size(), 2u);
  EXPECT_EQ(pending[0].a->backend + "/" + pending[0].b->backend, "gl/gl:softpipe");
  EXPECT_EQ(pending[1].a->backend + "/" + pending[1].b->backend, "gl:softpipe/vk");
  checkAcrossApis(cases_, out_, results);
  for (const CaseResult& r : results) {
    ASSERT_EQ(r.images.size(), 2u) << r.backend;
    EXPECT_EQ(r.status, Status::Pass) << r.backend;
  }
  EXPECT_TRUE(pendingBackendPairs(cases_, results).empty());
}

// The same when gl and vk warned against each other in their shard: a
// CompatibilityWarning (set by this check alone) is still an image within
// the spec, held against the backend it has not met.
TEST_F(CrossApi, AWarnedPairStillMeetsABackendFromAnotherShard) {
  std::vector<CaseResult> results = threeBackends(gl_);
  ImageComparison warned;
  warned.against = "other-backend:gl/vk";
  warned.verdict = ImageVerdict::Warn;
  for (CaseResult* r : {&results[0], &results[2]}) {
    r->images.push_back(warned);
    r->status = Status::CompatibilityWarning;
  }
  const std::vector<BackendPair> pending = pendingBackendPairs(cases_, results);
  ASSERT_EQ(pending.size(), 2u);
  checkAcrossApis(cases_, out_, results);
  EXPECT_EQ(results[1].images.size(), 2u);
  EXPECT_EQ(results[1].status, Status::Pass);
}

// A pair recorded on one side only (one result re-run beside its partner's
// kept one) gets the same comparison on the other, without a new one.
TEST_F(CrossApi, AComparisonOnOneSideIsCopiedToTheOther) {
  std::vector<CaseResult> results(2);
  results[0].caseId = results[1].caseId = "a/sphere";
  results[0].backend = "gl";
  results[1].backend = "vk";
  ImageComparison warned;
  warned.against = "other-backend:gl/vk";
  warned.verdict = ImageVerdict::Warn;
  warned.maxError = 0.003;
  results[0].images.push_back(warned);
  results[0].status = Status::CompatibilityWarning;
  checkAcrossApis(cases_, out_, results);  // no image written: none may be read
  ASSERT_EQ(results[0].images.size(), 1u);
  ASSERT_EQ(results[1].images.size(), 1u);
  EXPECT_EQ(results[1].images[0].maxError, 0.003);
  EXPECT_EQ(results[1].status, Status::CompatibilityWarning);
  EXPECT_NE(results[1].message.find("gl and vk differ"), std::string::npos) << results[1].message;
}

}  // namespace
}  // namespace snell
