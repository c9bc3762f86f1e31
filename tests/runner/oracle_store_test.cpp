// Oracle results kept across runs (runner/oracle_store): a stored result
// reads back bit for bit, a damaged or foreign file reads as nothing, every
// part of the input changes the key, the trim drops the least recently used
// first, and OracleCache computes only what the store does not hold.
#include "runner/oracle_store/oracle_store.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <thread>

#include "compare/image_io.h"
#include "core/build_id.h"
#include "core/content_hash.h"
#include "core/errors.h"
#include "runner/case_runner.h"
#include "runner/oracle_cache.h"
#include "runner/oracle_store/image_results.h"
#include "runner/oracle_store/oracle_store_key.h"
#include "runner/oracle_store/stored_result_format.h"

namespace snell {
namespace {

namespace fs = std::filesystem;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

template <typename T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

// Field by field, bit for bit (NaN == NaN, -0 != +0): the first field
// that differs, or "" when none does.
std::string firstDifference(const std::vector<OracleVarying>& a,
                            const std::vector<OracleVarying>& b) {
  if (a.size() != b.size()) return "the number of outputs";
  for (std::size_t k = 0; k < a.size(); ++k) {
    const OracleVarying &x = a[k], &y = b[k];
    const std::string at = x.name + ": ";
    if (x.name != y.name || x.components != y.components || x.mergedToHull != y.mergedToHull)
      return at + "name, components or mergedToHull";
    if (!sameBits(x.reference, y.reference)) return at + "reference";
    if (!sameBits(x.strict, y.strict)) return at + "strict";
    if (!sameBits(x.lo, y.lo)) return at + "lo";
    if (!sameBits(x.hi, y.hi)) return at + "hi";
    if (!sameBits(x.undefined, y.undefined)) return at + "undefined";
    if (x.alternatives.size() != y.alternatives.size()) return at + "alternatives";
    for (std::size_t s = 0; s < x.alternatives.size(); ++s) {
      const SampleAlternatives &p = x.alternatives[s], &q = y.alternatives[s];
      if (p.sample != q.sample || p.ways.size() != q.ways.size()) return at + "alternative sample";
      for (std::size_t w = 0; w < p.ways.size(); ++w)
        if (!sameBits(p.ways[w].reference, q.ways[w].reference) ||
            !sameBits(p.ways[w].lo, q.ways[w].lo) || !sameBits(p.ways[w].hi, q.ways[w].hi) ||
            !sameBits(p.ways[w].undefined, q.ways[w].undefined))
          return at + "alternative way";
    }
  }
  return "";
}

void expectIdentical(const std::vector<OracleVarying>& a, const std::vector<OracleVarying>& b) {
  EXPECT_EQ(firstDifference(a, b), "");
}

// The awkward values: signed zeros, infinities, NaN, a denormal, bounds
// that are floats (stored narrow) and one that is not (stored wide), and
// branch alternatives.
std::vector<OracleVarying> awkwardResult() {
  OracleVarying a;
  a.name = "R";
  a.components = 3;
  a.reference = {0.1, -0.0, kNaN, 1e-310, kInf, -kInf};
  a.strict = {0.1f, -0.0f, std::numeric_limits<float>::quiet_NaN(), 1e-40f, 1.0f, -1.0f};
  a.lo = {-kInf, -0.0, 0.0, 0x1p-149, 1.0, -0.5};
  a.hi = {kInf, 0.0, 0.1, 0x1p-149, 1.0000001, -0.25};  // 0.1 and 1.0000001 are not floats
  a.undefined = {1, 0, 0, 0, 0, 0};
  a.alternatives = {{4,
                     {{{1.0, 2.0, 3.0}, {0.5, 1.5, 2.5}, {1.5, 2.5, 3.5}, {0, 0, 1}},
                      {{-1.0, -2.0, -3.0}, {-1.5, -2.5, -kInf}, {-0.5, -1.5, kInf}, {0, 0, 0}}}}};
  a.mergedToHull = 7;
  OracleVarying b;
  b.name = "fresnel";
  b.components = 1;
  b.reference = {0.25, 0.5};
  b.strict = {0.25f, 0.5f};
  b.lo = {0.25, 0.5};
  b.hi = {0.25, 0.5};
  b.undefined = {0, 0};
  return {a, b};
}

Digest keyOf(const char* text) { return digestOf(text); }

TEST(StoredResultFormat, ReadsBackBitForBit) {
  const std::vector<OracleVarying> result = awkwardResult();
  const auto back = decodeStoredResult(keyOf("k"), encodeStoredResult(keyOf("k"), result));
  ASSERT_TRUE(back);
  expectIdentical(*back, result);
}

TEST(StoredResultFormat, TheComparisonSeesAOneBitChange) {
  std::vector<OracleVarying> changed = awkwardResult();
  changed[0].hi[1] = -0.0;  // +0 to -0: equal as numbers, not as bits
  EXPECT_EQ(firstDifference(changed, awkwardResult()), "R: hi");
  changed = awkwardResult();
  changed[0].alternatives[0].ways[1].lo[2] = -0x1p127;
  EXPECT_EQ(firstDifference(changed, awkwardResult()), "R: alternative way");
}

TEST(StoredResultFormat, ADamagedShortOrForeignFileReadsAsNothing) {
  const std::string bytes = encodeStoredResult(keyOf("k"), awkwardResult());
  EXPECT_FALSE(decodeStoredResult(keyOf("other"), bytes)) << "another key";
  for (std::size_t cut : {std::size_t{0}, std::size_t{10}, bytes.size() / 2, bytes.size() - 1})
    EXPECT_FALSE(decodeStoredResult(keyOf("k"), std::string_view(bytes).substr(0, cut)))
        << "cut to " << cut;
  EXPECT_FALSE(decodeStoredResult(keyOf("k"), bytes + "x")) << "a byte too many";
  for (std::size_t at : {std::size_t{0}, std::size_t{9}, bytes.size() - 3}) {
    std::string flipped = bytes;
    flipped[at] = static_cast<char>(flipped[at] ^ 0x10);
    EXPECT_FALSE(decodeStoredResult(keyOf("k"), flipped)) << "byte " << at << " changed";
  }
}

TEST(StoredResultFormat, AReferenceImageReadsBackAndAVectorFileIsNotOne) {
  ReferenceImage reference;
  reference.color = Image(3, 2);
  for (std::size_t k = 0; k < reference.color.pixels.size(); ++k)
    reference.color.pixels[k] = static_cast<float>(k) * 0.1f - 1.0f;
  reference.color.pixels[5] = -0.0f;
  reference.mask = {PixelMask::None,      PixelMask::Silhouette, PixelMask::FaceEdge,
                    PixelMask::Undefined, PixelMask::None,       PixelMask::None};
  const std::string bytes = encodeStoredReference(keyOf("k"), reference);
  const auto back = decodeStoredReference(keyOf("k"), bytes);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->color.width, 3);
  EXPECT_EQ(back->color.height, 2);
  EXPECT_TRUE(sameBits(back->color.pixels, reference.color.pixels));
  EXPECT_EQ(back->mask, reference.mask);
  EXPECT_FALSE(decodeStoredReference(keyOf("k"), bytes.substr(0, bytes.size() - 1)));
  EXPECT_FALSE(decodeStoredResult(keyOf("k"), bytes)) << "an image is not a vector result";
  EXPECT_FALSE(decodeStoredReference(keyOf("k"), encodeStoredResult(keyOf("k"), awkwardResult())))
      << "nor a vector result an image";
  reference.mask.pop_back();  // a mask that does not cover the image
  EXPECT_FALSE(decodeStoredReference(keyOf("k"), encodeStoredReference(keyOf("k"), reference)));
}

// One input, and every way to change it by a bit.
struct KeyInput {
  UniformMap uniforms{{"eta", {ValueType::Float, {0.66f}}}};
  ConstantMap constants{{"FresnelPower", 5.0}};
  AttributeMap attributes{{"rm_Normal", {"rm_Normal", 3, {0.0f, 0.0f, 1.0f, 0.0f, 1.0f, 0.0f}}}};
  std::size_t count = 2;
  PrecisionRules rules = PrecisionRules::Glsl;
  Digest key(const std::string& identity = "listing x") const {
    return oracleResultKey(identity, {uniforms, constants, attributes, count, rules});
  }
};

TEST(OracleResultKey, EveryPartOfTheInputChangesIt) {
  const Digest base = KeyInput{}.key();
  EXPECT_EQ(KeyInput{}.key(), base) << "the same input, the same key";
  EXPECT_NE(KeyInput{}.key("listing y"), base);
  KeyInput in;
  in.uniforms["eta"].data[0] = std::nextafter(0.66f, 1.0f);
  EXPECT_NE(in.key(), base) << "a uniform one ULP away";
  in = {};
  in.uniforms["eta"].type = ValueType::Vec2;
  EXPECT_NE(in.key(), base) << "a uniform's type";
  in = {};
  in.constants["FresnelPower"] = 5.000000000000001;
  EXPECT_NE(in.key(), base) << "a constant";
  in = {};
  in.attributes["rm_Normal"].data[5] = -0.0f;
  EXPECT_NE(in.key(), base) << "an attribute's zero's sign";
  in = {};
  in.attributes["rm_Normal"].components = 2;
  EXPECT_NE(in.key(), base) << "the attribute's packing";
  in = {};
  in.count = 1;
  EXPECT_NE(in.key(), base) << "the vertex count";
  in = {};
  in.rules = PrecisionRules::Vulkan;
  EXPECT_NE(in.key(), base) << "the precision rules";
  in = {};
  in.uniforms["eta2"] = {ValueType::Float, {0.66f}};
  EXPECT_NE(in.key(), base) << "one uniform more";
}

TEST(ContentHash, FieldsAreKeptApart) {
  ContentHash ab, a;
  ab.add(std::string_view("ab"));
  ab.add(std::string_view("c"));
  a.add(std::string_view("a"));
  a.add(std::string_view("bc"));
  EXPECT_NE(ab.finish(), a.finish());
  EXPECT_EQ(digestOf("abc").hex().size(), 32u);
}

TEST(BuildId, TheTestExecutableHasOneAndNullHasNone) {
  const std::string id = buildIdContaining(reinterpret_cast<const void*>(&buildIdContaining));
  EXPECT_GE(id.size(), 16u) << "linked without --build-id: nothing would be stored";
  EXPECT_EQ(id.find_first_not_of("0123456789abcdef"), std::string::npos) << id;
  EXPECT_EQ(buildIdContaining(nullptr), "");
}

class StoreFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / fmt::format("snell-oracle-store-{}", getpid());
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::vector<fs::path> files() const {
    std::vector<fs::path> all;
    for (const auto& e : fs::recursive_directory_iterator(dir_))
      if (e.is_regular_file()) all.push_back(e.path());
    return all;
  }
  fs::path dir_;
};

