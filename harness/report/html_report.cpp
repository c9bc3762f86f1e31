#include "report/html_report.h"

#include <fmt/format.h>
#include <stdlib.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <kainjow/mustache.hpp>
#include <map>
#include <optional>
#include <set>

#include "baseline/compare_runs.h"
#include "compare/image_io.h"
#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/utf8.h"
#include "golden/golden_store.h"
#include "report/data_uri.h"
#include "report/gnuplot_batch.h"
#include "report/heat_map_chart.h"
#include "report/recorded_images.h"
#include "report/report_template.h"
#include "report/slack_histogram_chart.h"
#include "report/sweep_findings.h"
#include "runner/cross_api_check.h"
#include "runner/image_check.h"

namespace snell {
namespace {

namespace fs = std::filesystem;
using kainjow::mustache::data;
using kainjow::mustache::list;

std::string number(double x) { return std::isfinite(x) ? fmt::format("{:.4g}", x) : "inf"; }

// HTML's escaping, with what HTML forbids in a document spelled out as
// \xNN, byte by byte: C0 and C1 control characters (a log's ESC or CSI, a
// manifest's U+0001) and bytes that are not UTF-8 (a multibyte character
// cut short in a worker's stderr). A raw one makes the page a parse error.
std::string htmlEscaped(const std::string& text) {
  return utf8SpellingOut(kainjow::mustache::html_escape<std::string>(text), [](char32_t c) {
    if (c < 0x20) return c == '\t' || c == '\n' || c == '\r';
    return c < 0x7F || c > 0x9F;
  });
}

// A result's status in counts and the matrix: a failure that passed on a
// rerun is a Flake there, as results.csv calls it, not the failure.
std::string tallyName(const CaseResult& r) {
  return r.passedOnRerun() ? "Flake" : statusName(r.status);
}

std::string listingOf(const std::string& caseId) {
  const auto slash = caseId.rfind('/');
  return slash == std::string::npos ? caseId : caseId.substr(0, slash);
}

std::string anchorOf(const std::string& caseId, const std::string& prefix = "case-") {
  std::string a = prefix;
  for (char c : caseId) a += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
  return a;
}

struct Column {
  std::size_t run;
  std::string backend;
  std::string name;
};

// A picture drawn later by gnuplot, or a file read now.
struct PendingPicture {
  std::string caption, cssClass;
  fs::path file;
  std::string mime;
};

// Images whose size differs from the other's cannot be differenced.
bool sameSize(const Image& a, const Image& b) { return a.width == b.width && a.height == b.height; }

class ReportBuilder {
 public:
  ReportBuilder(const std::vector<ReportRun>& runs, const ReportOptions& options, fs::path work)
      : runs_(runs), options_(options), batch_(work) {
    for (const Case& c : options.catalog) catalog_[c.id] = &c;
    for (std::size_t r = 0; r < runs.size(); ++r) {
      std::vector<std::string> seen;
      for (const CaseResult& result : runs[r].results) {
        if (std::find(seen.begin(), seen.end(), result.backend) != seen.end()) continue;
        seen.push_back(result.backend);
        columns_.push_back({r, result.backend,
                            runs.size() == 1
                                ? result.backend
                                : fmt::format("{}: {}", runs[r].label, result.backend)});
      }
      for (const CaseResult& result : runs[r].results) {
        byCase_[result.caseId][columnOf(r, result.backend)] = &result;
        if (std::find(caseOrder_.begin(), caseOrder_.end(), result.caseId) == caseOrder_.end())
          caseOrder_.push_back(result.caseId);
      }
    }
  }

