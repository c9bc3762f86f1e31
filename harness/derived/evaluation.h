#pragma once
// The derived program's evaluator (evaluate.h) as a template over the
// number type. evaluate.cpp instantiates it for double, float and Interval;
// the tests run it on the adversarial machine's number type too, so that
// the machine makes its choices along a derived program's own operations.
// Internal to the derived oracle and its tests.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <map>
#include <span>
#include <stdexcept>
#include <vector>

#include "core/values.h"
#include "derived/evaluate.h"
#include "derived/ir.h"
#include "oracle/branch_paths.h"
#include "oracle/glsl/glsl.h"
#include "oracle/glsl/texture.h"
#include "oracle/interval.h"
#include "oracle/interval_builtins.h"
#include "oracle/reference/fragment_oracle.h"

namespace snell::derived::detail {

// The scalar built-ins by the same name for every number type: glsl's for
// double and float, interval_builtins.h's for Interval.
struct Builtins {
  template <class T>
  static T sqrt(const T& x) {
    using glsl::sqrt, snell::sqrt;
    return sqrt(x);
  }
  template <class T>
  static T inversesqrt(const T& x) {
    using glsl::inversesqrt, snell::inversesqrt;
    return inversesqrt(x);
  }
  template <class T>
  static T exp(const T& x) {
    using glsl::exp, snell::exp;
    return exp(x);
  }
  template <class T>
  static T exp2(const T& x) {
    using glsl::exp2, snell::exp2;
    return exp2(x);
  }
  template <class T>
  static T log2(const T& x) {
    using glsl::log2, snell::log2;
    return log2(x);
  }
  template <class T>
  static T pow(const T& x, const T& y) {
    using glsl::pow, snell::pow;
    return pow(x, y);
  }
  template <class T>
  static T max(const T& a, const T& b) {
    using glsl::max, snell::max;
    return max(a, b);
  }
  template <class T>
  static T min(const T& a, const T& b) {
    using glsl::min, snell::min;
    return min(a, b);
  }
  // clamp(x, minVal, maxVal) is min(max(x, minVal), maxVal), and undefined
  // where minVal > maxVal (GLSL 4.60 section 8.3): where some allowed
  // evaluation of the bounds crosses them, any result is allowed.
  template <class T>
  static T clamp(const T& x, const T& minVal, const T& maxVal) {
    if constexpr (std::same_as<T, Interval>)
      if ((maxVal < minVal) != Truth::False) return Interval::unconstrained();
    return min(max(x, minVal), maxVal);
  }
  template <class T>
  static T abs(const T& x) {
    using glsl::abs, snell::abs;
    return abs(x);
  }
  template <class T>
  static T sumOfProducts(std::span<const T> a, std::span<const T> b) {
    if constexpr (std::same_as<T, Interval>) {
      return snell::sumOfProducts(a, b);
    } else {
      // By argument-dependent lookup: a number type of its own (the tests'
      // adversarial machine) brings its own open sum of products.
      using glsl::sumOfProducts;
      return sumOfProducts(a, b);
    }
  }
  template <class T>
  static Truth less(const T& a, const T& b) {
    if constexpr (std::same_as<T, Interval>) {
      return a < b;
    } else {
      return a < b ? Truth::True : Truth::False;
    }
  }
};

inline Truth negate(Truth t) {
  return t == Truth::Unknown ? t : (t == Truth::True ? Truth::False : Truth::True);
}

template <class T>
class Evaluation {
 public:
  Evaluation(const Program& program, const UniformMap& uniforms, const AttributeMap& inputs,
             std::size_t sampleCount)
      : program_(program),
        uniforms_(uniforms),
        inputs_(inputs),
        sampleCount_(sampleCount),
        numbers_(static_cast<std::size_t>(program.registerCount)),
        truths_(static_cast<std::size_t>(program.registerCount)) {}

