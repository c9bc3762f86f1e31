#include "derived/program_builder.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <iterator>
#include <stdexcept>

namespace snell::derived {

Value Value::pick(const std::vector<int>& components, Shape result) const {
  Value picked{result, {}, refusal};
  if (!refusal.empty()) return picked;
  for (int k : components) picked.regs.push_back(regs.at(static_cast<std::size_t>(k)));
  return picked;
}

Value Value::column(int index) const {
  Value picked{Shape{shape.kind, shape.rows, 1}, {}, refusal};
  if (!refusal.empty()) return picked;
  for (int r = 0; r < shape.rows; ++r)
    picked.regs.push_back(regs.at(static_cast<std::size_t>(index * shape.rows + r)));
  return picked;
}

namespace {

// The first refusal among `args`, as the result's ("" when none).
std::string refusalOf(const std::vector<Value>& args) {
  for (const Value& arg : args)
    if (!arg.refusal.empty()) return arg.refusal;
  return {};
}

// Once per name: a variable read on both ways of an if is read twice.
void addBinding(std::vector<Binding>& bindings, Binding binding) {
  for (const Binding& known : bindings)
    if (known.name == binding.name) return;
  bindings.push_back(std::move(binding));
}

[[noreturn]] void refused(const Refuse& refuse, const std::string& what) {
  refuse(what);
  throw std::logic_error("Refuse returned: " + what);
}

}  // namespace

std::vector<Reg> ProgramBuilder::emit(OpCode code, std::vector<Reg> args, int results, int line,
                                      bool isBool, int width) {
  Op op;
  op.code = code;
  op.width = width;
  op.result = program_.registerCount;
  op.resultCount = results;
  op.isBool = isBool;
  op.line = line;
  op.perSample = code == OpCode::Input;
  for (Reg arg : args) op.perSample = op.perSample || perSample_.at(static_cast<std::size_t>(arg));
  op.args = std::move(args);
  std::vector<Reg> regs;
  for (int k = 0; k < results; ++k) {
    regs.push_back(program_.registerCount++);
    perSample_.push_back(op.perSample ? 1 : 0);
  }
  program_.ops.push_back(std::move(op));
  return regs;
}

Reg ProgramBuilder::literal(double value, bool isBool) {
  // By bit pattern: -0.0 and 0.0 are different literals.
  const std::pair key{std::bit_cast<std::uint64_t>(value), isBool};
  auto found = literals_.find(key);
  if (found != literals_.end()) return found->second;
  const Reg reg = emit(OpCode::Literal, {}, 1, 0, isBool)[0];
  program_.ops.back().literal = value;
  literals_.emplace(key, reg);
  return reg;
}

std::vector<Reg> ProgramBuilder::uniform(const std::string& name, int components, int line,
                                         int columns) {
  addBinding(program_.uniforms, Binding{name, components, line, columns});
  return reads(OpCode::Uniform, name, components, line);
}

std::vector<Reg> ProgramBuilder::input(const std::string& name, int components, int line) {
  addBinding(program_.inputs, Binding{name, components, line});
  return reads(OpCode::Input, name, components, line);
}

std::vector<Reg> ProgramBuilder::reads(OpCode code, const std::string& name, int components,
                                       int line) {
  std::vector<Reg> regs;
  for (int k = 0; k < components; ++k) {
    regs.push_back(emit1(code, {}, line));
    program_.ops.back().name = name;
    program_.ops.back().component = k;
  }
  return regs;
}

Value ProgramBuilder::componentwise(OpCode code, const std::vector<Value>& args, Shape result,
                                    int line) {
  Value value{result, {}, {}};
  for (int k = 0; k < result.size(); ++k) {
    std::vector<Reg> operands;
    for (const Value& arg : args)
      operands.push_back(arg.regs.size() == 1 ? arg.regs[0]
                                              : arg.regs.at(static_cast<std::size_t>(k)));
    value.regs.push_back(emit1(code, std::move(operands), line));
  }
  return value;
}

Reg ProgramBuilder::sumOfProducts(const std::vector<Reg>& a, const std::vector<Reg>& b, int line) {
  std::vector<Reg> args = a;
  args.insert(args.end(), b.begin(), b.end());
  return emit(OpCode::SumOfProducts, std::move(args), 1, line, false,
              static_cast<int>(a.size()))[0];
}

std::vector<Reg> ProgramBuilder::toFloat(const Value& value, int line) {
  if (value.shape.kind == Kind::Float) return value.regs;
  std::vector<Reg> regs;
  for (Reg reg : value.regs) regs.push_back(emit1(OpCode::BoolToFloat, {reg}, line));
  return regs;
}

Value ProgramBuilder::binary(glslang::TOperator op, const Value& left, const Value& right,
                             Shape result, int line, const Refuse& refuse) {
  using namespace glslang;
  if (std::string refusal = refusalOf({left, right}); !refusal.empty())
    return Value{result, {}, refusal};
  const auto floats = [&] {
    if (left.shape.kind != Kind::Float || right.shape.kind != Kind::Float)
      refused(refuse, "arithmetic on bool values");
  };
  switch (op) {
    case EOpAdd:
      floats();
      return componentwise(OpCode::Add, {left, right}, result, line);
    case EOpSub:
      floats();
      return componentwise(OpCode::Sub, {left, right}, result, line);
    case EOpMul:
    case EOpVectorTimesScalar:
    case EOpMatrixTimesScalar:
      floats();
      return componentwise(OpCode::Mul, {left, right}, result, line);
    case EOpDiv:
      floats();
      return componentwise(OpCode::Div, {left, right}, result, line);
    case EOpMatrixTimesVector: {
      // Row r: m[0][r] * v[0] + m[1][r] * v[1] + ..., dot()'s freedom of order.
      Value value{result, {}, {}};
      for (int r = 0; r < left.shape.rows; ++r) {
        std::vector<Reg> row;
        for (int c = 0; c < left.shape.columns; ++c)
          row.push_back(left.regs[static_cast<std::size_t>(c * left.shape.rows + r)]);
        value.regs.push_back(sumOfProducts(row, right.regs, line));
      }
      return value;
    }
    case EOpVectorTimesMatrix: {
      Value value{result, {}, {}};
      for (int c = 0; c < right.shape.columns; ++c)
        value.regs.push_back(sumOfProducts(left.regs, right.column(c).regs, line));
      return value;
    }
    case EOpMatrixTimesMatrix: {
      Value value{result, {}, {}};
      for (int c = 0; c < right.shape.columns; ++c) {
        for (int r = 0; r < left.shape.rows; ++r) {
          std::vector<Reg> row;
          for (int k = 0; k < left.shape.columns; ++k)
            row.push_back(left.regs[static_cast<std::size_t>(k * left.shape.rows + r)]);
          value.regs.push_back(sumOfProducts(row, right.column(c).regs, line));
        }
      }
      return value;
    }
    case EOpLessThan:
    case EOpGreaterThan:
    case EOpLessThanEqual:
    case EOpGreaterThanEqual: {
      floats();
      if (left.regs.size() != 1 || right.regs.size() != 1)
        refused(refuse, "a comparison of vectors");
      const bool swap = op == EOpGreaterThan || op == EOpGreaterThanEqual;
      const OpCode code =
          op == EOpLessThan || op == EOpGreaterThan ? OpCode::Less : OpCode::LessEqual;
      std::vector<Reg> args = swap ? std::vector{right.regs[0], left.regs[0]}
                                   : std::vector{left.regs[0], right.regs[0]};
      return Value{result, emit(code, std::move(args), 1, line, true), {}};
    }
    default:
      refused(refuse, "this operator");
  }
}

Value ProgramBuilder::unary(glslang::TOperator op, const Value& operand, Shape result, int line,
                            const Refuse& refuse, const std::string& called) {
  using namespace glslang;
  if (!operand.refusal.empty()) return Value{result, {}, operand.refusal};
  if (op == EOpConvBoolToFloat) return Value{result, toFloat(operand, line), {}};
  if (operand.shape.kind != Kind::Float) refused(refuse, "this operation on bool values");
  const int width = operand.shape.rows;
  switch (op) {
    case EOpNegative:
      return componentwise(OpCode::Neg, {operand}, result, line);
    case EOpNormalize:
      return Value{result, emit(OpCode::Normalize, operand.regs, width, line, false, width), {}};
    case EOpLength:
      return Value{result, emit(OpCode::Length, operand.regs, 1, line, false, width), {}};
    case EOpSqrt:
      return componentwise(OpCode::Sqrt, {operand}, result, line);
    case EOpInverseSqrt:
      return componentwise(OpCode::InverseSqrt, {operand}, result, line);
    case EOpExp:
      return componentwise(OpCode::Exp, {operand}, result, line);
    case EOpExp2:
      return componentwise(OpCode::Exp2, {operand}, result, line);
    case EOpLog2:
      return componentwise(OpCode::Log2, {operand}, result, line);
    case EOpAbs:
      return componentwise(OpCode::Abs, {operand}, result, line);
    default:
      return Value{
          result, {}, unsupported(called.empty() ? "this operation" : called + "()", line)};
  }
}

Value ProgramBuilder::construct(Shape result, const std::vector<Value>& args, int line,
                                const Refuse& refuse) {
  if (std::string refusal = refusalOf(args); !refusal.empty()) return Value{result, {}, refusal};
  if (result.kind != Kind::Float) refused(refuse, "a bool constructor");
  Value value{result, {}, {}};
  if (args.size() == 1 && args[0].regs.size() == 1) {
    const Reg scalar = toFloat(args[0], line)[0];
    if (result.columns == 1) {
      value.regs.assign(static_cast<std::size_t>(result.size()), scalar);
    } else {
      // mat(s): s on the diagonal, 0 elsewhere.
      const Reg zero = literal(0.0, false);
      for (int c = 0; c < result.columns; ++c)
        for (int r = 0; r < result.rows; ++r) value.regs.push_back(r == c ? scalar : zero);
    }
    return value;
  }
  if (args.size() == 1 && args[0].shape.columns > 1 && result.columns > 1) {
    // mat3(mat4) keeps the upper left; a larger matrix gets the identity's rest.
    const Value& m = args[0];
    for (int c = 0; c < result.columns; ++c)
      for (int r = 0; r < result.rows; ++r)
        value.regs.push_back(c < m.shape.columns && r < m.shape.rows
                                 ? m.regs[static_cast<std::size_t>(c * m.shape.rows + r)]
                                 : literal(r == c ? 1.0 : 0.0, false));
    return value;
  }
  for (const Value& arg : args) {
    const std::vector<Reg> regs = toFloat(arg, line);
    value.regs.insert(value.regs.end(), regs.begin(), regs.end());
  }
  if (static_cast<int>(value.regs.size()) < result.size())
    refused(refuse, "a constructor with too few components");
  value.regs.resize(static_cast<std::size_t>(result.size()));
  return value;
}

Value ProgramBuilder::builtin(glslang::TOperator op, const std::vector<Value>& args, Shape result,
                              int line, const Refuse& refuse, const std::string& called) {
  using namespace glslang;
  if (std::string refusal = refusalOf(args); !refusal.empty()) return Value{result, {}, refusal};
  for (const Value& arg : args)
    if (arg.shape.kind != Kind::Float) refused(refuse, "a built-in on bool values");
  const auto joined = [&](std::size_t count) {
    std::vector<Reg> regs;
    for (std::size_t k = 0; k < count; ++k)
      regs.insert(regs.end(), args[k].regs.begin(), args[k].regs.end());
    return regs;
  };
  const int width = args.empty() ? 1 : args[0].shape.rows;
  switch (op) {
    case EOpDot:
      return Value{result, emit(OpCode::Dot, joined(2), 1, line, false, width), {}};
    case EOpDistance: {
      const Value difference = componentwise(OpCode::Sub, {args[0], args[1]}, args[0].shape, line);
      return Value{result, emit(OpCode::Length, difference.regs, 1, line, false, width), {}};
    }
    case EOpReflect:
      return Value{result, emit(OpCode::Reflect, joined(2), width, line, false, width), {}};
    case EOpRefract:
      return Value{result, emit(OpCode::Refract, joined(3), width, line, false, width), {}};
    case EOpCross: {
      // GLSL 4.60 section 8.5's formula, each product and difference an
      // operation of its own: x.y * y.z - y.y * x.z, ...
      const std::vector<Reg>& x = args[0].regs;
      const std::vector<Reg>& y = args[1].regs;
      Value value{result, {}, {}};
      for (int k = 0; k < 3; ++k) {
        const auto a = static_cast<std::size_t>((k + 1) % 3),
                   b = static_cast<std::size_t>((k + 2) % 3);
        const Reg left = emit1(OpCode::Mul, {x[a], y[b]}, line);
        const Reg right = emit1(OpCode::Mul, {y[a], x[b]}, line);
        value.regs.push_back(emit1(OpCode::Sub, {left, right}, line));
      }
      return value;
    }
    case EOpMix:
      return componentwise(OpCode::Mix, args, result, line);
    case EOpPow:
      return componentwise(OpCode::Pow, args, result, line);
    case EOpMax:
      return componentwise(OpCode::Max, args, result, line);
    case EOpMin:
      return componentwise(OpCode::Min, args, result, line);
    case EOpClamp:
      return componentwise(OpCode::Clamp, args, result, line);
    default:
      return Value{
          result, {}, unsupported(called.empty() ? "this built-in function" : called + "()", line)};
  }
}

Value ProgramBuilder::lookup(const std::string& sampler, bool cube, const Value& coordinates,
                             int line) {
  if (!coordinates.refusal.empty()) return Value{Shape{Kind::Float, 4, 1}, {}, coordinates.refusal};
  std::vector<std::string>& samplers = cube ? program_.samplersCube : program_.samplers2D;
  if (std::find(samplers.begin(), samplers.end(), sampler) == samplers.end())
    samplers.push_back(sampler);
  const OpCode code = cube ? OpCode::TextureCube : OpCode::Texture2D;
  std::vector<Reg> args = coordinates.regs;
  args.resize(cube ? 3 : 2);
  Value value{Shape{Kind::Float, 4, 1}, emit(code, std::move(args), 4, line), {}};
  program_.ops.back().name = sampler;
  return value;
}

Value ProgramBuilder::inverse(const Value& matrix, int line) {
  if (!matrix.refusal.empty()) return matrix;
  const int width = matrix.shape.rows;
  return Value{
      matrix.shape, emit(OpCode::Inverse, matrix.regs, width * width, line, false, width), {}};
}

Value ProgramBuilder::select(const Value& condition, const Value& then, const Value& otherwise,
                             int line, const Refuse& refuse) {
  if (std::string refusal = refusalOf({condition, then, otherwise}); !refusal.empty())
    return Value{then.shape, {}, refusal};
  if (then.shape.kind != Kind::Float || otherwise.shape.kind != Kind::Float)
    refused(refuse, "a bool value chosen by a condition");
  Value value{then.shape, {}, {}};
  for (std::size_t k = 0; k < then.regs.size(); ++k) {
    const Reg a = then.regs[k];
    const Reg b = otherwise.regs[k];
    if (a == b || a == kUnassigned || b == kUnassigned) {
      // The same value both ways; or written on one way only, where the
      // other leaves it undefined: unassigned.
      value.regs.push_back(a == b ? a : kUnassigned);
      continue;
    }
    value.regs.push_back(emit1(OpCode::Select, {condition.regs[0], a, b}, line));
  }
  return value;
}

std::string ProgramBuilder::unsupported(const std::string& what, int line) const {
  return located(what + " is outside the derived oracle's subset", line);
}

std::string ProgramBuilder::located(const std::string& message, int line) const {
  std::size_t begin = 0;
  for (int k = 1; k < line && begin != std::string::npos; ++k) {
    begin = text_.find('\n', begin);
    if (begin != std::string::npos) ++begin;
  }
  std::string quoted;
  if (line > 0 && begin != std::string::npos) {
    const std::size_t end = text_.find('\n', begin);
    quoted = text_.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
    const std::size_t first = quoted.find_first_not_of(" \t\r");
    const std::size_t last = quoted.find_last_not_of(" \t\r");
    quoted = first == std::string::npos ? "" : quoted.substr(first, last - first + 1);
    // A generated line can be a hundred kilobytes: the start says which.
    constexpr std::size_t kQuotedMax = 160;
    if (quoted.size() > kQuotedMax) {
      quoted.resize(kQuotedMax);
      quoted += " ...";
    }
  }
  if (quoted.empty()) return fmt::format("{}:{}: {}", program_.file, line, message);
  return fmt::format("{}:{}: {}: `{}`", program_.file, line, message, quoted);
}

Program ProgramBuilder::finish(std::vector<Variable> outputs) {
  std::vector<std::uint8_t> live(static_cast<std::size_t>(program_.registerCount), 0);
  for (const Variable& output : outputs)
    for (Reg reg : output.components) live[static_cast<std::size_t>(reg)] = 1;
  std::vector<Op> kept;
  for (auto op = program_.ops.rbegin(); op != program_.ops.rend(); ++op) {
    bool needed = false;
    for (int k = 0; k < op->resultCount; ++k)
      needed = needed || live[static_cast<std::size_t>(op->result + k)];
    if (!needed) continue;
    for (Reg arg : op->args) live[static_cast<std::size_t>(arg)] = 1;
    kept.push_back(std::move(*op));
  }
  std::reverse(kept.begin(), kept.end());
  Program program = std::move(program_);
  program.ops = std::move(kept);
  const auto read = [&](const Binding& binding, OpCode code) {
    return std::any_of(program.ops.begin(), program.ops.end(),
                       [&](const Op& op) { return op.code == code && op.name == binding.name; });
  };
  std::erase_if(program.uniforms, [&](const Binding& b) { return !read(b, OpCode::Uniform); });
  std::erase_if(program.inputs, [&](const Binding& b) { return !read(b, OpCode::Input); });
  program.outputs = std::move(outputs);
  return program;
}

std::vector<std::string> outputNames(const Program& program) {
  std::vector<std::string> names;
  for (const Variable& output : program.outputs) names.push_back(output.name);
  return names;
}

std::vector<std::string> inputNames(const Program& program) {
  std::vector<std::string> names;
  for (const Binding& input : program.inputs) names.push_back(input.name);
  return names;
}

const char* opCodeName(OpCode code) {
  static constexpr const char* kNames[] = {
      "literal",   "uniform", "input",       "add",       "sub",         "mul",
      "div",       "neg",     "less",        "lessEqual", "boolToFloat", "sumOfProducts",
      "dot",       "length",  "normalize",   "reflect",   "refract",     "mix",
      "pow",       "sqrt",    "inversesqrt", "exp",       "exp2",        "log2",
      "max",       "min",     "abs",         "clamp",     "select",      "textureCube",
      "texture2D", "inverse"};
  static_assert(std::size(kNames) == static_cast<std::size_t>(OpCode::Inverse) + 1);
  return kNames[static_cast<int>(code)];
}

}  // namespace snell::derived