  std::string render(ReportStats& stats) {
    // Read first: a malformed sweep stops the report before any drawing.
    std::optional<SweepFindings> sweep;
    if (!options_.sweepDir.empty()) sweep = readSweepFindings(options_.sweepDir);
    data page;
    page.set("title", options_.title);
    page.set("generated", generatedAt());
    std::size_t count = 0;
    for (const ReportRun& run : runs_) count += run.results.size();
    page.set("result_count", std::to_string(count));
    page.set("tallies", tallies());
    if (runs_.size() > 1) page.set("changes", changes());
    data incompleteRuns = data::type::list;
    for (const ReportRun& run : runs_)
      if (run.incomplete) incompleteRuns.push_back(data("label", run.label));
    page.set("incomplete_runs", incompleteRuns);
    list columns;
    for (const Column& c : columns_) columns.push_back(data("name", c.name));
    page.set("columns", columns);
    page.set("listings", listings(sweep.has_value()));
    page.set("has_sweep", sweep.has_value());
    if (sweep) page.set("sweep", sweepSection(*sweep, stats));
    page.set("matrix", matrix());
    page.set("drivers", drivers());
    // Cases (charts are queued now and drawn in one gnuplot run below).
    std::vector<std::string> order = caseOrder_;
    std::stable_sort(order.begin(), order.end(), [&](const std::string& a, const std::string& b) {
      return failing(a) && !failing(b);
    });
    for (const std::string& id : order) casePages_.push_back(casePage(id, stats));
    batch_.run();
    list cases;
    for (CasePage& p : casePages_) cases.push_back(finish(p, stats));
    page.set("cases", cases);
    // Said on the page too: a reader of the page never saw the command's
    // stderr, and failing image cases with no picture looked complete.
    stats.imagesMissing = hasImageCases() && stats.heatMaps == 0 && stats.pictures == 0;
    if (stats.imagesMissing)
      page.set("images_missing",
               fmt::format("No pictures or heat maps: {} (--images) holds none of these runs' "
                           "images; a run writes them to its --out folder.",
                           options_.imagesDir.string()));
    stats.cases = order.size();
    kainjow::mustache::mustache tmpl{std::string(kReportTemplate)};
    if (!tmpl.is_valid()) throw SetupError("report template: " + tmpl.error_message());
    tmpl.set_custom_escape(htmlEscaped);
    return tmpl.render(page);
  }

 private:
  struct ResultPage {
    data fields;
    fs::path histogram;
    std::vector<PendingPicture> pictures;
  };
  struct CasePage {
    data fields;
    std::vector<ResultPage> results;
    std::vector<PendingPicture> pairs;
  };

  std::size_t columnOf(std::size_t run, const std::string& backend) const {
    for (std::size_t k = 0; k < columns_.size(); ++k)
      if (columns_[k].run == run && columns_[k].backend == backend) return k;
    return 0;
  }

  // Whether the case fails in the latest run that has it: a case an
  // earlier run failed and the last one passes is fixed, not failing.
  bool failing(const std::string& id) const {
    std::size_t latest = 0;
    for (const auto& [column, r] : byCase_.at(id)) latest = std::max(latest, columns_[column].run);
    for (const auto& [column, r] : byCase_.at(id))
      if (columns_[column].run == latest && isFailure(r->gateStatus())) return true;
    return false;
  }

  // Each run's count of results by status (added across runs, they
  // counted a case failed and then fixed as both).
  list tallies() const {
    list runs;
    for (const ReportRun& run : runs_) {
      std::map<std::string, std::size_t> counts;
      for (const CaseResult& r : run.results) ++counts[tallyName(r)];
      list tally;
      for (const auto& [status, n] : counts) {
        data t;
        t.set("status", status);
        t.set("count", std::to_string(n));
        tally.push_back(t);
      }
      data row;
      if (runs_.size() > 1) row.set("label", run.label);
      row.set("tally", tally);
      runs.push_back(row);
    }
    return runs;
  }