  std::vector<std::vector<T>> run() {
    for (const Op& op : program_.ops) execute(op);
    std::vector<std::vector<T>> outputs;
    for (const Variable& output : program_.outputs) {
      const std::size_t components = output.components.size();
      std::vector<T> values(sampleCount_ * components);
      for (std::size_t c = 0; c < components; ++c)
        for (std::size_t s = 0; s < sampleCount_; ++s)
          values[s * components + c] = number(output.components[c], s);
      outputs.push_back(std::move(values));
    }
    return outputs;
  }

 private:
  std::size_t samplesOf(const Op& op) const { return op.perSample ? sampleCount_ : 1; }
  const T& number(Reg reg, std::size_t sample) const {
    const std::vector<T>& values = numbers_[static_cast<std::size_t>(reg)];
    return values[values.size() == 1 ? 0 : sample];
  }
  Truth truth(Reg reg, std::size_t sample) const {
    const std::vector<Truth>& values = truths_[static_cast<std::size_t>(reg)];
    return values[values.size() == 1 ? 0 : sample];
  }
  const T& arg(const Op& op, int k, std::size_t sample) const {
    return number(op.args[static_cast<std::size_t>(k)], sample);
  }

  // One result per sample from `f(sample)`.
  template <class F>
  void each(const Op& op, F f) {
    std::vector<T>& out = numbers_[static_cast<std::size_t>(op.result)];
    const std::size_t n = samplesOf(op);
    out.resize(n);
    for (std::size_t s = 0; s < n; ++s) out[s] = f(s);
  }

  template <class F>
  void eachTruth(const Op& op, F f) {
    std::vector<Truth>& out = truths_[static_cast<std::size_t>(op.result)];
    const std::size_t n = samplesOf(op);
    out.resize(n);
    for (std::size_t s = 0; s < n; ++s) out[s] = f(s);
  }

  template <int N>
  glsl::vec<T, N> vector(const Op& op, int first, std::size_t sample) const {
    glsl::vec<T, N> v;
    for (int k = 0; k < N; ++k) v[k] = arg(op, first + k, sample);
    return v;
  }

  // A vector result per sample from `f(sample)`, into op's result registers.
  template <int N, class F>
  void eachVector(const Op& op, F f) {
    const std::size_t n = samplesOf(op);
    for (int k = 0; k < N; ++k) numbers_[static_cast<std::size_t>(op.result + k)].resize(n);
    for (std::size_t s = 0; s < n; ++s) {
      const glsl::vec<T, N> v = f(s);
      for (int k = 0; k < N; ++k) numbers_[static_cast<std::size_t>(op.result + k)][s] = v[k];
    }
  }

  template <int N>
  void vectorOp(const Op& op) {
    switch (op.code) {
      case OpCode::Dot:
        each(op,
             [&](std::size_t s) { return glsl::dot(vector<N>(op, 0, s), vector<N>(op, N, s)); });
        break;
      case OpCode::Length:
        each(op, [&](std::size_t s) { return glsl::length(vector<N>(op, 0, s)); });
        break;
      case OpCode::Normalize:
        eachVector<N>(op, [&](std::size_t s) { return glsl::normalize(vector<N>(op, 0, s)); });
        break;
      case OpCode::Reflect:
        eachVector<N>(op, [&](std::size_t s) {
          return glsl::reflect(vector<N>(op, 0, s), vector<N>(op, N, s));
        });
        break;
      case OpCode::Refract:
        eachVector<N>(op, [&](std::size_t s) {
          const glsl::vec<T, N> I = vector<N>(op, 0, s);
          const glsl::vec<T, N> normal = vector<N>(op, N, s);
          const T& eta = arg(op, 2 * N, s);
          if constexpr (std::same_as<T, Interval>) {
            // refract()'s own `k < 0.0` (oracle/glsl/geometric.h), to know
            // the samples where it may go either way.
            const T k = glsl::refractK(eta, glsl::dot(normal, I));
            if (undecided_ && (k < glsl::lit<T>(0.0)) == Truth::Unknown) markUndecided(op, s);
          }
          return glsl::refract(I, normal, eta);
        });
        break;
      case OpCode::SumOfProducts:
        each(op, [&](std::size_t s) {
          std::array<T, N> a, b;
          for (int k = 0; k < N; ++k) {
            a[k] = arg(op, k, s);
            b[k] = arg(op, N + k, s);
          }
          return Builtins::sumOfProducts<T>(a, b);
        });
        break;
      default:
        break;
    }
  }

