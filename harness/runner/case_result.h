#pragma once
// Everything one case on one backend produced: what the reports print.
#include <string>
#include <vector>

#include "backends/backend.h"
#include "compare/image_compare.h"
#include "compare/vector_check.h"
#include "core/phase_clock.h"
#include "core/status.h"

namespace snell {

struct CaseResult {
  std::string caseId;
  std::string backend;  // "gl" / "vk"
  Status status = Status::Pass;
  std::string message;  // why, when not Pass: first failures, compile log, error
  std::string title;
  std::string sourceFile, sourceWhere;
  DriverInfo driver;
  std::size_t vertices = 0;
  std::vector<VaryingCheck> varyings;
  std::vector<ImageComparison> images;  // vs reference, vs golden, vs the other API
  std::string compileLog;
  double seconds = 0;         // the whole case
  double backendSeconds = 0;  // compile + draw + read back
  double oracleSeconds = 0;   // 0 when the oracle result came from the cache
  // The oracle results the case computed or read (vectors, and a reference
  // image it rendered or read from the store, not one it shared with the
  // run's other worker), and how many of them an earlier run had computed
  // (read from the oracle store, runner/oracle_store). Like the times, they
  // say how the run went, not what it found: which worker renders a shared
  // reference first varies from run to run.
  int oracleResults = 0;
  int oracleStored = 0;
  // The case's wall time by phase, which add up to `seconds`; `start` comes
  // on top: a worker's start-up, charged to the first case it runs.
  PhaseTimes phases;
  // The statuses of reruns of an unexpected failure, in order: a failure
  // that passes on a rerun is a flake, and is reported as one.
  std::vector<Status> reruns;
  // "I/N" when the run was shard I of N (`run --shard`), so that a merge can
  // tell a shard that is missing; empty for a whole run.
  std::string shard;
  // With `shard`: the selection the run was split from (its --filter and
  // --backend as given), so that a merge can tell shards of different runs,
  // whose cases together are not one run's.
  std::string shardOf;
  // With `shard`: how many cases each shard of that run holds (those not
  // skipped on every backend), so that a merge can tell whether a shard
  // none of its inputs holds had cases to give.
  std::vector<std::size_t> shardCases;
  // The digest of the listing as it ran (core/listing_digest.h), so that a
  // merge can tell a shard run on another catalog; empty in records written
  // before records carried it.
  std::string listingDigest;

  // One vector (or scalar) per captured output per vertex.
  std::size_t vectorsChecked() const { return vertices * varyings.size(); }
  std::size_t componentsChecked() const;
  std::size_t componentsUndefined() const;
  std::size_t componentsFailed() const;
  double worstSlack() const;
  // A failure that passed on a rerun: a flake, which passes the gate.
  bool passedOnRerun() const;
  // The status the gate goes by: Pass for a flake, else `status`.
  Status gateStatus() const;
  // The status as a person reads it: "Timeout, then Pass on a rerun
  // (Flake)" for a flake, "Fail (reruns: Fail)" for a failure rerun.
  std::string statusText() const;
  // The reruns' statuses in order: "Fail, Pass".
  std::string rerunsText() const;
};

}  // namespace snell