  // From the first run to the last, as `snell compare` judges them:
  // regressions, fixes, changes, new and removed results, and drift.
  data changes() const {
    const RunComparison c = compareRuns(
        {runs_.front().label, "", runs_.front().results, runs_.front().incomplete},
        {runs_.back().label, "", runs_.back().results, runs_.back().incomplete}, DriftRule{});
    list rows;
    const auto caseRow = [&](const std::string& kind, const std::string& key,
                             const std::string& from, const std::string& to) {
      // Keys are "BACKEND CASE".
      const std::size_t space = key.find(' ');
      const std::string id = space == std::string::npos ? key : key.substr(space + 1);
      data row;
      row.set("kind", kind);
      row.set("backend", space == std::string::npos ? "" : key.substr(0, space));
      row.set("id", id);
      row.set("anchor", anchorOf(id));
      row.set("from", from);
      row.set("to", to);
      rows.push_back(row);
    };
    for (const StatusChange& r : c.regressions)
      caseRow("regression", r.key, statusName(r.from), statusName(r.to));
    for (const StatusChange& f : c.fixes)
      caseRow("fix", f.key, statusName(f.from), statusName(f.to));
    for (const StatusChange& x : c.changes)
      caseRow("change", x.key, statusName(x.from), statusName(x.to));
    for (const StatusChange& f : c.flakes)
      caseRow("flake (a rerun passed)", f.key, statusName(f.from), statusName(f.to));
    for (const std::string& key : c.added) caseRow("new", key, "", "");
    for (const std::string& key : c.removed) caseRow("removed", key, "", "");
    for (const std::string& key : c.notReached) caseRow("not reached", key, "", "");
    for (const Drift& d : c.drift)
      caseRow("drift: " + d.metric, d.key, number(d.from), number(d.to));
    data section;
    section.set("from", c.from);
    section.set("to", c.to);
    section.set("counts", fmt::format("{} regressions, {} fixes, {} changes, {} flakes, {} new, {} "
                                      "removed, {} not reached, {} drifted, {} unchanged",
                                      c.regressions.size(), c.fixes.size(), c.changes.size(),
                                      c.flakes.size(), c.added.size(), c.removed.size(),
                                      c.notReached.size(), c.drift.size(), c.unchanged));
    section.set("rows", rows);
    section.set("has_rows", !rows.empty());
    return section;
  }

  static std::string generatedAt() {
    const auto now = std::chrono::floor<std::chrono::seconds>(std::chrono::system_clock::now());
    const auto days = std::chrono::floor<std::chrono::days>(now);
    const std::chrono::year_month_day date{days};
    const std::chrono::hh_mm_ss time{now - days};
    return fmt::format("{:04}-{:02}-{:02} {:02}:{:02} UTC", static_cast<int>(date.year()),
                       static_cast<unsigned>(date.month()), static_cast<unsigned>(date.day()),
                       time.hours().count(), time.minutes().count());
  }

  list listings(bool swept) const {
    std::vector<std::string> names;
    std::map<std::string, std::map<std::size_t, std::map<std::string, std::size_t>>> counts;
    std::map<std::string, std::map<std::size_t, Status>> worst;
    for (const std::string& id : caseOrder_) {
      const std::string name = listingOf(id);
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
      for (const auto& [column, r] : byCase_.at(id)) {
        ++counts[name][column][tallyName(*r)];
        const auto it = worst[name].find(column);
        worst[name][column] =
            it == worst[name].end() ? r->gateStatus() : worstOf(it->second, r->gateStatus());
      }
    }
    list rows;
    for (const std::string& name : names) {
      data row;
      row.set("name", name);
      if (swept) row.set("sweep_anchor", anchorOf(name, "sweep-"));
      list cells;
      for (std::size_t k = 0; k < columns_.size(); ++k) {
        data cell;
        std::string text;
        for (const auto& [status, n] : counts[name][k])
          text += fmt::format("{}{} {}", text.empty() ? "" : ", ", n, status);
        cell.set("text", text.empty() ? "-" : text);
        cell.set("worst", worst[name].count(k) ? statusName(worst[name][k]) : "");
        cells.push_back(cell);
      }
      row.set("cells", cells);
      rows.push_back(row);
    }
    return rows;
  }

  std::vector<std::string> listingNames() const {
    std::vector<std::string> names;
    for (const std::string& id : caseOrder_)
      if (std::find(names.begin(), names.end(), listingOf(id)) == names.end())
        names.push_back(listingOf(id));
    return names;
  }

