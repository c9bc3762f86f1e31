#include "baseline/compare_runs.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/errors.h"
#include "core/listing_digest.h"

namespace snell {
namespace {

std::map<std::string, const CaseResult*> keyed(const RunSide& side, bool byCase) {
  std::map<std::string, const CaseResult*> out;
  for (const CaseResult& r : side.results) {
    if (!side.backend.empty() && r.backend != side.backend) continue;
    out[byCase ? r.caseId : r.backend + " " + r.caseId] = &r;
  }
  return out;
}

// The largest image error of a result against each thing it was compared
// with: the CPU reference, the golden, the other API's image.
std::map<std::string, double> imageErrors(const CaseResult& r) {
  std::map<std::string, double> errors;
  for (const ImageComparison& c : r.images) {
    if (!c.problem.empty()) continue;  // not made (sizes differ, an image missing): no error
    const auto [it, fresh] = errors.emplace(c.against, c.maxError);
    if (!fresh) it->second = std::max(it->second, c.maxError);
  }
  return errors;
}

void checkDrift(const std::string& key, const std::string& metric, double from, double to,
                double floor, const DriftRule& rule, std::vector<Drift>& drift) {
  if (std::isnan(from) || std::isnan(to) || to <= floor) return;
  if (to > rule.factor * std::max(from, floor)) drift.push_back({key, metric, from, to});
}

std::string number(double x) { return std::isfinite(x) ? fmt::format("{:.3g}", x) : "inf"; }

nlohmann::json changesToJson(const std::vector<StatusChange>& changes) {
  nlohmann::json out = nlohmann::json::array();
  for (const StatusChange& c : changes)
    out.push_back({{"key", c.key}, {"from", statusName(c.from)}, {"to", statusName(c.to)}});
  return out;
}

// JSON has no infinity.
nlohmann::json jsonNumber(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json();
}

}  // namespace

RunComparison compareRuns(const RunSide& from, const RunSide& to, const DriftRule& rule) {
  if (from.backend.empty() != to.backend.empty())
    throw UsageError(
        fmt::format("{} and {}: name a backend on both sides (FILE@gl FILE@vk) or on "
                    "neither",
                    from.label, to.label));
  const bool byCase = !from.backend.empty();
  const auto a = keyed(from, byCase);
  const auto b = keyed(to, byCase);
  RunComparison c;
  c.from = from.label;
  c.to = to.label;
  for (const auto& [key, old] : a) {
    const auto it = b.find(key);
    if (it == b.end()) {
      (to.incomplete ? c.notReached : c.removed).push_back(key);
      continue;
    }
    const CaseResult& now = *it->second;
    // A record of a case that ended while its listing was being edited
    // ran an unknown text: edited, whatever the other record says.
    if (!old->listingDigest.empty() && !now.listingDigest.empty() &&
        (old->listingDigest != now.listingDigest || now.listingDigest == kListingEditedDuringRun))
      c.listingEdited.push_back(key);
    // A flake passes the gate in `run` and `merge`: judged here by the same
    // status, and listed apart.
    const Status was = old->gateStatus(), is = now.gateStatus();
    if (now.passedOnRerun())
      c.flakes.push_back({key, now.status,
                          *std::find_if(now.reruns.begin(), now.reruns.end(),
                                        [](Status s) { return !isFailure(s); })});
    const StatusChange change{key, was, is};
    if (was == is) ++c.unchanged;
    // Support that comes or goes is a change, not better or worse; but a
    // case a build newly claims to support and then fails is a regression.
    else if (is == Status::NotSupported || (was == Status::NotSupported && !isFailure(is)))
      c.changes.push_back(change);
    else if (worstOf(was, is) == is)
      c.regressions.push_back(change);
    else
      c.fixes.push_back(change);
    checkDrift(key, "worst slack", old->worstSlack(), now.worstSlack(), rule.slackFloor, rule,
               c.drift);
    // Each image comparison both runs made: a growing distance from the
    // golden (what was blessed) or from the other API is drift as much as
    // one from the reference.
    const std::map<std::string, double> before = imageErrors(*old);
    for (const auto& [against, error] : imageErrors(now))
      if (const auto was = before.find(against); was != before.end())
        checkDrift(key, "image error vs " + against, was->second, error, rule.imageFloor, rule,
                   c.drift);
  }
  for (const auto& [key, r] : b)
    if (!a.count(key)) c.added.push_back(key);
  return c;
}

void printComparison(std::ostream& out, const RunComparison& c, const DriftRule& rule) {
  fmt::print(out,
             "{} -> {}: {} regressions, {} fixes, {} changes, {} flakes, {} new, {} removed, {}"
             "{} drifted (grew more than {}x), {} with the same status to the gate (drifted ones "
             "included, and flakes that passed before){}\n",
             c.from, c.to, c.regressions.size(), c.fixes.size(), c.changes.size(), c.flakes.size(),
             c.added.size(), c.removed.size(),
             c.notReached.empty() ? std::string()
                                  : fmt::format("{} not reached (the later run was interrupted), ",
                                                c.notReached.size()),
             c.drift.size(), rule.factor, c.unchanged,
             c.listingEdited.empty()
                 ? std::string()
                 : fmt::format("; {} ran another text of their listing", c.listingEdited.size()));
  for (const auto& [word, list] : {std::pair{"regression", &c.regressions},
                                   std::pair{"fix", &c.fixes}, std::pair{"change", &c.changes}})
    for (const StatusChange& s : *list)
      fmt::print(out, "  {:<10}  {}: {} -> {}\n", word, s.key, statusName(s.from),
                 statusName(s.to));
  for (const StatusChange& s : c.flakes)
    fmt::print(out, "  {:<10}  {}: {}, then {} on a rerun\n", "flake", s.key, statusName(s.from),
               statusName(s.to));
  for (const std::string& key : c.added) fmt::print(out, "  {:<10}  {}\n", "new", key);
  for (const std::string& key : c.removed) fmt::print(out, "  {:<10}  {}\n", "removed", key);
  for (const std::string& key : c.notReached) fmt::print(out, "  {:<10}  {}\n", "not reached", key);
  for (const Drift& d : c.drift)
    fmt::print(out, "  {:<10}  {}: {} {} -> {}{}\n", "drift", d.key, d.metric, number(d.from),
               number(d.to), d.from > 0 ? fmt::format(" (x{:.1f})", d.to / d.from) : "");
  for (const std::string& key : c.listingEdited)
    fmt::print(out,
               "  {:<10}  {}: its listing's manifest or shader files differ between the runs\n",
               "edited", key);
}

nlohmann::json comparisonToJson(const RunComparison& c) {
  nlohmann::json drift = nlohmann::json::array();
  for (const Drift& d : c.drift)
    drift.push_back({{"key", d.key},
                     {"metric", d.metric},
                     {"from", jsonNumber(d.from)},
                     {"to", jsonNumber(d.to)}});
  return {{"from", c.from},
          {"to", c.to},
          {"regressions", changesToJson(c.regressions)},
          {"fixes", changesToJson(c.fixes)},
          {"changes", changesToJson(c.changes)},
          {"flakes", changesToJson(c.flakes)},
          {"new", c.added},
          {"removed", c.removed},
          {"not_reached", c.notReached},
          {"drift", drift},
          {"listing_edited", c.listingEdited},
          {"unchanged", c.unchanged}};
}

}  // namespace snell