  void execute(const Op& op) {
    using B = Builtins;
    switch (op.code) {
      case OpCode::Literal:
        if (op.isBool) {
          eachTruth(op,
                    [&](std::size_t) { return op.literal != 0.0 ? Truth::True : Truth::False; });
        } else {
          each(op, [&](std::size_t) { return glsl::lit<T>(op.literal); });
        }
        break;
      case OpCode::Uniform: {
        const float value = uniforms_.at(op.name).data[static_cast<std::size_t>(op.component)];
        each(op, [&](std::size_t) { return glsl::fromFloat<T>(value); });
        break;
      }
      case OpCode::Input: {
        const AttributeStream& stream = inputs_.at(op.name);
        const auto stride = static_cast<std::size_t>(stream.components);
        const auto component = static_cast<std::size_t>(op.component);
        each(op, [&](std::size_t s) {
          return glsl::fromFloat<T>(stream.data[s * stride + component]);
        });
        break;
      }
      case OpCode::Add:
        each(op, [&](std::size_t s) { return arg(op, 0, s) + arg(op, 1, s); });
        break;
      case OpCode::Sub:
        each(op, [&](std::size_t s) { return arg(op, 0, s) - arg(op, 1, s); });
        break;
      case OpCode::Mul:
        each(op, [&](std::size_t s) { return arg(op, 0, s) * arg(op, 1, s); });
        break;
      case OpCode::Div:
        each(op, [&](std::size_t s) { return arg(op, 0, s) / arg(op, 1, s); });
        break;
      case OpCode::Neg:
        each(op, [&](std::size_t s) { return -arg(op, 0, s); });
        break;
      case OpCode::Less:
        eachTruth(op, [&](std::size_t s) { return B::less(arg(op, 0, s), arg(op, 1, s)); });
        break;
      case OpCode::LessEqual:
        eachTruth(op, [&](std::size_t s) { return negate(B::less(arg(op, 1, s), arg(op, 0, s))); });
        break;
      case OpCode::BoolToFloat:
        each(op, [&](std::size_t s) {
          return select(op, s, op.args[0], glsl::lit<T>(1.0), glsl::lit<T>(0.0));
        });
        break;
      case OpCode::Mix:
        each(op,
             [&](std::size_t s) { return glsl::mix(arg(op, 0, s), arg(op, 1, s), arg(op, 2, s)); });
        break;
      case OpCode::Pow:
        each(op, [&](std::size_t s) { return B::pow(arg(op, 0, s), arg(op, 1, s)); });
        break;
      case OpCode::Sqrt:
        each(op, [&](std::size_t s) { return B::sqrt(arg(op, 0, s)); });
        break;
      case OpCode::InverseSqrt:
        each(op, [&](std::size_t s) { return B::inversesqrt(arg(op, 0, s)); });
        break;
      case OpCode::Exp:
        each(op, [&](std::size_t s) { return B::exp(arg(op, 0, s)); });
        break;
      case OpCode::Exp2:
        each(op, [&](std::size_t s) { return B::exp2(arg(op, 0, s)); });
        break;
      case OpCode::Log2:
        each(op, [&](std::size_t s) { return B::log2(arg(op, 0, s)); });
        break;
      case OpCode::Max:
        each(op, [&](std::size_t s) { return B::max(arg(op, 0, s), arg(op, 1, s)); });
        break;
      case OpCode::Min:
        each(op, [&](std::size_t s) { return B::min(arg(op, 0, s), arg(op, 1, s)); });
        break;
      case OpCode::Abs:
        each(op, [&](std::size_t s) { return B::abs(arg(op, 0, s)); });
        break;
      case OpCode::Clamp:
        each(op,
             [&](std::size_t s) { return B::clamp(arg(op, 0, s), arg(op, 1, s), arg(op, 2, s)); });
        break;
      case OpCode::Select:
        each(op, [&](std::size_t s) {
          return select(op, s, op.args[0], arg(op, 1, s), arg(op, 2, s));
        });
        break;
      case OpCode::TextureCube:
      case OpCode::Texture2D:
      case OpCode::Inverse:
        if constexpr (std::same_as<T, double>) {
          referenceOnlyOp(op);
        } else {
          throw std::logic_error(fmt::format("{}:{}: {} reached a gated evaluation", program_.file,
                                             op.line, opCodeName(op.code)));
        }
        break;
      case OpCode::SumOfProducts:
      case OpCode::Dot:
      case OpCode::Length:
      case OpCode::Normalize:
      case OpCode::Reflect:
      case OpCode::Refract:
        switch (op.width) {
          case 1:
            vectorOp<1>(op);
            break;
          case 2:
            vectorOp<2>(op);
            break;
          case 3:
            vectorOp<3>(op);
            break;
          default:
            vectorOp<4>(op);
            break;
        }
        break;
    }
  }