  // Each listing of the report with its breaks from the sweep, then the
  // sweep's own charts. Charts are already drawn: read now.
  data sweepSection(const SweepFindings& sweep, ReportStats& stats) {
    data section;
    section.set("dir", sweep.dir.string());
    list rows;
    for (const std::string& name : listingNames()) {
      const ListingFindings found = findingsFor(sweep, name);
      data row;
      row.set("name", name);
      row.set("anchor", anchorOf(name, "sweep-"));
      row.set("covered", found.covered);
      row.set("why", found.why);
      std::size_t total = 0;
      list groups;
      for (const SweepGroup& g : found.groups) {
        data group;
        group.set("backend", g.backend);
        group.set("class", g.cls);
        group.set("count", std::to_string(g.count));
        group.set("kinds", g.kinds);
        list first;
        for (const SweepPointText& p : g.first) first.push_back(data("text", p.text));
        group.set("first", first);
        group.set("worst", g.worst.text);
        groups.push_back(group);
        total += g.count;
      }
      row.set("groups", groups);
      row.set("has_groups", !found.groups.empty());
      row.set("total", std::to_string(total));
      row.set("charts", sweepCharts(found.charts, stats));
      rows.push_back(row);
    }
    section.set("listings", rows);
    section.set("charts", sweepCharts(sweep.charts, stats));
    return section;
  }

  list sweepCharts(const std::vector<SweepChart>& charts, ReportStats& stats) {
    std::vector<PendingPicture> pending;
    for (const SweepChart& c : charts) pending.push_back({c.caption, "chart", c.png, "image/png"});
    return pictures(pending, stats);
  }

  list matrix() const {
    list rows;
    for (const std::string& id : caseOrder_) {
      data row;
      row.set("id", id);
      row.set("anchor", anchorOf(id));
      list cells;
      for (std::size_t k = 0; k < columns_.size(); ++k) {
        data cell;
        const auto it = byCase_.at(id).find(k);
        if (it == byCase_.at(id).end()) {
          cell.set("status", "-");
          cell.set("slack", "");
        } else {
          const CaseResult& r = *it->second;
          cell.set("status", tallyName(r));
          std::string text = r.componentsChecked() ? "slack " + number(r.worstSlack()) : "-";
          // An image that did not pass is what the status is about: its
          // largest error and pixels over the fail threshold are shown too.
          for (const ImageComparison& c : r.images)
            if (c.verdict != ImageVerdict::Pass)
              text += fmt::format(" · {} {} ({} px over fail)", c.against, number(c.maxError),
                                  c.failed);
          cell.set("slack", text);
        }
        cells.push_back(cell);
      }
      row.set("cells", cells);
      rows.push_back(row);
    }
    return rows;
  }

  list drivers() const {
    list rows;
    std::set<std::string> seen;
    for (const Column& c : columns_)
      for (const CaseResult& r : runs_[c.run].results) {
        if (r.backend != c.backend || r.driver.renderer.empty()) continue;
        const std::string key = fmt::format("{} {} {}", c.run, r.backend, r.driver.renderer);
        if (!seen.insert(key).second) continue;
        data row;
        row.set("run", runs_[c.run].label);
        row.set("backend", r.backend);
        row.set("api", r.driver.api);
        row.set("api_version", r.driver.apiVersion);
        row.set("renderer", r.driver.renderer);
        row.set("driver_version", r.driver.driverVersion);
        row.set("device_type", r.driver.deviceType);
        rows.push_back(row);
      }
    return rows;
  }

  bool hasImageCases() const {
    for (const ReportRun& run : runs_)
      for (const CaseResult& r : run.results)
        if (!r.images.empty()) return true;
    return false;
  }

  double failThreshold(const std::string& id) const {
    const auto it = catalog_.find(id);
    return it != catalog_.end() && it->second->spec.image.fail > 0 ? it->second->spec.image.fail
                                                                   : 0.004;
  }

  // Read once: a case's images serve several heat maps.
  const Image* image(const fs::path& path) {
    auto [it, added] = images_.try_emplace(path);
    if (added && fs::exists(path)) {
      try {
        it->second = readImage(path);
      } catch (const UsageError&) {
        // An unreadable image is left out of the report, like a missing one.
      }
    }
    return it->second ? &*it->second : nullptr;
  }

