#include "runner/builtin_eval.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/errors.h"
#include "oracle/builtin_probe.h"
#include "runner/block_pool.h"
#include "runner/builtin_draw.h"
#include "runner/eval_answer_text.h"
#include "runner/eval_line.h"
#include "runner/eval_line_fast.h"
#include "runner/json_fields.h"
#include "runner/line_chunks.h"
#include "runner/physics_eval_line.h"

namespace snell {
namespace {

using nlohmann::json;

// Lines a thread takes at a time: small enough that two threads finish a
// chunk together, large enough that taking one costs nothing.
constexpr std::size_t kBlockLines = 256;

struct Line {
  std::size_t number = 0;
  bool blank = false;
  std::optional<BuiltinCall> call;  // empty when blank, malformed or a physics line
  std::optional<json> physics;      // a physics line's answer
  std::string error;                // why it is malformed
  std::optional<BuiltinResult> oracle;
  std::vector<float> driver;
};

// What one block of lines added to the summary; summed in block order, so
// the first malformed line is the same whichever thread ran which block.
struct BlockOutput {
  fmt::memory_buffer text;
  EvalSummary summary;
};

// The same text with each byte that is not UTF-8 as U+FFFD, as the answer
// (jsonText) writes it: the message on stderr then says what the answer says.
std::string validUtf8(const std::string& text) {
  return json::parse(jsonText(text)).get<std::string>();
}

// Whether a parse error stopped at a bare NaN or Infinity (JavaScript's
// spellings, which JSON does not have), for a hint at the strings it takes.
bool stoppedAtNonFiniteWord(std::string_view text, const json::exception& error) {
  const auto* parse = dynamic_cast<const json::parse_error*>(&error);
  if (!parse || parse->byte == 0 || parse->byte > text.size()) return false;
  const auto isWordByte = [](char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '-' || c == '+';
  };
  std::size_t begin = parse->byte - 1, end = parse->byte - 1;
  while (begin > 0 && isWordByte(text[begin - 1])) --begin;
  while (end < text.size() && isWordByte(text[end])) ++end;
  std::string word(text.substr(begin, end - begin));
  if (!word.empty() && (word[0] == '-' || word[0] == '+')) word.erase(0, 1);
  for (char& c : word) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return word == "nan" || word == "inf" || word == "infinity";
}

void parseLine(Line& line, std::string_view text, bool onDriver) {
  if (text.find_first_not_of(" \t\r") == std::string_view::npos) {
    line.blank = true;
    return;
  }
  if (std::optional<BuiltinCall> call = parseCommonEvalLine(text)) {
    line.call = std::move(call);
    return;
  }
  try {
    const json object = parseEvalJson(text);
    if (!isPhysicsCall(object)) {
      line.call = parseEvalObject(object);
    } else if (onDriver) {
      throw UsageError(fmt::format(
          "{} is answered by the physics reference, not by a driver: run it with --backend "
          "oracle",
          object.at("fn").get<std::string>()));
    } else {
      line.physics = evaluatePhysicsCall(object);
    }
  } catch (const json::exception& error) {
    // The input's line is the one named already; within it, the column.
    std::string why = readableError(error);
    if (const std::size_t at = why.find("at line 1, column "); at != std::string::npos)
      why.replace(at, 18, "at column ");
    line.error = fmt::format("not valid JSON ({}){}", why,
                             stoppedAtNonFiniteWord(text, error)
                                 ? "; JSON has no NaN or infinity: write the strings \"nan\", "
                                   "\"inf\" or \"-inf\""
                                 : "");
  } catch (const UsageError& error) {
    line.error = error.what();
  }
}

// Writes the line's answer (none for a blank line) and counts it.
void answerLine(const Line& line, const BuiltinResult* oracle, bool onDriver, PrecisionRules rules,
                BlockOutput& block) {
  if (line.blank) return;
  EvalSummary& summary = block.summary;
  if (line.physics) {
    ++summary.answered;
    json out = {{"line", line.number}};
    out.update(*line.physics);
    block.text.append(jsonText(out));
    block.text.push_back('\n');
    return;
  }
  if (!line.call) {
    if (!summary.malformed++) {
      summary.firstMalformedLine = line.number;
      summary.firstMalformedReason = validUtf8(line.error);
    }
    const json out = {{"line", line.number},
                      {"error", fmt::format("line {}: {}", line.number, line.error)}};
    block.text.append(jsonText(out));
    block.text.push_back('\n');
    return;
  }
  ++summary.answered;
  const EvalAnswer answer{line.number, &*line.call, oracle, onDriver ? &line.driver : nullptr,
                          rules};
  if (appendEvalAnswer(block.text, answer)) ++summary.outsideSpec;
}

// The lines with a call, drawn on the driver (runner/builtin_draw.h).
void runOnDriver(std::vector<Line>& lines, Backend& backend) {
  std::vector<DrawnCall> calls;
  calls.reserve(lines.size());
  for (Line& line : lines)
    if (line.call) calls.push_back({&*line.call, &line.driver});
  drawBuiltinCalls(calls, backend);
}

void addBlock(EvalSummary& total, const EvalSummary& block) {
  if (block.malformed && !total.malformed) {
    total.firstMalformedLine = block.firstMalformedLine;
    total.firstMalformedReason = block.firstMalformedReason;
  }
  total.answered += block.answered;
  total.malformed += block.malformed;
  total.outsideSpec += block.outsideSpec;
}

}  // namespace

PrecisionRules precisionRulesForApi(const std::string& api) {
  return api == "Vulkan" ? PrecisionRules::Vulkan : PrecisionRules::Glsl;
}

EvalSummary evaluateLines(std::istream& in, std::ostream& out, Backend* backend,
                          PrecisionRules rules, const EvalOptions& options) {
  EvalSummary summary;
  BlockPool pool(std::max(1u, options.threads));
  LineChunks chunks(in);
  std::vector<Line> lines;
  std::vector<BlockOutput> blocks;
  const bool onDriver = backend != nullptr;
  std::size_t done = 0;
  const auto stopRequested = [&] { return options.stop && *options.stop != 0; };
  for (;;) {
    const std::vector<std::string_view>& read =
        chunks.next(std::max<std::size_t>(1, options.chunkLines));
    // Once a stop is requested the input ends (options.stop): the lines
    // already read are answered, but not a last one that the interrupted
    // read may have cut short.
    const bool stopping = stopRequested();
    const std::span<const std::string_view> text(
        read.data(), read.size() - (stopping && chunks.lastLineUnterminated() ? 1 : 0));
    if (text.empty()) break;
    const std::size_t first = chunks.firstLineNumber();
    const auto parse = [&](Line& line, std::size_t k, bool driver) {
      if (chunks.tooLong(k))
        line.error =
            fmt::format("longer than {} MiB, which no call needs; it was skipped to its end",
                        LineChunks::kMaxLineBytes >> 20);
      else
        parseLine(line, text[k], driver);
    };
    const std::size_t blockCount = (text.size() + kBlockLines - 1) / kBlockLines;
    blocks.resize(blockCount);
    for (BlockOutput& block : blocks) {
      block.text.clear();
      block.summary = {};
    }
    const auto blockOf = [&](std::size_t begin) -> BlockOutput& {
      return blocks[begin / kBlockLines];
    };
    if (!onDriver) {
      // Read, evaluate and answer each line in one pass: nothing waits on
      // a draw, and no line outlives its answer (a chunk's worth of Line
      // records, built and cleared for every chunk, was a twentieth of the
      // time).
      pool.run(text.size(), kBlockLines, [&](std::size_t begin, std::size_t end) {
        BlockOutput& block = blockOf(begin);
        for (std::size_t k = begin; k < end; ++k) {
          Line line;
          line.number = first + k;
          parse(line, k, false);
          std::optional<BuiltinResult> oracle;
          if (line.call) oracle = evaluateBuiltin(*line.call, rules);
          answerLine(line, oracle ? &*oracle : nullptr, false, rules, block);
        }
      });
    } else {
      lines.clear();
      lines.resize(text.size());
      pool.run(text.size(), kBlockLines, [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) {
          lines[k].number = first + k;
          parse(lines[k], k, true);
        }
      });
      // The calling thread draws (a driver's context is bound to it) while
      // the others start on the oracle; it joins them when the draw is done.
      pool.run(
          text.size(), kBlockLines,
          [&](std::size_t begin, std::size_t end) {
            for (std::size_t k = begin; k < end; ++k)
              if (lines[k].call) lines[k].oracle = evaluateBuiltin(*lines[k].call, rules);
          },
          [&] { runOnDriver(lines, *backend); });
      pool.run(text.size(), kBlockLines, [&](std::size_t begin, std::size_t end) {
        BlockOutput& block = blockOf(begin);
        for (std::size_t k = begin; k < end; ++k)
          answerLine(lines[k], lines[k].oracle ? &*lines[k].oracle : nullptr, true, rules, block);
      });
    }
    for (const BlockOutput& block : blocks) {
      out.write(block.text.data(), static_cast<std::streamsize>(block.text.size()));
      addBlock(summary, block.summary);
    }
    out.flush();
    done += text.size();
    if (options.progress) options.progress(done);
  }
  summary.linesDone = done;
  summary.stopped = stopRequested();
  // A read ended by the stop request's signal is not a failed input.
  summary.readError = summary.stopped ? 0 : chunks.readError();
  return summary;
}

}  // namespace snell
