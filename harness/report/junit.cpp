#include "report/junit.h"

#include <fmt/format.h>

#include <map>
#include <pugixml.hpp>
#include <sstream>

namespace snell {

std::string toJUnitXml(const std::vector<CaseResult>& results) {
  pugi::xml_document doc;
  pugi::xml_node suites = doc.append_child("testsuites");
  suites.append_attribute("name") = "snell";
  std::map<std::string, pugi::xml_node> byBackend;
  for (const CaseResult& r : results) {
    pugi::xml_node& suite = byBackend[r.backend];
    if (!suite) {
      suite = suites.append_child("testsuite");
      suite.append_attribute("name") = r.backend.c_str();
    }
    pugi::xml_node test = suite.append_child("testcase");
    test.append_attribute("classname") = fmt::format("snell.{}", r.backend).c_str();
    test.append_attribute("name") = r.caseId.c_str();
    test.append_attribute("time") = r.seconds;
    if (isFailure(r.status)) {
      pugi::xml_node failure =
          test.append_child(r.status == Status::Fail ? "failure" : "error");
      failure.append_attribute("type") = statusName(r.status);
      failure.append_attribute("message") = statusName(r.status);
      failure.append_child(pugi::node_pcdata).set_value(r.message.c_str());
    } else if (r.status == Status::NotSupported) {
      test.append_child("skipped").append_attribute("message") = r.message.c_str();
    }
    test.append_child("system-out").append_child(pugi::node_pcdata).set_value(
        (fmt::format("status {}; {} components checked, {} undefined, worst slack {:.3g}; {} on {}",
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
  }
  std::ostringstream out;
  doc.save(out, "  ");
  return out.str();
}

}  // namespace snell