  // Why the images of `r`'s backend in --images are another run's (empty
  // when they are its own, or cannot be told): their largest difference
  // from the reference beside them is not the one `r` recorded. A stale
  // folder otherwise put a passing run's pictures under a failing run's
  // numbers, with captions that contradicted them.
  std::string anotherRunsImages(const CaseResult& r, const Image* rendered, const Image* reference,
                                const std::vector<bool>& masked) const {
    if (!rendered || !reference) return "";
    const auto other = differenceNotAsRecorded(r, *rendered, *reference, masked);
    if (!other) return "";
    return fmt::format(
        "No pictures: the {} image in {} is another run's. Its largest difference from the "
        "reference there is {:.3g}; this run recorded {:.3g}. Pass --images this run's --out.",
        r.backend, options_.imagesDir.string(), other->there, other->recorded);
  }

  // The golden the run compared `r`'s image with, and the heat map of the
  // two, when the golden in --golden is the one it compared (its largest
  // difference is the one `r` recorded): a failure by the golden showed no
  // picture of it.
  void addGoldenPictures(const std::string& id, const CaseResult& r, const Image& rendered,
                         const std::vector<bool>& masked, double fail, ResultPage& rp,
                         ReportStats& stats) {
    const auto key = options_.goldenKeys.find(r.backend);
    if (options_.goldenDir.empty() || key == options_.goldenKeys.end()) return;
    for (const ImageComparison& c : r.images) {
      if (c.against != "golden" || !c.problem.empty()) continue;
      const GoldenFiles files = goldenFiles(options_.goldenDir, id, key->second);
      const Image* golden = image(files.image);
      if (!golden || !sameSize(*golden, rendered)) return;
      const double there = largestDifference(rendered, *golden, masked);
      if (std::abs(there - c.maxError) > 1e-4 * std::max(there, c.maxError) + 1e-7) {
        rp.fields.set("golden_note",
                      fmt::format("No golden picture: {} is not the golden this run compared "
                                  "with (its largest difference there is {:.3g}; the run "
                                  "recorded {:.3g}). Pass --golden the run's --golden folder.",
                                  files.image.string(), there, c.maxError));
        return;
      }
      if (c.verdict != ImageVerdict::Pass && fs::exists(files.preview))
        rp.pictures.push_back(
            {fmt::format("golden ({})", key->second), "picture", files.preview, "image/png"});
      HeatMapSummary summary;
      const fs::path png = addHeatMap(batch_, fmt::format("{} against its golden", r.backend),
                                      rendered, *golden, masked, fail, summary);
      rp.pictures.push_back({fmt::format("{} against its golden: {} pixels over {:g}", r.backend,
                                         summary.overThreshold, fail),
                             "", png, "image/png"});
      ++stats.heatMaps;
      return;
    }
  }