TEST_F(StoreFolder, SavesLoadsAndTakesADamagedFileForAMiss) {
  const OracleStore store(dir_);
  EXPECT_FALSE(store.load(keyOf("k"))) << "nothing stored yet";
  ASSERT_TRUE(store.save(keyOf("k"), awkwardResult()));
  const auto back = store.load(keyOf("k"));
  ASSERT_TRUE(back);
  expectIdentical(*back, awkwardResult());
  ASSERT_EQ(files().size(), 1u);
  fs::resize_file(files()[0], fs::file_size(files()[0]) - 1);
  EXPECT_FALSE(store.load(keyOf("k"))) << "cut short";
  ASSERT_TRUE(store.save(keyOf("k"), awkwardResult())) << "written again over the damaged one";
  EXPECT_TRUE(store.load(keyOf("k")));
}

TEST_F(StoreFolder, AFolderThatCannotBeMadeStoresNothing) {
  fs::create_directories(dir_);
  std::ofstream(dir_ / "file") << "not a folder";
  const OracleStore store(dir_ / "file" / "store");
  EXPECT_FALSE(store.save(keyOf("k"), awkwardResult()));
  EXPECT_FALSE(store.load(keyOf("k")));
}

TEST_F(StoreFolder, TheTrimDropsTheLeastRecentlyUsedFirst) {
  const OracleStore store(dir_);
  for (const char* k : {"a", "b", "c"}) ASSERT_TRUE(store.save(keyOf(k), awkwardResult()));
  const std::uintmax_t each = fs::file_size(files()[0]);
  // Written a, b, c; then a is used: b is the least recently used.
  const auto past = fs::file_time_type::clock::now() - std::chrono::hours(1);
  for (const fs::path& f : files()) fs::last_write_time(f, past);
  for (const char* k : {"c", "a"}) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    ASSERT_TRUE(store.load(keyOf(k)));
  }
  const StoreTrim trim = trimKeyedFileStore(dir_, 2 * each);
  EXPECT_EQ(trim.removed, 1u);
  EXPECT_EQ(trim.kept, 2 * each);
  EXPECT_FALSE(store.load(keyOf("b")));
  EXPECT_TRUE(store.load(keyOf("a")));
  EXPECT_TRUE(store.load(keyOf("c")));
  EXPECT_EQ(trimKeyedFileStore(dir_, 0).kept, 0u);
  EXPECT_TRUE(files().empty());
}

