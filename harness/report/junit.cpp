#include "report/junit.h"

#include <fmt/format.h>

#include <map>
#include <pugixml.hpp>
#include <sstream>
#include <string_view>

#include "core/utf8.h"
#include "runner/checks/check_kind.h"

namespace snell {

namespace {

// The status, then what each check kind found wrong: what a CI page shows
// without opening the failure's text.
std::string failureMessage(const CaseResult& r) {
  std::string message = statusName(r.status);
  for (const auto& kind : checkKinds())
    if (const std::string found = kind->junitMessage(r); !found.empty()) message += ": " + found;
  return message;
}

}  // namespace

JUnitNotes junitNotesOf(const BaselineReport& report) {
  JUnitNotes notes;
  for (const JudgedCase& c : report.cases) {
    const std::string key = c.result->backend + " " + c.result->caseId;
    if (c.outcome == Outcome::ExpectedFail)
      notes.expectedFailures[key] =
          fmt::format("expected failure, {}", c.knownFailure->place.where());
    else if (c.outcome == Outcome::KnownFlake)
      notes.flakes[key] = fmt::format("known flake, {}", c.flakePattern->place.where());
    else if (c.outcome == Outcome::Flake)
      notes.flakes[key] = "failed, then passed on a rerun";
  }
  return notes;
}

namespace {

// XML 1.0 has no way to write most control characters, not even as
// character references (&#1; makes the file unreadable to every parser),
// nor U+FFFE, U+FFFF or a byte that is not UTF-8: a driver's or worker's
// message that holds one (an ESC of a coloured log, a truncated multibyte
// character) gets it spelled out as \xNN instead.
std::string xmlSafe(std::string_view text) {
  return utf8SpellingOut(text, [](char32_t c) {
    if (c < 0x20) return c == '\t' || c == '\n' || c == '\r';
    return c != 0x7F && c != 0xFFFE && c != 0xFFFF;
  });
}

}  // namespace

std::string toJUnitXml(const std::vector<CaseResult>& results, const JUnitNotes& notes) {
  pugi::xml_document doc;
  pugi::xml_node suites = doc.append_child("testsuites");
  suites.append_attribute("name") =
      notes.incomplete.empty()
          ? "snell"
          : xmlSafe(fmt::format("snell (incomplete: {})", notes.incomplete)).c_str();
  std::map<std::string, pugi::xml_node> byBackend;
  for (const CaseResult& r : results) {
    pugi::xml_node& suite = byBackend[r.backend];
    if (!suite) {
      suite = suites.append_child("testsuite");
      suite.append_attribute("name") = xmlSafe(r.backend).c_str();
    }
    pugi::xml_node test = suite.append_child("testcase");
    test.append_attribute("classname") = xmlSafe(fmt::format("snell.{}", r.backend)).c_str();
    test.append_attribute("name") = xmlSafe(r.caseId).c_str();
    // Fixed-point seconds: JUnit's schema types `time` as xs:decimal, which
    // has no exponent (a case of 4e-06 s is written 0.000004).
    test.append_attribute("time") = fmt::format("{:.6f}", r.seconds).c_str();
    const std::string key = r.backend + " " + r.caseId;
    if (const auto expected = notes.expectedFailures.find(key);
        expected != notes.expectedFailures.end()) {
      test.append_child("skipped").append_attribute("message") =
          xmlSafe(fmt::format("{}: {}", statusName(r.status), expected->second)).c_str();
    } else if (const auto flake = notes.flakes.find(key); flake != notes.flakes.end()) {
      // Surefire's element for a test that failed, then passed on a rerun.
      pugi::xml_node flaky = test.append_child("flakyFailure");
      flaky.append_attribute("type") = statusName(r.status);
      flaky.append_attribute("message") = xmlSafe(flake->second).c_str();
      flaky.append_child(pugi::node_pcdata).set_value(xmlSafe(r.message).c_str());
    } else if (isFailure(r.status)) {
      pugi::xml_node failure = test.append_child(r.status == Status::Fail ? "failure" : "error");
      failure.append_attribute("type") = statusName(r.status);
      failure.append_attribute("message") = xmlSafe(failureMessage(r)).c_str();
      failure.append_child(pugi::node_pcdata).set_value(xmlSafe(r.message).c_str());
    } else if (r.status == Status::NotSupported) {
      test.append_child("skipped").append_attribute("message") = xmlSafe(r.message).c_str();
    }
    test.append_child("system-out")
        .append_child(pugi::node_pcdata)
        .set_value(
            xmlSafe(
                fmt::format(
                    "status {}; {} components checked, {} undefined, worst slack {:.3g}; {} on {}",
                    statusName(r.status), r.componentsChecked(), r.componentsUndefined(),
                    r.worstSlack(), r.driver.apiVersion, r.driver.renderer) +
                // A listing kept as published that must not compile: its diagnostic
                // is the result.
                (r.status == Status::ExpectedCompileError ? "\n" + r.message : std::string()))
                .c_str());
  }
  for (auto& [backend, suite] : byBackend) {
    int tests = 0, failures = 0, errors = 0, skipped = 0;
    for (pugi::xml_node test : suite.children("testcase")) {
      ++tests;
      failures += test.child("failure") ? 1 : 0;
      errors += test.child("error") ? 1 : 0;
      skipped += test.child("skipped") ? 1 : 0;
    }
    suite.append_attribute("tests") = tests;
    suite.append_attribute("failures") = failures;
    suite.append_attribute("errors") = errors;
    suite.append_attribute("skipped") = skipped;
    if (!notes.incomplete.empty()) {
      pugi::xml_node property = suite.prepend_child("properties").append_child("property");
      property.append_attribute("name") = "incomplete";
      property.append_attribute("value") = xmlSafe(notes.incomplete).c_str();
    }
  }
  std::ostringstream out;
  doc.save(out, "  ");
  return out.str();
}

}  // namespace snell