  CasePage casePage(const std::string& id, ReportStats& stats) {
    CasePage page;
    page.fields.set("id", id);
    page.fields.set("anchor", anchorOf(id));
    page.fields.set("failing", failing(id));
    const CaseResult& any = *byCase_.at(id).begin()->second;
    page.fields.set("title", any.title);
    page.fields.set("source", fmt::format("{} ({})", any.sourceWhere, any.sourceFile));
    const fs::path dir = options_.imagesDir / id;
    const std::vector<bool> masked = maskFlags(maskImagePath(options_.imagesDir, id));
    const double fail = failThreshold(id);
    const Image* reference = image(referenceImagePath(options_.imagesDir, id));
    bool referenceShown = false;
    std::set<std::string> notThisRuns;  // backends whose images there are another run's
    for (const auto& [column, r] : byCase_.at(id)) {
      ResultPage rp;
      rp.fields.set("column", columns_[column].name);
      rp.fields.set("status", r->statusText());
      rp.fields.set("status_class", tallyName(*r));
      if (r->status != Status::Pass) rp.fields.set("message", r->message);
      list varyings, failures;
      for (const VaryingCheck& v : r->varyings) {
        data row;
        row.set("name", v.name);
        row.set("checked", std::to_string(v.checked));
        row.set("undefined", std::to_string(v.undefined));
        row.set("failed", std::to_string(v.failed));
        row.set("worst", v.checked ? number(v.worstSlack) : "-");
        row.set("worst_vertex", v.checked ? std::to_string(v.worstVertex) : "-");
        varyings.push_back(row);
        for (const ComponentFailure& f : v.worstFailures) {
          data fr;
          fr.set("output", v.name);
          fr.set("vertex", std::to_string(f.vertex));
          fr.set("component", std::string(1, "xyzw"[f.component & 3]));
          fr.set("observed", fmt::format("{:.9g}", f.observed));
          fr.set("reference", fmt::format("{:.9g}", f.reference));
          fr.set("lo", fmt::format("{:.9g}", f.lo));
          fr.set("hi", fmt::format("{:.9g}", f.hi));
          fr.set("slack", number(f.slack));
          failures.push_back(fr);
        }
      }
      rp.fields.set("has_varyings", !r->varyings.empty());
      rp.fields.set("varyings", varyings);
      rp.fields.set("has_failures", !failures.empty());
      rp.fields.set("failures", failures);
      list images;
      for (const ImageComparison& c : r->images) {
        data row;
        row.set("against", c.against);
        row.set("verdict", imageVerdictName(c.verdict));
        row.set("max_error", number(c.maxError));
        // No pixel differs: there is no place to name.
        row.set("at", c.maxError > 0 ? fmt::format("({}, {})", c.maxX, c.maxY) : "-");
        row.set("warned", std::to_string(c.warned));
        row.set("failed", std::to_string(c.failed));
        row.set("compared", std::to_string(c.compared));
        std::string m;
        for (const auto& [reason, n] : c.masked)
          if (n) m += fmt::format("{}{} {}", m.empty() ? "" : ", ", reason, n);
        row.set("masked", m.empty() ? "none" : m);
        images.push_back(row);
      }
      rp.fields.set("has_images", !r->images.empty());
      rp.fields.set("images", images);
      std::size_t checked = 0;
      for (const VaryingCheck& v : r->varyings) checked += v.checked;
      if (checked) {
        rp.histogram = addSlackHistogram(batch_, r->varyings);
        ++stats.histograms;
      }
      const std::string& backend = columns_[column].backend;
      // Images on disk belong to the last run that wrote the folder: shown
      // for the last run only, and only when they are that run's.
      const std::string otherRuns =
          columns_[column].run + 1 == runs_.size()
              ? anotherRunsImages(*r, image(dir / (backend + ".exr")), reference, masked)
              : "";
      if (!otherRuns.empty()) {
        rp.fields.set("images_note", otherRuns);
        notThisRuns.insert(backend);
        ++stats.otherRunsImages;
      } else if (columns_[column].run + 1 == runs_.size()) {
        if (!referenceShown && fs::exists(dir / "reference.png")) {
          rp.pictures.push_back({"CPU reference", "picture", dir / "reference.png", "image/png"});
          referenceShown = true;
        }
        if (fs::exists(dir / (backend + ".png")))
          rp.pictures.push_back(
              {backend + " rendered", "picture", dir / (backend + ".png"), "image/png"});
        const Image* rendered = image(dir / (backend + ".exr"));
        if (rendered && reference && sameSize(*rendered, *reference)) {
          HeatMapSummary summary;
          const fs::path png =
              addHeatMap(batch_, fmt::format("{} against the CPU reference", backend), *rendered,
                         *reference, masked, fail, summary);
          rp.pictures.push_back({fmt::format("{} against the reference: {} pixels over {:g}",
                                             backend, summary.overThreshold, fail),
                                 "", png, "image/png"});
          ++stats.heatMaps;
        }
        if (rendered) addGoldenPictures(id, *r, *rendered, masked, fail, rp, stats);
      }
      page.results.push_back(std::move(rp));
    }
    // Every pair of backends of the last run that rendered the case. The
    // run compares only pairs whose images are within the spec
    // (renderedWithinSpec): a pair with one off the reference is drawn here
    // for a look, and its caption says it is no part of the verdict.
    std::vector<std::string> rendered;
    std::map<std::string, bool> withinSpec;
    for (const auto& [column, r] : byCase_.at(id))
      if (columns_[column].run + 1 == runs_.size() &&
          !notThisRuns.count(columns_[column].backend) &&
          image(dir / (columns_[column].backend + ".exr"))) {
        rendered.push_back(columns_[column].backend);
        withinSpec[columns_[column].backend] = renderedWithinSpec(r->status);
      }
    for (std::size_t a = 0; a < rendered.size(); ++a)
      for (std::size_t b = a + 1; b < rendered.size(); ++b) {
        const Image& first = *image(dir / (rendered[a] + ".exr"));
        const Image& second = *image(dir / (rendered[b] + ".exr"));
        if (!sameSize(first, second)) continue;
        HeatMapSummary summary;
        const fs::path png =
            addHeatMap(batch_, fmt::format("{} against {}", rendered[b], rendered[a]), second,
                       first, masked, fail, summary);
        const bool gated = withinSpec[rendered[a]] && withinSpec[rendered[b]];
        page.pairs.push_back(
            {fmt::format(
                 "{} against {} ({}): {} pixels over {:g}, largest {:.3g}{}", rendered[b],
                 rendered[a], runs_.back().label, summary.overThreshold, fail, summary.maxError,
                 gated ? "" : "; not compared by the run, one image being off the reference"),
             "", png, "image/png"});
        ++stats.heatMaps;
      }
    return page;
  }

