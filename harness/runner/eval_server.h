#pragma once
// `snell serve`: one backend brought up once, answering `snell eval
// --server` requests over a Unix socket, one at a time. Starting a driver
// is most of a small eval's time (llvmpipe: 30 to 50 ms a process); a
// server pays it once. Before each request it checks the code it has
// loaded (core/watched_files.h): when a driver or snell itself has changed
// on disk, it refuses the request, says which file changed, and stops.
#include <sys/types.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "core/watched_files.h"
#include "runner/builtin_eval.h"
#include "runner/interrupt_flag.h"
#include "runner/unix_socket.h"

namespace snell {

struct ServeOptions {
  std::string socketPath;
  // Files to watch besides the loaded code (a Vulkan ICD manifest, a
  // driver that is loaded through another library's name).
  std::vector<std::string> watch;
  // Stops after this long without a request; zero never.
  std::chrono::seconds idleExit{1800};
  EvalOptions eval;
};

class EvalServer {
 public:
  // Answers one call of each probe program (so that no request pays for
  // their compiles), takes the snapshot of the loaded code and listens at
  // options.socketPath (see listenAt), unless `interrupt` has already
  // seen a signal: `backend` must already be up.
  // `interrupt` is installed by the caller before the driver starts, so
  // that SIGINT/SIGTERM at any point stop the server through its
  // destructor (which removes the socket).
  EvalServer(Backend& backend, std::string backendName, ServeOptions options,
             const InterruptFlag& interrupt);
  ~EvalServer();  // removes the socket file, if it is still this server's
  EvalServer(const EvalServer&) = delete;
  EvalServer& operator=(const EvalServer&) = delete;

  std::size_t watchedFiles() const { return watched_.size(); }

  // Answers requests until SIGINT or SIGTERM, the idle time, or a changed
  // file; returns which, in words. Writes a line per request to `log`.
  std::string run(std::FILE* log);

 private:
  // Answers one connection; false when the server must stop (`why` says).
  bool answer(int fd, std::FILE* log, std::string& why);

  Backend& backend_;
  std::string backendName_;
  ServeOptions options_;
  const InterruptFlag& interrupt_;
  PrecisionRules rules_;
  std::string build_;
  UniqueFd listening_;
  ino_t socketInode_ = 0;  // of the socket file this server bound
  WatchedFiles watched_;
};

}  // namespace snell
