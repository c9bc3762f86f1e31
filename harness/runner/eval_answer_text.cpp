#include "runner/eval_answer_text.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string_view>

#include "runner/builtin_draw.h"

namespace snell {
namespace {

void text(fmt::memory_buffer& out, std::string_view s) { out.append(s); }

// A finite number as nlohmann's dump() writes it (its Grisu2 conversion:
// not always the shortest digits, so fmt's would differ now and then), or
// the string eval gives for a non-finite one.
void number(fmt::memory_buffer& out, double x) {
  if (!std::isfinite(x)) {
    text(out, x > 0 ? "\"inf\"" : x < 0 ? "\"-inf\"" : "\"nan\"");
    return;
  }
  // Written in place: a copy through a local array was a call to memcpy
  // per number, nine numbers an answer.
  constexpr std::size_t kRoom = 64;
  const std::size_t at = out.size();
  out.resize(at + kRoom);
  const char* end = nlohmann::detail::to_chars(out.data() + at, out.data() + at + kRoom, x);
  out.resize(static_cast<std::size_t>(end - out.data()));
}

template <class Values>
void numbers(fmt::memory_buffer& out, const Values& values) {
  out.push_back('[');
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (k) out.push_back(',');
    number(out, static_cast<double>(values[k]));
  }
  out.push_back(']');
}

void flags(fmt::memory_buffer& out, const Components<bool>& values) {
  out.push_back('[');
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (k) out.push_back(',');
    text(out, values[k] ? "true" : "false");
  }
  out.push_back(']');
}

bool any(const Components<bool>& values) {
  return std::find(values.begin(), values.end(), true) != values.end();
}

void way(fmt::memory_buffer& out, const BuiltinWay& w) {
  text(out, "{\"hi\":");
  numbers(out, w.hi);
  text(out, ",\"lo\":");
  numbers(out, w.lo);
  if (any(w.undefined)) {
    text(out, ",\"undefined\":");
    flags(out, w.undefined);
  }
  text(out, ",\"value\":");
  numbers(out, w.value);
  out.push_back('}');
}

}  // namespace

bool appendEvalAnswer(fmt::memory_buffer& out, const EvalAnswer& answer) {
  const BuiltinResult& oracle = *answer.oracle;
  // Keys in the order nlohmann's std::map kept them: alternatives, exact,
  // fn, hi, line, lo, rules, slack, undefined, value, within_spec.
  out.push_back('{');
  if (oracle.ways.size() > 1) {
    text(out, "\"alternatives\":[");
    for (std::size_t k = 0; k < oracle.ways.size(); ++k) {
      if (k) out.push_back(',');
      way(out, oracle.ways[k]);
    }
    text(out, "],");
  }
  DriverJudgement judgement;
  if (answer.driver) {
    judgement = judgeDriverVector(oracle, *answer.driver);
    text(out, "\"exact\":");
    numbers(out, oracle.value);
    out.push_back(',');
  }
  text(out, "\"fn\":\"");
  text(out, answer.call->fn);
  text(out, "\",\"hi\":");
  numbers(out, oracle.hi);
  fmt::format_to(std::back_inserter(out), ",\"line\":{},\"lo\":", answer.line);
  numbers(out, oracle.lo);
  text(out, ",\"rules\":\"");
  text(out, precisionRulesName(answer.rules));
  out.push_back('"');
  if (answer.driver) {
    text(out, ",\"slack\":");
    if (std::isfinite(judgement.worstSlack))
      number(out, judgement.worstSlack);
    else
      text(out, "\"inf\"");
  }
  if (any(oracle.undefined)) {
    text(out, ",\"undefined\":");
    flags(out, oracle.undefined);
  }
  text(out, ",\"value\":");
  if (answer.driver)
    numbers(out, *answer.driver);
  else
    numbers(out, oracle.value);
  if (answer.driver)
    text(out, judgement.outside ? ",\"within_spec\":false" : ",\"within_spec\":true");
  text(out, "}\n");
  return judgement.outside;
}

}  // namespace snell