  // The reference image's lookups and inverse(), in double (the gates
  // never evaluate them, see lower_glsl.h).
  void referenceOnlyOp(const Op& op) {
    if (op.code == OpCode::Inverse) {
      const auto n = static_cast<std::size_t>(op.width);
      const std::size_t samples = samplesOf(op);
      for (std::size_t k = 0; k < n * n; ++k)
        numbers_[static_cast<std::size_t>(op.result) + k].resize(samples);
      std::vector<double> m(n * n);
      for (std::size_t s = 0; s < samples; ++s) {
        for (std::size_t k = 0; k < n * n; ++k) m[k] = arg(op, static_cast<int>(k), s);
        const std::vector<double> inverse = inverted(m, n);
        for (std::size_t k = 0; k < n * n; ++k)
          numbers_[static_cast<std::size_t>(op.result) + k][s] = inverse[k];
      }
      return;
    }
    if (!textures_)
      throw std::logic_error(
          fmt::format("{}:{}: a lookup with no textures bound", program_.file, op.line));
    const bool cube = op.code == OpCode::TextureCube;
    glsl::samplerCube cubeSampler;
    glsl::sampler2D sampler2D;
    if (cube) {
      cubeSampler.map = textures_->cubeMaps.at(op.name);
    } else {
      sampler2D.image = textures_->textures2D.at(op.name);
    }
    eachVector<4>(op, [&](std::size_t s) {
      if (cube) {
        cubeSampler.undefinedLookup = cubeSampler.faceEdgeLookup = false;
        const glsl::vec4<double> color = glsl::texture(cubeSampler, vector<3>(op, 0, s));
        noteLookup(op, s, cubeSampler.undefinedLookup, cubeSampler.faceEdgeLookup);
        return color;
      }
      sampler2D.undefinedLookup = false;
      const glsl::vec4<double> color = glsl::texture(sampler2D, vector<2>(op, 0, s));
      noteLookup(op, s, sampler2D.undefinedLookup, false);
      return color;
    });
  }

  void noteLookup(const Op& op, std::size_t sample, bool undefined, bool faceEdge) {
    if (!findings_) return;
    const std::size_t first = op.perSample ? sample : 0;
    const std::size_t last = op.perSample ? sample + 1 : sampleCount_;
    for (std::size_t s = first; s < last; ++s) {
      findings_->undefined[s] = findings_->undefined[s] || undefined;
      findings_->faceEdge[s] = findings_->faceEdge[s] || faceEdge;
    }
  }