// The store may be a folder that holds other files (a CI cache folder, a
// project): the trim removes only its own entries and its own leftover
// temporaries, however old or large the others are.
TEST_F(StoreFolder, TheTrimTouchesNoFileThatIsNotTheStores) {
  const OracleStore store(dir_);
  ASSERT_TRUE(store.save(keyOf("a"), awkwardResult()));
  const fs::path entry = files()[0];
  const fs::path leftover = fs::path(entry.string() + ".tmp4242");
  fs::copy_file(entry, leftover);
  const std::vector<fs::path> foreign = {dir_ / "templates" / "page.html.tmpl",
                                         dir_ / "backup.tmp",
                                         dir_ / "notes.result",
                                         dir_ / "project" / "data.result",
                                         entry.parent_path() / "readme.txt",
                                         entry.parent_path() / (entry.filename().string() + "l"),
                                         entry.parent_path() / "0123.result.tmpx"};
  for (const fs::path& f : foreign) {
    fs::create_directories(f.parent_path());
    std::ofstream(f) << std::string(4096, 'x');
  }
  const auto old = fs::file_time_type::clock::now() - std::chrono::hours(72);
  for (const auto& e : fs::recursive_directory_iterator(dir_))
    if (e.is_regular_file()) fs::last_write_time(e.path(), old);
  const StoreTrim trim = trimKeyedFileStore(dir_, 0);
  EXPECT_EQ(trim.removed, 2u) << "the entry and the day-old temporary";
  EXPECT_FALSE(fs::exists(entry));
  EXPECT_FALSE(fs::exists(leftover));
  for (const fs::path& f : foreign) EXPECT_TRUE(fs::exists(f)) << f;
}

