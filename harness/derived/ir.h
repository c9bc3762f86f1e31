#pragma once
// The derived oracle's program: a shader's main() and the functions it
// calls (inlined), lowered from the listing's own text into a flat list of
// operations on scalar registers. Each register is written once. Vectors
// and matrices are lists of registers (matrices column-major, as GLSL
// stores them), so swizzles, constructors and component writes cost
// nothing at evaluation time; the vector built-ins (dot, normalize,
// reflect, refract, matrix * vector) stay whole operations, because their
// precision is that of the formula as a whole (oracle/glsl/geometric.h).
#include <cstdint>
#include <string>
#include <vector>

namespace snell::derived {

using Reg = std::int32_t;

enum class OpCode : std::uint8_t {
  Literal,  // `literal`, a decimal as the source prints it (bool: 0 or 1)
  Uniform,  // component `component` of uniform `name`
  Input,    // component `component` of per-sample input `name`
  Add,
  Sub,
  Mul,
  Div,
  Neg,
  Less,       // bool result
  LessEqual,  // bool result
  BoolToFloat,
  SumOfProducts,  // args a[0..width), b[0..width): one row of matrix * vector
  Dot,            // args x[0..width), y[0..width)
  Length,         // args x[0..width)
  Normalize,      // args x[0..width); `width` results
  Reflect,        // args I, N; `width` results
  Refract,        // args I, N, eta; `width` results
  Mix,            // x, y, a (scalar: vector mixes are lowered per component)
  Pow,
  Sqrt,
  InverseSqrt,
  Exp,
  Exp2,
  Log2,
  Max,
  Min,
  Abs,
  Clamp,
  // cond, then, otherwise: GLSL's if/else and ?: on a value both ways
  // compute; where the condition may go either way, the hull of both.
  Select,
  // The reference image's operations, evaluated in double only (the lowering
  // refuses them in a gated value, see lower_glsl.h):
  TextureCube,  // sampler `name`, direction args[0..3): 4 results
  Texture2D,    // sampler `name`, coordinates args[0..2): 4 results
  Inverse,      // a width x width matrix, column-major: width * width results
};

const char* opCodeName(OpCode code);

struct Op {
  OpCode code = OpCode::Literal;
  int width = 1;
  std::vector<Reg> args;
  Reg result = 0;  // results are result .. result + resultCount - 1
  int resultCount = 1;
  bool perSample = false;  // false: the same value for every sample (uniforms, literals)
  bool isBool = false;     // the results are bools (comparisons, bool literals)
  double literal = 0.0;
  std::string name;
  int component = 0;
  int line = 0;  // source line, for messages
};

// A named value the program computes: an output, or a local of main().
struct Variable {
  std::string name;
  std::vector<Reg> components;
};

// A uniform or per-sample input the program reads, with its component
// count and the line it is first read at.
struct Binding {
  std::string name;
  int components = 1;
  int line = 0;
  int columns = 1;  // a matrix's columns (components / columns rows)
};

struct Program;
// The names of a program's outputs and of the per-sample inputs it reads.
std::vector<std::string> outputNames(const Program& program);
std::vector<std::string> inputNames(const Program& program);

struct Program {
  std::string file;  // the source, for messages
  std::vector<Op> ops;
  int registerCount = 0;
  std::vector<Variable> outputs;
  std::vector<Binding> uniforms;
  std::vector<Binding> inputs;
  // The samplers the program's lookups read, by GLSL name.
  std::vector<std::string> samplersCube;
  std::vector<std::string> samplers2D;
};

}  // namespace snell::derived
