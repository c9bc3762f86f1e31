#pragma once
// Builds a Program (ir.h) one operation at a time from GLSL-shaped values:
// what the front end (lower_glsl.cpp) calls for each operator, constructor
// and built-in, with GLSL's rules for shapes (a scalar operand of a vector
// operation is applied to every component; matrices are column-major).
#include <glslang/Include/intermediate.h>

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "derived/ir.h"

namespace snell::derived {

enum class Kind { Float, Bool, Opaque };

struct Shape {
  Kind kind = Kind::Float;
  int rows = 1;     // a vector's size; a matrix's rows
  int columns = 1;  // 1 for scalars and vectors
  int size() const { return rows * columns; }
};

// A component not yet written (`vec3 v; v.x = 1.0;`).
inline constexpr Reg kUnassigned = -1;

// A GLSL value during lowering: its registers, or, for a value the oracle
// cannot follow (a texture lookup, a legacy built-in), the message that
// refuses any output that depends on it.
struct Value {
  Shape shape;
  std::vector<Reg> regs;
  std::string refusal;

  Value pick(const std::vector<int>& components, Shape result) const;
  Value column(int index) const;
};

// Called with what is unsupported; does not return (it throws).
using Refuse = std::function<void(const std::string& what)>;

class ProgramBuilder {
 public:
  // `text`: the source as written, quoted in messages.
  ProgramBuilder(std::string file, std::string text) : text_(std::move(text)) {
    program_.file = std::move(file);
  }

  Reg literal(double value, bool isBool);
  std::vector<Reg> uniform(const std::string& name, int components, int line, int columns = 1);
  std::vector<Reg> input(const std::string& name, int components, int line);

  Value binary(glslang::TOperator op, const Value& left, const Value& right, Shape result, int line,
               const Refuse& refuse);
  // `called`: the function's name as the source spells it, for the message
  // when it is outside the subset (empty where it is an operator).
  Value unary(glslang::TOperator op, const Value& operand, Shape result, int line,
              const Refuse& refuse, const std::string& called = {});
  Value construct(Shape result, const std::vector<Value>& args, int line, const Refuse& refuse);
  Value builtin(glslang::TOperator op, const std::vector<Value>& args, Shape result, int line,
                const Refuse& refuse, const std::string& called = {});

  // texture(sampler, coordinates) on a samplerCube (`cube`) or a sampler2D,
  // and inverse(m): double-only operations (ir.h) for the reference image.
  Value lookup(const std::string& sampler, bool cube, const Value& coordinates, int line);
  Value inverse(const Value& matrix, int line);

  // `condition ? then : otherwise`, component by component.
  Value select(const Value& condition, const Value& then, const Value& otherwise, int line,
               const Refuse& refuse);

  // The program that computes `outputs`, without the operations none of
  // them needs.
  Program finish(std::vector<Variable> outputs);

  // "FILE:LINE: <what> is outside the derived oracle's subset: `<the line>`".
  std::string unsupported(const std::string& what, int line) const;
  // "FILE:LINE: <message>: `<the line>`".
  std::string located(const std::string& message, int line) const;

 private:
  std::vector<Reg> emit(OpCode code, std::vector<Reg> args, int results, int line,
                        bool isBool = false, int width = 1);
  Reg emit1(OpCode code, std::vector<Reg> args, int line) {
    return emit(code, std::move(args), 1, line)[0];
  }
  // One Uniform or Input operation per component.
  std::vector<Reg> reads(OpCode code, const std::string& name, int components, int line);
  // `code` applied component by component, a scalar operand to every one.
  Value componentwise(OpCode code, const std::vector<Value>& args, Shape result, int line);
  Reg sumOfProducts(const std::vector<Reg>& a, const std::vector<Reg>& b, int line);
  std::vector<Reg> toFloat(const Value& value, int line);

  std::string text_;
  Program program_;
  std::vector<std::uint8_t> perSample_;  // by register
  std::map<std::pair<std::uint64_t, bool>, Reg> literals_;
};

}  // namespace snell::derived