  // Gauss-Jordan elimination with partial pivoting of a column-major n x n
  // matrix; a singular one gives NaN (GLSL leaves its inverse undefined).
  static std::vector<double> inverted(std::vector<double> m, std::size_t n) {
    const auto at = [n](std::vector<double>& a, std::size_t row, std::size_t column) -> double& {
      return a[column * n + row];
    };
    std::vector<double> inverse(n * n, 0.0);
    for (std::size_t k = 0; k < n; ++k) at(inverse, k, k) = 1.0;
    for (std::size_t column = 0; column < n; ++column) {
      std::size_t pivot = column;
      for (std::size_t row = column + 1; row < n; ++row)
        if (std::abs(at(m, row, column)) > std::abs(at(m, pivot, column))) pivot = row;
      const double p = at(m, pivot, column);
      if (p == 0.0 || !std::isfinite(p)) return std::vector<double>(n * n, glsl::lit<double>(NAN));
      for (std::size_t c = 0; c < n; ++c) {
        std::swap(at(m, column, c), at(m, pivot, c));
        std::swap(at(inverse, column, c), at(inverse, pivot, c));
      }
      for (std::size_t c = 0; c < n; ++c) {
        at(m, column, c) /= p;
        at(inverse, column, c) /= p;
      }
      for (std::size_t row = 0; row < n; ++row) {
        if (row == column) continue;
        const double factor = at(m, row, column);
        for (std::size_t c = 0; c < n; ++c) {
          at(m, row, c) -= factor * at(m, column, c);
          at(inverse, row, c) -= factor * at(inverse, column, c);
        }
      }
    }
    return inverse;
  }

  // GLSL's `condition ? then : otherwise` (and float(bool), 1.0 or 0.0).
  // Over the batch an undecided condition gives the hull of both. While a
  // sample's ways are explored (oracle/branch_paths.h), each condition is
  // one choice, made where it is first used (however many components it
  // selects), and recorded; a double replay takes the recorded outcome at
  // the same place.
  T select(const Op& op, std::size_t sample, Reg condition, const T& then, const T& otherwise) {
    if constexpr (std::same_as<T, Interval>) {
      const Truth t = chosen(condition, sample);
      if (t == Truth::Unknown) {
        if (undecided_) markUndecided(op, sample);
        return hull(then, otherwise);
      }
      return t == Truth::True ? then : otherwise;
    } else {
      return chosen(condition, sample) == Truth::True ? then : otherwise;
    }
  }

  Truth chosen(Reg condition, std::size_t sample) {
    Truth t = truth(condition, sample);
    BranchPaths* paths = activeBranchPaths();
    BranchReplay* replay = activeBranchReplay();
    if (!paths && !replay) return t;
    auto known = choices_.find(condition);
    if (known != choices_.end()) return known->second;
    if (replay) {
      t = replay->next() ? Truth::True : Truth::False;
    } else if (t == Truth::Unknown) {
      const BranchPaths::Choice choice = paths->chooseUnknown();
      if (choice != BranchPaths::Choice::Hull) {
        t = choice == BranchPaths::Choice::Then ? Truth::True : Truth::False;
        paths->record(t == Truth::True);
      }
    } else {
      paths->record(t == Truth::True);
    }
    choices_.emplace(condition, t);
    return t;
  }

  void markUndecided(const Op& op, std::size_t sample) {
    if (op.perSample) {
      (*undecided_)[sample] = 1;
    } else {
      std::fill(undecided_->begin(), undecided_->end(), 1);
    }
  }

  const Program& program_;
  const UniformMap& uniforms_;
  const AttributeMap& inputs_;
  std::size_t sampleCount_;
  std::vector<std::vector<T>> numbers_;
  std::vector<std::vector<Truth>> truths_;
  std::map<Reg, Truth> choices_;  // while exploring or replaying one sample

 public:
  // Set by the caller: a flag per sample, raised where a branch may go
  // either way.
  std::vector<std::uint8_t>* undecided_ = nullptr;
  // The reference image's textures and what its lookups ran into.
  const FragmentBindings* textures_ = nullptr;
  LookupFindings* findings_ = nullptr;
};

}  // namespace snell::derived::detail
