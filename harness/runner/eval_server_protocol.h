#pragma once
// What `snell eval --server` and `snell serve` say to each other over a
// Unix socket. The client sends one header line (JSON), then its JSON Lines
// input as they are, and shuts its side when the input ends. The server
// sends the answers exactly as `snell eval` prints them, then one record
// separator byte (0x1e, which JSON text always escapes, so no answer holds
// it) and the trailer: one JSON line with the summary, or the error that
// stopped the request.
#include <string>
#include <string_view>

#include "runner/builtin_eval.h"

namespace snell {

inline constexpr char kEvalTrailerMark = '\x1e';

struct EvalRequest {
  std::string backend;  // the backend the client asked for (a server runs one)
  std::string build;    // the client's build ID: answers come from the same code
};

struct EvalReply {
  EvalSummary summary;
  std::string error;           // non-empty: the request was not answered, and why
  bool serverStopped = false;  // the server exits after this reply
};

std::string requestHeaderLine(const EvalRequest& request);
// Throws UsageError for a header that is not one of ours.
EvalRequest parseRequestHeader(std::string_view line);

std::string replyTrailerLine(const EvalReply& reply);
// Throws SetupError for a trailer that is not one of ours.
EvalReply parseReplyTrailer(std::string_view line);

// Where `snell serve --backend NAME` listens unless told otherwise:
// $XDG_RUNTIME_DIR/snell-serve-NAME.sock, else /tmp/snell-serve-UID-NAME.sock.
std::string defaultServeSocket(const std::string& backend);

// This build of snell's ID (see core/build_id.h).
std::string evalBuildId();

}  // namespace snell
