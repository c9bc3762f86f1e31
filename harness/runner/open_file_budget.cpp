#include "runner/open_file_budget.h"

#include <sys/resource.h>

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace snell {
namespace {

// The descriptors open now (the listing's own one left out).
long openDescriptors() {
  std::error_code error;
  long count = 0;
  for (std::filesystem::directory_iterator it("/proc/self/fd", error), end; !error && it != end;
       it.increment(error))
    ++count;
  return error ? 0 : std::max(0L, count - 1);
}

long descriptorsNeeded(long open, long workers) {
  // The last worker to start holds six while its pipes are made.
  return open + kDescriptorsKeptForTheRun + workers * kDescriptorsPerWorker + kDescriptorsPerWorker;
}

}  // namespace

WorkerFit fitWorkersToOpenFileLimit(int wanted) {
  rlimit limits{};
  if (getrlimit(RLIMIT_NOFILE, &limits) != 0 || limits.rlim_cur == RLIM_INFINITY)
    return {wanted, -1, -1};
  const long open = openDescriptors();
  const long needed = descriptorsNeeded(open, wanted);
  if (static_cast<rlim_t>(needed) > limits.rlim_cur) {
    rlimit raised = limits;
    raised.rlim_cur = std::min<rlim_t>(limits.rlim_max, static_cast<rlim_t>(needed));
    if (setrlimit(RLIMIT_NOFILE, &raised) == 0) limits = raised;
  }
  const long soft = static_cast<long>(limits.rlim_cur);
  const long hard = limits.rlim_max == RLIM_INFINITY ? -1 : static_cast<long>(limits.rlim_max);
  const long room = soft - descriptorsNeeded(open, 0);
  const long fit = std::clamp(room / kDescriptorsPerWorker, 0L, static_cast<long>(wanted));
  return {static_cast<int>(fit), soft, hard};
}

}  // namespace snell
