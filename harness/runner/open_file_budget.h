#pragma once
// How many worker processes the open-file limit lets a run keep. Each
// worker holds three pipe ends in snell's own process (its stdin, stdout
// and stderr; six while it starts), beside the files the run itself opens.
// A -j past what RLIMIT_NOFILE leaves would fail part way through the run
// with "Too many open files", so the workers are fitted to the limit
// before the first starts, raising the soft limit toward the hard one
// where that is enough.

namespace snell {

struct WorkerFit {
  int workers = 0;  // what fits, at most the number wanted
  long limit = 0;   // the soft limit after any raise
  long hardLimit = 0;
};

// The descriptors snell opens for its own files while workers run, beyond
// those open when the workers are fitted: the results file, an oracle store
// entry, an image, the image module's libraries as they load. A whole-suite
// run with two workers peaked at 13 open in all, 4 of them its own files.
inline constexpr long kDescriptorsKeptForTheRun = 16;
inline constexpr long kDescriptorsPerWorker = 3;

// `wanted` workers, or fewer where the limit (once raised as far as it may
// go) holds fewer; 0 when not even one fits.
WorkerFit fitWorkersToOpenFileLimit(int wanted);

}  // namespace snell