// Counts its evaluations; its identity is set by the test.
class CountingOracle : public VertexOracle {
 public:
  explicit CountingOracle(int* calls) : calls_(calls) {}
  std::vector<std::string> outputs() const override { return {"R", "fresnel"}; }
  std::vector<OracleVarying> evaluate(const OracleInput&) const override {
    ++*calls_;
    return awkwardResult();
  }

 private:
  int* calls_;
};

TEST_F(StoreFolder, OracleCacheComputesOnlyWhatTheStoreLacks) {
  int calls = 0;
  const NamedOracle named{"counting", std::make_unique<CountingOracle>(&calls), "counting v1"};
  const KeyInput in;
  const OracleInput input{in.uniforms, in.constants, in.attributes, in.count, in.rules};
  OracleCache firstRun{OracleStore(dir_)};
  expectIdentical(firstRun.evaluate(named, input), awkwardResult());
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(firstRun.stored(), 0);
  OracleCache laterRun{OracleStore(dir_)};
  expectIdentical(laterRun.evaluate(named, input), awkwardResult());
  EXPECT_EQ(calls, 1) << "read from the store, not computed";
  EXPECT_EQ(laterRun.evaluated(), 1);
  EXPECT_EQ(laterRun.stored(), 1);

  const NamedOracle unknownBuild{"counting", std::make_unique<CountingOracle>(&calls), ""};
  laterRun.evaluate(unknownBuild, input);
  laterRun.evaluate(unknownBuild, input);
  EXPECT_EQ(calls, 3) << "an oracle without an identity is never stored";
  OracleCache noStore;
  noStore.evaluate(named, input);
  EXPECT_EQ(calls, 4);
  EXPECT_EQ(noStore.stored(), 0);
}

// A listing's own oracles (hand-written and derived), on its scene: what
// the store gives back is what they compute, and both have identities.
TEST_F(StoreFolder, AListingsOraclesReadBackAsComputed) {
  const std::vector<Manifest> manifests =
      loadManifests(SNELL_SOURCE_ROOT "/shaders/orange-book/14.1-fresnel");
  Case sphere;
  for (Case& c : expandCases(manifests, "*/sphere")) sphere = c;
  ASSERT_EQ(sphere.id, "orange-book/14.1-fresnel/sphere");
  SceneCache scenes;
  const ResolvedBindings bindings =
      resolveBindings(*sphere.manifest, scenes.get(sphere.spec.scene));
  const std::vector<NamedOracle> oracles = vectorOracles(*sphere.manifest, CaptureStage::Vertex);
  ASSERT_FALSE(oracles.empty());
  for (PrecisionRules rules : {PrecisionRules::Glsl, PrecisionRules::Vulkan})
    for (const NamedOracle& named : oracles) {
      SCOPED_TRACE(named.label);
      EXPECT_FALSE(named.identity.empty());
      const OracleInput input{bindings.uniforms, sphere.manifest->constants, bindings.attributes,
                              bindings.vertexCount, rules};
      const std::vector<OracleVarying> computed = named.oracle->evaluate(input);
      OracleCache writer{OracleStore(dir_)}, reader{OracleStore(dir_)};
      writer.evaluate(named, input);
      const std::vector<OracleVarying> read = reader.evaluate(named, input);
      EXPECT_EQ(reader.stored(), 1);
      expectIdentical(read, computed);
    }
}

