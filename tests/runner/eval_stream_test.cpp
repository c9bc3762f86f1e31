// `snell eval` a chunk at a time on several threads: the answers, their
// order and the summary are those of one chunk on one thread, on the oracle
// and on each driver; a bad line in a later chunk is named by its number.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "backends/backend_registry.h"
#include "eval_input.h"
#include "runner/builtin_eval.h"

namespace snell {
namespace {

struct EvalRun {
  std::string out;
  EvalSummary summary;
};

EvalRun evaluate(const std::string& input, std::size_t chunkLines, unsigned threads,
                 Backend* backend = nullptr, PrecisionRules rules = PrecisionRules::Glsl) {
  std::istringstream in(input);
  std::ostringstream out;
  EvalOptions options;
  options.chunkLines = chunkLines;
  options.threads = threads;
  EvalRun run;
  run.summary = evaluateLines(in, out, backend, rules, options);
  run.out = out.str();
  return run;
}

std::vector<nlohmann::json> answers(const std::string& text) {
  std::vector<nlohmann::json> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
  return lines;
}

void expectSameRun(const EvalRun& run, const EvalRun& reference) {
  EXPECT_EQ(run.out, reference.out);
  EXPECT_EQ(run.summary.answered, reference.summary.answered);
  EXPECT_EQ(run.summary.malformed, reference.summary.malformed);
  EXPECT_EQ(run.summary.outsideSpec, reference.summary.outsideSpec);
  EXPECT_EQ(run.summary.firstMalformedLine, reference.summary.firstMalformedLine);
  EXPECT_EQ(run.summary.firstMalformedReason, reference.summary.firstMalformedReason);
}

TEST(EvalStream, ManyChunksGiveTheAnswersOfOneInTheSameOrder) {
  const std::string input = testing::evalInputOfEveryShape(700);
  const EvalRun whole = evaluate(input, 1 << 20, 1);
  // Every non-blank line answered once, numbered as the input numbers it.
  std::size_t expected = 1;
  std::size_t answered = 0;
  for (const nlohmann::json& answer : answers(whole.out)) {
    while (
        testing::evalLineOfEveryShape(static_cast<int>(expected - 1)).find_first_not_of(" \t\r") ==
        std::string::npos)
      ++expected;
    ASSERT_EQ(answer.at("line").get<std::size_t>(), expected) << answer.dump();
    ++expected;
    ++answered;
  }
  EXPECT_EQ(answered, whole.summary.answered + whole.summary.malformed);
  EXPECT_GT(whole.summary.malformed, 0u);
  for (std::size_t chunk : {1, 7, 64, 699, 700}) {
    SCOPED_TRACE(chunk);
    expectSameRun(evaluate(input, chunk, 1), whole);
  }
}

TEST(EvalStream, ThreadedOracleGivesTheSerialAnswers) {
  const std::string input = testing::evalInputOfEveryShape(3000);
  for (PrecisionRules rules : {PrecisionRules::Glsl, PrecisionRules::Vulkan}) {
    const EvalRun serial = evaluate(input, 1 << 20, 1, nullptr, rules);
    for (unsigned threads : {2u, 3u, 8u}) {
      SCOPED_TRACE(threads);
      expectSameRun(evaluate(input, 1000, threads, nullptr, rules), serial);
    }
  }
}

TEST(EvalStream, ABadLineInALaterChunkIsNamedByItsNumber) {
  std::string input;
  for (int k = 1; k <= 14; ++k)
    input += k == 11 ? "{\"fn\":\"refract\",\"I\":[0,-1,0],\n"
                     : "{\"fn\":\"reflect\",\"I\":[0.6,-0.8],\"N\":[0,1]}\n";
  for (unsigned threads : {1u, 2u}) {
    const EvalRun run = evaluate(input, 4, threads);  // line 11 is in the third chunk
    EXPECT_EQ(run.summary.malformed, 1u);
    EXPECT_EQ(run.summary.answered, 13u);
    EXPECT_EQ(run.summary.firstMalformedLine, 11u);
    EXPECT_NE(run.summary.firstMalformedReason.find("not valid JSON"), std::string::npos)
        << run.summary.firstMalformedReason;
    const auto lines = answers(run.out);
    ASSERT_EQ(lines.size(), 14u);
    EXPECT_EQ(lines[10].at("error").get<std::string>().rfind("line 11: not valid JSON", 0), 0u)
        << lines[10].dump();
    EXPECT_TRUE(lines[11].contains("value"));
  }
}

// A driver draws each chunk; its values land on the lines they belong to.
class EvalStreamOnDriver : public ::testing::TestWithParam<std::string> {};

TEST_P(EvalStreamOnDriver, ManyChunksOnTwoThreadsGiveTheAnswersOfOne) {
  std::string input;
  for (int k = 0; k < 400; ++k)
    if (k % 13 != 7) input += testing::evalLineOfEveryShape(k) + "\n";  // no physics lines
  const auto backend = makeBackend(GetParam(), BackendOptions{.validation = true});
  const PrecisionRules rules = precisionRulesForApi(backend->driverInfo().api);
  const EvalRun whole = evaluate(input, 1 << 20, 1, backend.get(), rules);
  std::size_t onDriver = 0;
  for (const nlohmann::json& answer : answers(whole.out))
    onDriver += answer.contains("within_spec");
  EXPECT_GT(onDriver, 250u) << whole.out.substr(0, 2000);
  expectSameRun(evaluate(input, 37, 2, backend.get(), rules), whole);
}

INSTANTIATE_TEST_SUITE_P(Backends, EvalStreamOnDriver, ::testing::Values("gl", "vk"));

}  // namespace
}  // namespace snell
