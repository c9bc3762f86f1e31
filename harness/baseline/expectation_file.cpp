#include "baseline/expectation_file.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <set>
#include <utility>

#include "backends/backend_registry.h"
#include "core/errors.h"

namespace snell {
namespace {

namespace fs = std::filesystem;

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

[[noreturn]] void badLine(const fs::path& file, int line, const std::string& what) {
  throw UsageError(fmt::format("{}:{}: {}", file.string(), line, what));
}

bool isDate(const std::string& s) {
  if (s.size() != 10 || s[4] != '-' || s[7] != '-') return false;
  for (std::size_t k : {0, 1, 2, 3, 5, 6, 8, 9})
    if (s[k] < '0' || s[k] > '9') return false;
  const std::chrono::year_month_day date{std::chrono::year(std::stoi(s.substr(0, 4))),
                                         std::chrono::month(std::stoul(s.substr(5, 2))),
                                         std::chrono::day(std::stoul(s.substr(8, 2)))};
  return date.ok();
}

// A `# key: value` comment with one of the metadata keys; other comments are
// free text. Returns false for free text.
bool readMetadata(const std::string& comment, EntryMetadata& metadata, const fs::path& file,
                  int line) {
  const auto colon = comment.find(':');
  if (colon == std::string::npos) return false;
  const std::string key = trim(comment.substr(0, colon));
  const std::string value = trim(comment.substr(colon + 1));
  std::string* field = key == "reason"    ? &metadata.reason
                       : key == "link"    ? &metadata.link
                       : key == "added"   ? &metadata.added
                       : key == "expires" ? &metadata.expires
                                          : nullptr;
  if (!field) return false;
  if ((key == "added" || key == "expires") && !isDate(value))
    badLine(file, line, fmt::format("`{}: {}` is not a date; write it as YYYY-MM-DD", key, value));
  *field = value;
  return true;
}

template <class Entry>
void readFile(const fs::path& file, const std::string& today, std::vector<Entry>& entries) {
  std::ifstream in(file);
  if (!in) return;  // a missing file is an empty list
  EntryMetadata pending;
  int number = 0;
  for (std::string raw; std::getline(in, raw);) {
    ++number;
    // A byte order mark (an editor's UTF-8 with BOM) would make the first
    // entry a name no case has.
    if (number == 1 && raw.starts_with("\xEF\xBB\xBF")) raw.erase(0, 3);
    const std::string line = trim(raw);
    if (line.empty()) {
      // Metadata belongs to the entry directly below it: across a blank
      // line it belongs to none. An expiry date would then be dropped
      // without a word, and the entry would never expire; a reason or link
      // of a header is a comment like any other.
      if (!pending.expires.empty())
        badLine(file, number,
                "a blank line below an `# expires:` comment: it belongs to the entry directly "
                "below it; remove the blank line");
      pending = {};
      continue;
    }
    if (line[0] == '#') {
      readMetadata(trim(line.substr(1)), pending, file, number);
      continue;
    }
    if (!pending.expires.empty() && pending.expires < today)
      badLine(
          file, number,
          fmt::format("this entry expired on {}{}; check the case again, then delete the "
                      "entry or give it a new `# expires:` date",
                      pending.expires, pending.reason.empty() ? "" : " (" + pending.reason + ")"));
    Entry entry;
    entry.place = {file.string(), number, line};
    entry.metadata = std::exchange(pending, {});
    if constexpr (std::is_same_v<Entry, KnownFailure>) {
      const auto comma = line.find(',');
      if (comma == std::string::npos)
        badLine(file, number, "expected `case,Status` (a case id, a comma and a status)");
      // Case ids hold no comma: a third field is a note the format has no
      // place for.
      if (line.find(',', comma + 1) != std::string::npos)
        badLine(file, number,
                fmt::format("`{}` has more than two fields; write `case,Status`, and a note "
                            "as a `# reason:` comment above it",
                            line));
      entry.caseId = trim(line.substr(0, comma));
      const std::string status = trim(line.substr(comma + 1));
      const std::optional<Status> parsed = statusFromName(status);
      if (!parsed || !isFailure(*parsed))
        badLine(
            file, number,
            fmt::format("`{}` is not a failing status; use Fail, CompileError, Timeout or Crash",
                        status));
      entry.status = *parsed;
    } else {
      entry.pattern = line;
      try {
        entry.regex = std::regex(line, std::regex::ECMAScript);
      } catch (const std::regex_error& error) {
        badLine(file, number,
                fmt::format("`{}` is not a regular expression ({})", line, error.what()));
      }
    }
    entries.push_back(std::move(entry));
  }
  if (!pending.reason.empty() || !pending.expires.empty() || !pending.added.empty() ||
      !pending.link.empty())
    badLine(file, number, "metadata comments at the end of the file belong to no entry");
}

const CasePattern* firstMatch(const std::vector<CasePattern>& patterns, const std::string& caseId) {
  for (const CasePattern& p : patterns)
    if (std::regex_search(caseId, p.regex)) return &p;
  return nullptr;
}

}  // namespace

std::string EntryPlace::where() const { return fmt::format("{}:{}", file, line); }

const KnownFailure* Expectations::knownFailure(const std::string& caseId) const {
  for (const KnownFailure& f : fails)
    if (f.caseId == caseId) return &f;
  return nullptr;
}

const CasePattern* Expectations::flake(const std::string& caseId) const {
  return firstMatch(flakes, caseId);
}

const CasePattern* Expectations::skip(const std::string& caseId) const {
  return firstMatch(skips, caseId);
}

const Expectations& ExpectationSet::of(const std::string& backend) const {
  static const Expectations none;
  const auto it = byBackend.find(backend);
  return it == byBackend.end() ? none : it->second;
}

Expectations readExpectationFiles(const fs::path& fails, const fs::path& flakes,
                                  const fs::path& skips, const std::string& today) {
  Expectations e;
  readFile(fails, today, e.fails);
  readFile(flakes, today, e.flakes);
  readFile(skips, today, e.skips);
  std::map<std::string, const KnownFailure*> seen;
  for (const KnownFailure& f : e.fails)
    if (!seen.emplace(f.caseId, &f).second)
      badLine(f.place.file, f.place.line,
              fmt::format("{} is listed twice (first at line {}); keep one line", f.caseId,
                          seen[f.caseId]->place.line));
  return e;
}

namespace {

// A folder's files are BACKEND-fails.txt, -flakes.txt and -skips.txt: one
// named for no backend (vulkan-fails.txt), or a folder with none at all (a
// wrong path), would be no expectations and pass the gate without a word.
void requireBackendNamedFiles(const fs::path& folder) {
  std::error_code error;
  int found = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    for (const char* suffix : {"-fails.txt", "-flakes.txt", "-skips.txt"}) {
      if (!name.ends_with(suffix) || name.size() == std::string_view(suffix).size()) continue;
      ++found;
      const std::string backend = name.substr(0, name.size() - std::string_view(suffix).size());
      const auto& entries = backendRegistry().entries();
      if (std::none_of(entries.begin(), entries.end(),
                       [&](const BackendEntry& e) { return e.name == backend; })) {
        std::vector<std::string> names;
        for (const BackendEntry& e : entries) names.push_back(e.name);
        throw UsageError(fmt::format(
            "{}: `{}` is no backend, so its entries would apply to none; name it BACKEND{} "
            "for one of {}",
            entry.path().string(), backend, suffix, fmt::join(names, ", ")));
      }
    }
  }
  if (found == 0)
    throw UsageError(
        fmt::format("{}: holds no expectation files (BACKEND-fails.txt, -flakes.txt, "
                    "-skips.txt); give the folder that holds them",
                    folder.string()));
}

}  // namespace