  data finish(CasePage& page, ReportStats& stats) {
    list results;
    for (ResultPage& rp : page.results) {
      if (!rp.histogram.empty())
        rp.fields.set("histogram", dataUri("image/svg+xml", readBytes(rp.histogram)));
      rp.fields.set("pictures", pictures(rp.pictures, stats));
      results.push_back(rp.fields);
    }
    page.fields.set("results", results);
    page.fields.set("has_pairs", !page.pairs.empty());
    page.fields.set("pairs", pictures(page.pairs, stats));
    return page.fields;
  }

  list pictures(const std::vector<PendingPicture>& pending, ReportStats& stats) {
    list out;
    for (const PendingPicture& p : pending) {
      const std::string bytes = readBytes(p.file);
      if (bytes.empty()) continue;
      data picture;
      picture.set("caption", p.caption);
      picture.set("class", p.cssClass);
      picture.set("uri", dataUri(p.mime, bytes));
      out.push_back(picture);
      ++stats.pictures;
    }
    return out;
  }

  const std::vector<ReportRun>& runs_;
  const ReportOptions& options_;
  GnuplotBatch batch_;
  std::map<std::string, const Case*> catalog_;
  std::vector<Column> columns_;
  std::vector<std::string> caseOrder_;
  std::map<std::string, std::map<std::size_t, const CaseResult*>> byCase_;
  std::map<fs::path, std::optional<Image>> images_;
  std::vector<CasePage> casePages_;
};

}  // namespace

ReportStats writeHtmlReport(const std::vector<ReportRun>& runs, const ReportOptions& options,
                            const fs::path& outDir) {
  fs::create_directories(outDir);
  // The charts' scratch folder is a new one of this report's own: a folder
  // of the user's in --out (a `work/` of theirs) is never touched, and it
  // goes whatever ends the report.
  std::string pattern = (outDir / ".snell-report-XXXXXX").string();
  if (!::mkdtemp(pattern.data()))
    throw SetupError(fmt::format("{}: cannot make a scratch folder for the charts ({})",
                                 outDir.string(), std::strerror(errno)));
  const fs::path work = pattern;
  struct RemoveWork {
    fs::path path;
    ~RemoveWork() {
      std::error_code ignored;
      fs::remove_all(path, ignored);
    }
  } removeWork{work};
  ReportStats stats;
  const std::string html = ReportBuilder(runs, options, work).render(stats);
  writeFileAtomically(outDir / "index.html", html);
  stats.bytes = html.size();
  return stats;
}

}  // namespace snell
