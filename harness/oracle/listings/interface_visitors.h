#pragma once
// The visitors a listing's `visit` is run with. A listing names each of its
// interface variables once (input, uniform, constant, output); these turn
// that one list into a description, into bound values and into captured
// outputs.
#include <cmath>
#include <cstddef>
#include <vector>

#include "core/values.h"
#include "oracle/glsl/scalar.h"
#include "oracle/listings/interface_checks.h"
#include "oracle/listings/interface_types.h"
#include "oracle/vertex_oracle.h"

namespace snell::listings {

class DescribeInterface {
 public:
  template <class X>
  void input(const char* name, X&) {
    add(InterfaceEntry::Kind::Input, name, glslTypeOf<X>());
  }
  template <class X>
  void uniform(const char* name, X&) {
    add(InterfaceEntry::Kind::Uniform, name, glslTypeOf<X>());
  }
  template <class X>
  void constant(const char* name, X&) {
    static_assert(glslTypeOf<X>() == ValueType::Float, "a manifest's constants are floats");
    add(InterfaceEntry::Kind::Constant, name, ValueType::Float);
  }
  template <class X>
  void output(const char* name, X&) {
    add(InterfaceEntry::Kind::Output, name, glslTypeOf<X>());
  }

  const std::vector<InterfaceEntry>& entries() const { return entries_; }

 private:
  void add(InterfaceEntry::Kind kind, const char* name, ValueType type) {
    entries_.push_back(InterfaceEntry{kind, name, type});
  }
  std::vector<InterfaceEntry> entries_;
};

// Uniforms and constants: the same for every vertex. Expects checked input.
template <glsl::Number T>
class BindUniforms {
 public:
  BindUniforms(const UniformMap& uniforms, const ConstantMap& constants)
      : uniforms_(uniforms), constants_(constants) {}

  template <class X>
  void input(const char*, X&) {}
  template <class X>
  void uniform(const char* name, X& variable) {
    const std::vector<float>& data = uniforms_.at(name).data;
    std::size_t next = 0;
    forEachComponent(variable, [&](T& component) { component = glsl::fromFloat<T>(data[next++]); });
  }
  // `const float Name = value;` rounds the printed value to float.
  void constant(const char* name, T& variable) { variable = glsl::lit<T>(constants_.at(name)); }
  template <class X>
  void output(const char*, X&) {}

 private:
  const UniformMap& uniforms_;
  const ConstantMap& constants_;
};

// One vertex's inputs. Expects checked input.
template <glsl::Number T>
class BindVertex {
 public:
  BindVertex(const AttributeMap& attributes, std::size_t vertex)
      : attributes_(attributes), vertex_(vertex) {}

  template <class X>
  void input(const char* name, X& variable) {
    const AttributeStream& stream = attributes_.at(name);
    std::size_t next = vertex_ * static_cast<std::size_t>(stream.components);
    forEachComponent(variable,
                     [&](T& component) { component = glsl::fromFloat<T>(stream.data[next++]); });
  }
  template <class X>
  void uniform(const char*, X&) {}
  void constant(const char*, T&) {}
  template <class X>
  void output(const char*, X&) {}

 private:
  const AttributeMap& attributes_;
  std::size_t vertex_;
};

// One vertex's outputs into the varyings (in `visit` order): double fills
// `reference`, float `strict`, Interval `lo`/`hi`; each marks what the spec
// leaves undefined.
template <glsl::Number T>
class CaptureOutputs {
 public:
  CaptureOutputs(std::vector<OracleVarying>& varyings, std::size_t vertex)
      : varyings_(varyings), vertex_(vertex) {}

  template <class X>
  void input(const char*, X&) {}
  template <class X>
  void uniform(const char*, X&) {}
  void constant(const char*, T&) {}
  template <class X>
  void output(const char*, X& variable) {
    OracleVarying& varying = varyings_[next_++];
    std::size_t index = vertex_ * static_cast<std::size_t>(varying.components);
    forEachComponent(variable, [&](T& value) { store(varying, index++, value); });
  }

 private:
  static void store(OracleVarying& varying, std::size_t index, const T& value) {
    if constexpr (std::same_as<T, double>) {
      varying.reference[index] = value;
    } else if constexpr (std::same_as<T, float>) {
      varying.strict[index] = value;
    } else {
      varying.lo[index] = value.lo;
      varying.hi[index] = value.hi;
    }
    if (glsl::isUndefined(value)) varying.undefined[index] = 1;
  }

  std::vector<OracleVarying>& varyings_;
  std::size_t vertex_;
  std::size_t next_ = 0;
};

// Every output component of a run, in visit order.
template <glsl::Number T>
class CollectOutputs {
 public:
  template <class X>
  void input(const char*, X&) {}
  template <class X>
  void uniform(const char*, X&) {}
  void constant(const char*, T&) {}
  template <class X>
  void output(const char*, X& variable) {
    forEachComponent(variable, [&](T& value) { values.push_back(value); });
  }

  std::vector<T> values;
};

// Sets every output component from `values`, in visit order.
template <glsl::Number T>
class AssignOutputs {
 public:
  explicit AssignOutputs(const std::vector<T>& values) : values_(values) {}

  template <class X>
  void input(const char*, X&) {}
  template <class X>
  void uniform(const char*, X&) {}
  void constant(const char*, T&) {}
  template <class X>
  void output(const char*, X& variable) {
    forEachComponent(variable, [&](T& value) { value = values_[next_++]; });
  }

 private:
  const std::vector<T>& values_;
  std::size_t next_ = 0;
};

}  // namespace snell::listings