ExpectationSet loadExpectations(const fs::path& source, const std::vector<std::string>& backends,
                                const std::string& today) {
  ExpectationSet set;
  set.source = source.string();
  if (fs::is_directory(source)) {
    requireBackendNamedFiles(source);
    // Every backend's files are read, those of backends this run leaves out
    // too: a malformed or expired entry is found by every job that reads
    // the folder, not only by the one that runs its backend.
    for (const BackendEntry& entry : backendRegistry().entries()) {
      const Expectations e = readExpectationFiles(source / (entry.name + "-fails.txt"),
                                                  source / (entry.name + "-flakes.txt"),
                                                  source / (entry.name + "-skips.txt"), today);
      if (std::find(backends.begin(), backends.end(), entry.name) != backends.end())
        set.byBackend[entry.name] = e;
    }
    return set;
  }
  const std::string name = source.filename().string();
  for (const char* suffix : {"-fails.txt", "-flakes.txt", "-skips.txt"}) {
    const std::string s = suffix;
    if (name.size() <= s.size() || name.compare(name.size() - s.size(), s.size(), s) != 0) continue;
    if (!fs::exists(source))
      throw UsageError(
          fmt::format("{}: no such file; give an expectations folder or an existing "
                      "PREFIX-fails.txt, -flakes.txt or -skips.txt",
                      source.string()));
    const fs::path prefix = source.parent_path() / name.substr(0, name.size() - s.size());
    const Expectations e =
        readExpectationFiles(prefix.string() + "-fails.txt", prefix.string() + "-flakes.txt",
                             prefix.string() + "-skips.txt", today);
    for (const std::string& backend : backends) set.byBackend[backend] = e;
    return set;
  }
  throw UsageError(fmt::format(
      "{}: not an expectations folder nor a file named PREFIX-fails.txt, PREFIX-flakes.txt or "
      "PREFIX-skips.txt",
      source.string()));
}

std::vector<std::string> entriesMatchingNoCase(const ExpectationSet& set,
                                               const std::vector<std::string>& caseIds) {
  const std::set<std::string> known(caseIds.begin(), caseIds.end());
  std::set<std::string> said;  // FILE:LINE of the entries already noted
  std::vector<std::string> notes;
  const auto note = [&](const EntryPlace& place, const std::string& what) {
    if (said.insert(place.where()).second) notes.push_back(place.where() + ": " + what);
  };
  for (const auto& [backend, e] : set.byBackend) {
    for (const KnownFailure& f : e.fails) {
      if (known.contains(f.caseId)) continue;
      const auto slash = f.caseId.find('/');
      const bool prefixed =
          slash != std::string::npos && known.contains(f.caseId.substr(slash + 1));
      note(f.place, prefixed ? fmt::format("`{}` is no case id; drop the backend in front of it "
                                           "(`{}`)",
                                           f.caseId, f.caseId.substr(slash + 1))
                             : fmt::format("`{}` is no case of the catalog; check it against "
                                           "`snell list`",
                                           f.caseId));
    }
    for (const std::vector<CasePattern>* patterns : {&e.flakes, &e.skips})
      for (const CasePattern& p : *patterns)
        if (std::none_of(known.begin(), known.end(),
                         [&](const std::string& id) { return std::regex_search(id, p.regex); }))
          note(p.place, fmt::format("`{}` matches no case of the catalog; check it against "
                                    "`snell list`",
                                    p.pattern));
  }
  return notes;
}

std::string todayUtc() {
  const auto days = std::chrono::floor<std::chrono::days>(std::chrono::system_clock::now());
  const std::chrono::year_month_day date{days};
  return fmt::format("{:04}-{:02}-{:02}", static_cast<int>(date.year()),
                     static_cast<unsigned>(date.month()), static_cast<unsigned>(date.day()));
}

}  // namespace snell
