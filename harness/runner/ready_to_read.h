#pragma once
// Whether a read of `fd` would return at once: data is there, or its end
// or an error is known. For streambufs' showmanyc(), so that a reader can
// answer the lines it has instead of waiting on a writer that waits for
// those answers (runner/line_chunks.h).
#include <poll.h>

namespace snell {

inline bool readsWithoutWaiting(int fd) {
  pollfd ready{fd, POLLIN, 0};
  return ::poll(&ready, 1, 0) > 0;  // POLLHUP and POLLERR count: the read ends
}

}  // namespace snell
