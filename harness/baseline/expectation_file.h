#pragma once
// Expectation files in the conventions of Mesa's CI (deqp-runner):
//   PREFIX-fails.txt   `case,Status` per line: a known failure, exact id
//   PREFIX-flakes.txt  one regular expression per line: cases known to flake
//   PREFIX-skips.txt   one regular expression per line: cases not to run
// Blank lines and `#` comments are ignored, except metadata comments
// directly above an entry, which belong to it:
//   # reason: refract() rounds k twice on softpipe
//   # link: https://gitlab.freedesktop.org/mesa/mesa/-/issues/1234
//   # added: 2026-11-20
//   # expires: 2027-05-01
// An entry past its expiry date is an error (exit 2, FILE:LINE): a known
// failure must be looked at again, not carried forever.
#include <filesystem>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "core/status.h"

namespace snell {

struct EntryMetadata {
  std::string reason, link, added, expires;  // dates as YYYY-MM-DD
};

// Where an entry was read, as FILE:LINE.
struct EntryPlace {
  std::string file;
  int line = 0;
  std::string text;  // the line as written, for "delete this line"
  std::string where() const;
};

struct KnownFailure {
  std::string caseId;
  Status status = Status::Fail;
  EntryPlace place;
  EntryMetadata metadata;
};

struct CasePattern {
  std::string pattern;
  std::regex regex;  // searched, not anchored, as deqp-runner does
  EntryPlace place;
  EntryMetadata metadata;
};

struct Expectations {
  std::vector<KnownFailure> fails;
  std::vector<CasePattern> flakes, skips;

  const KnownFailure* knownFailure(const std::string& caseId) const;
  const CasePattern* flake(const std::string& caseId) const;
  const CasePattern* skip(const std::string& caseId) const;
};

// Expectations for each backend of a run. An empty `source` means none.
struct ExpectationSet {
  std::string source;
  std::map<std::string, Expectations> byBackend;

  bool empty() const { return source.empty(); }
  // The backend's expectations, or an empty set.
  const Expectations& of(const std::string& backend) const;
};

// `source` is a folder, read as DIR/<backend>-fails.txt, -flakes.txt and
// -skips.txt for each backend (a missing file is an empty list), or one of
// PREFIX-fails.txt / -flakes.txt / -skips.txt: that prefix's three files,
// for every backend of the run (the form for one driver: softpipe-fails.txt).
// `today` is YYYY-MM-DD. Throws UsageError with FILE:LINE.
ExpectationSet loadExpectations(const std::filesystem::path& source,
                                const std::vector<std::string>& backends, const std::string& today);

// A note (FILE:LINE, what to do) for each entry that names or matches no
// case of the catalog: a typo, or a case id with the backend in front of it
// (`gl/orange-book/...`, as results.csv names it), which would otherwise
// only be "absent" beside the failure it was meant to cover. Once per
// entry, though a folder's entry serves one backend and a prefix's all.
std::vector<std::string> entriesMatchingNoCase(const ExpectationSet& set,
                                               const std::vector<std::string>& caseIds);

// One file's kind is given by the caller; exposed for the tests.
Expectations readExpectationFiles(const std::filesystem::path& fails,
                                  const std::filesystem::path& flakes,
                                  const std::filesystem::path& skips, const std::string& today);

// Today's date in UTC as YYYY-MM-DD.
std::string todayUtc();

}  // namespace snell
