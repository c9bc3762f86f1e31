#pragma once
// Small builders shared by the GL tests, so each test reads as the job it
// sends rather than as struct plumbing.
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "backends/backend.h"

namespace snell::gltest {

inline ProgramSource vertexOnly(std::string vertex, Profile profile = Profile::Core,
                                std::string path = "") {
  ProgramSource source;
  source.vertex = std::move(vertex);
  source.vertexPath = std::move(path);
  source.profile = profile;
  return source;
}

inline AttributeStream attribute(std::string name, int components, std::vector<float> data) {
  AttributeStream stream;
  stream.name = std::move(name);
  stream.components = components;
  stream.data = std::move(data);
  return stream;
}

inline void addAttribute(CaptureJob& job, AttributeStream stream) {
  std::string name = stream.name;
  job.attributes[name] = std::move(stream);
}

inline Value value(ValueType type, std::vector<float> data) { return Value{type, std::move(data)}; }

inline const CapturedVarying& varyingNamed(const CaptureOutcome& outcome, const std::string& name) {
  for (const auto& varying : outcome.varyings)
    if (varying.name == name) return varying;
  throw std::runtime_error("no captured varying named " + name);
}

}  // namespace snell::gltest