// The digest a stored file is named by (dir/ab/cdef....result).
Digest digestOfFile(const fs::path& file) {
  const std::string hex = file.parent_path().filename().string() + file.stem().string();
  Digest d;
  for (std::size_t k = 0; k < d.bytes.size(); ++k)
    d.bytes[k] = static_cast<std::uint8_t>(std::stoi(hex.substr(2 * k, 2), nullptr, 16));
  return d;
}

Image gradient(float scale) {
  Image image(4, 3);
  for (std::size_t k = 0; k < image.pixels.size(); ++k)
    image.pixels[k] = static_cast<float>(k) * scale;
  return image;
}

TEST_F(StoreFolder, ADecodedImageIsKeptByTheFilesBytes) {
  fs::create_directories(dir_);
  const fs::path exr = dir_ / "image.exr";
  writeImageAtomically(exr, gradient(0.01f));
  const OracleStore store(dir_ / "store");
  EXPECT_EQ(readImageKept(&store, exr).pixels, gradient(0.01f).pixels);
  ASSERT_EQ(files().size(), 2u) << "the image and one stored result";
  EXPECT_EQ(readImageKept(&store, exr).pixels, gradient(0.01f).pixels);
  EXPECT_EQ(files().size(), 2u) << "read from the store";
  // What the store holds is what is given: a result put there by hand
  // under the file's key comes back, so the store is really consulted.
  fs::path stored;
  for (const fs::path& f : files())
    if (f.extension() == ".result") stored = f;
  std::ofstream(stored, std::ios::binary | std::ios::trunc)
      << encodeStoredImage(digestOfFile(stored), gradient(0.5f));
  EXPECT_EQ(readImageKept(&store, exr).pixels, gradient(0.5f).pixels);
  writeImageAtomically(exr, gradient(0.02f));  // other bytes: another key
  EXPECT_EQ(readImageKept(&store, exr).pixels, gradient(0.02f).pixels);
  EXPECT_EQ(readImageKept(nullptr, exr).pixels, gradient(0.02f).pixels);
  EXPECT_THROW(readImageKept(&store, dir_ / "missing.exr"), UsageError);
}

TEST_F(StoreFolder, AComparisonIsKeptByItsImagesAndThresholds) {
  const OracleStore store(dir_);
  Image observed = gradient(0.01f);
  observed.pixels[5] += 0.1f;
  const ImageTolerance rules{0.004, 0.002, 0.0, 0.05};
  const ImageComparison direct = compareImages("golden", observed, gradient(0.01f), {}, rules);
  ASSERT_EQ(direct.verdict, ImageVerdict::Fail);
  const auto same = [&](const ImageComparison& c) {
    EXPECT_EQ(c.against, direct.against);
    EXPECT_EQ(c.verdict, direct.verdict);
    EXPECT_EQ(c.maxError, direct.maxError);
    EXPECT_EQ(c.meanError, direct.meanError);
    EXPECT_EQ(c.maxX, direct.maxX);
    EXPECT_EQ(c.maxY, direct.maxY);
    EXPECT_EQ(c.failed, direct.failed);
    EXPECT_EQ(c.compared, direct.compared);
    EXPECT_EQ(c.masked, direct.masked);
  };
  same(compareImagesKept(&store, "golden", observed, gradient(0.01f), {}, rules));
  ASSERT_EQ(files().size(), 1u);
  same(compareImagesKept(&store, "golden", observed, gradient(0.01f), {}, rules));
  EXPECT_EQ(files().size(), 1u) << "read from the store";
  const ImageTolerance looser{0.5, 0.4, 0.0, 1.0};
  EXPECT_EQ(compareImagesKept(&store, "golden", observed, gradient(0.01f), {}, looser).verdict,
            ImageVerdict::Pass)
      << "other thresholds: another key";
  std::vector<PixelMask> mask(12, PixelMask::None);
  mask[1] = PixelMask::Silhouette;  // pixel 1 holds channel 5
  EXPECT_EQ(compareImagesKept(&store, "golden", observed, gradient(0.01f), mask, rules).verdict,
            ImageVerdict::Pass)
      << "another mask: another key";
  EXPECT_EQ(files().size(), 3u);
}

}  // namespace
}  // namespace snell
