#include "runner/eval_server_protocol.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdlib>
#include <nlohmann/json.hpp>

#include "core/build_id.h"
#include "core/errors.h"

namespace snell {
namespace {

using nlohmann::json;

constexpr int kProtocol = 1;

}  // namespace

std::string requestHeaderLine(const EvalRequest& request) {
  return json{{"snell_eval", kProtocol}, {"backend", request.backend}, {"build", request.build}}
             .dump() +
         '\n';
}

EvalRequest parseRequestHeader(std::string_view line) {
  const json header = json::parse(line.begin(), line.end(), nullptr, false);
  const auto has = [&](const char* key, bool (json::*is)() const noexcept) {
    return header.contains(key) && (header[key].*is)();
  };
  if (!header.is_object() || !has("snell_eval", &json::is_number_integer) ||
      header["snell_eval"] != kProtocol || !has("backend", &json::is_string) ||
      !has("build", &json::is_string))
    throw UsageError("not a snell eval request (protocol 1)");
  return {header["backend"].get<std::string>(), header["build"].get<std::string>()};
}

std::string replyTrailerLine(const EvalReply& reply) {
  const EvalSummary& s = reply.summary;
  json trailer = {{"answered", s.answered},
                  {"malformed", s.malformed},
                  {"outside_spec", s.outsideSpec},
                  {"first_malformed_line", s.firstMalformedLine},
                  {"first_malformed_reason", s.firstMalformedReason},
                  {"server_stopped", reply.serverStopped}};
  if (!reply.error.empty()) trailer["error"] = reply.error;
  // The reasons may quote input that is not UTF-8.
  return std::string(1, kEvalTrailerMark) +
         trailer.dump(-1, ' ', false, json::error_handler_t::replace) + '\n';
}

EvalReply parseReplyTrailer(std::string_view line) {
  try {
    const json trailer = json::parse(line.begin(), line.end());
    EvalReply reply;
    reply.summary.answered = trailer.at("answered").get<std::size_t>();
    reply.summary.malformed = trailer.at("malformed").get<std::size_t>();
    reply.summary.outsideSpec = trailer.at("outside_spec").get<std::size_t>();
    reply.summary.firstMalformedLine = trailer.at("first_malformed_line").get<std::size_t>();
    reply.summary.firstMalformedReason = trailer.at("first_malformed_reason").get<std::string>();
    reply.serverStopped = trailer.at("server_stopped").get<bool>();
    reply.error = trailer.value("error", "");
    return reply;
  } catch (const json::exception& error) {
    throw SetupError(
        fmt::format("the server's reply does not end as snell serve's do ({})", error.what()));
  }
}

std::string defaultServeSocket(const std::string& backend) {
  const char* runtime = std::getenv("XDG_RUNTIME_DIR");
  if (runtime && *runtime) return fmt::format("{}/snell-serve-{}.sock", runtime, backend);
  return fmt::format("/tmp/snell-serve-{}-{}.sock", getuid(), backend);
}

std::string evalBuildId() {
  return buildIdContaining(reinterpret_cast<const void*>(&requestHeaderLine));
}

}  // namespace snell
