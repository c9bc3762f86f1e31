#include "derived/lower_glsl.h"

#include <fmt/format.h>
#include <glslang/Include/intermediate.h>
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <optional>
#include <regex>
#include <set>

#include "core/errors.h"
#include "core/legacy_builtins.h"
#include "derived/literal_names.h"
#include "derived/program_builder.h"

namespace snell::derived {
namespace {

using ::TIntermNode;
using glslang::TIntermAggregate;
using glslang::TIntermBinary;
using glslang::TIntermSymbol;
using glslang::TIntermTyped;
using glslang::TIntermUnary;

// glslang keeps process-wide tables; they live until the process exits.
void ensureGlslangInitialised() {
  struct Process {
    Process() { glslang::InitializeProcess(); }
    ~Process() { glslang::FinalizeProcess(); }
  };
  static Process process;
}

// `const` blanked to spaces (see the header): the token only, not names
// that contain it.
std::string withoutConstQualifiers(const std::string& text) {
  static const std::regex kConst(R"(\bconst\b)");
  return std::regex_replace(text, kConst, "     ");
}

constexpr const char* kAdvice =
    "give the listing a hand-written oracle (manifest `oracle`), or rewrite it without that "
    "construct, or capture the values it needs before that line";

// A variable's storage in the lowering environment: a symbol by its
// glslang id, or one member of an interface block (gl_Position in
// gl_PerVertex) by block id and member.
using Key = long long;
Key symbolKey(const TIntermSymbol& symbol) { return static_cast<Key>(symbol.getId()); }
Key memberKey(const TIntermSymbol& block, int member) {
  return (static_cast<Key>(block.getId() + 1) << 8) + member + (Key{1} << 60);
}

class Lowering {
 public:
  // `parsedText`: the text glslang parsed, whose columns its locations give.
  Lowering(const ShaderSource& source, const std::string& parsedText, TIntermNode* root,
           LowerOptions options, const std::map<std::string, double>& literals)
      : source_(source),
        parsedText_(parsedText),
        builder_(source.file, source.text),
        options_(options),
        literals_(literals) {
    collectFunctions(root);
  }

  Program run(const std::vector<OutputRequest>& requested) {
    requests_ = requested;
    TIntermAggregate* root = nullptr;
    for (auto& [name, function] : functions_)
      if (name == "main(") root = function;
    if (!root) throw UsageError(fmt::format("{}: the shader has no main()", source_.file));
    for (TIntermNode* global : globals_) statement(global);
    inMain_ = true;
    functionBody(*root, /*allowReturnValue=*/false);
    std::vector<Variable> outputs;
    std::vector<std::string> names;
    for (const OutputRequest& request : requested)
      if (std::find(fed_.begin(), fed_.end(), request.name) == fed_.end())
        names.push_back(request.name);
    if (requested.empty()) names = writtenOutputs_;
    for (const std::string& name : names) outputs.push_back(output(name));
    return builder_.finish(std::move(outputs));
  }

  // Keeps the value of each output requested after a line as main() goes
  // past that line: from a statement on that line or before it to one on a
  // later line. In an unrolled loop that happens on every iteration, and
  // the last one's value is kept, as the probe writing the capture on
  // every iteration leaves it.
  void snapshotBefore(int line) {
    if (!inMain_ || !callStack_.empty() || line <= 0) return;
    const int previous = lastLine_;
    lastLine_ = line;
    for (const OutputRequest& request : requests_) {
      if (request.afterLine <= 0 || request.afterLine >= line || request.afterLine < previous)
        continue;
      const auto key = names_.find(request.name);
      if (key == names_.end()) continue;
      const auto value = variables_.find(key->second);
      if (value == variables_.end()) continue;
      if (!value->second.refusal.empty() && source_.stage == Stage::Fragment) {
        if (loops_ > 0)
          throw UsageError(
              builder_.unsupported(fmt::format("a capture of {} after line {}, inside a loop, that "
                                               "the oracle cannot compute",
                                               request.name, request.afterLine),
                                   request.afterLine) +
              "; the value read back is the last iteration's, and each iteration "
              "would need its own; capture it after the loop");
        // A fragment capture the oracle cannot compute (it reads
        // gl_FragCoord, or a ray march's result) is read back and fed in
        // from here on, as the hand-written oracles take such values.
        auto fed = fedValues_.find(request.name);
        if (fed == fedValues_.end()) {
          Value input{value->second.shape, {}, {}};
          input.regs = builder_.input(request.name, input.shape.size(), request.afterLine);
          fed = fedValues_.emplace(request.name, input).first;
          fed_.push_back(request.name);
        }
        value->second = fed->second;
        continue;
      }
      snapshots_[request.name] = value->second;
    }
  }

 private:
  static constexpr int kMaxNesting = 1000;
  struct NestingGuard {
    explicit NestingGuard(int& depth) : depth_(depth) { ++depth_; }
    ~NestingGuard() { --depth_; }
    NestingGuard(const NestingGuard&) = delete;
    NestingGuard& operator=(const NestingGuard&) = delete;
    int& depth_;
  };
  int nesting_ = 0;

  // While a ?: operand is lowered: the call depth of the ?: itself. GLSL
  // evaluates the chosen operand only (GLSL 4.60 section 5.8), so an
  // assignment or an out argument in an operand, at that depth, happens on
  // one way only; the lowering evaluates both, and is refused there. Inside
  // a function the operand calls, the callee's own variables are its own.
  struct SelectionGuard {
    SelectionGuard(std::vector<std::size_t>& depths, std::size_t depth) : depths_(depths) {
      depths_.push_back(depth);
    }
    ~SelectionGuard() { depths_.pop_back(); }
    SelectionGuard(const SelectionGuard&) = delete;
    SelectionGuard& operator=(const SelectionGuard&) = delete;
    std::vector<std::size_t>& depths_;
  };
  std::vector<std::size_t> selectionDepths_;

  void refuseInsideSelection(const TIntermNode& node, const std::string& what) const {
    if (!selectionDepths_.empty() && selectionDepths_.back() == callStack_.size())
      refuse(node, fmt::format("{} inside ?: (only the chosen operand is evaluated, so it "
                               "happens on one way only: write an if/else)",
                               what));
  }

  [[noreturn]] void refuse(const TIntermNode& node, const std::string& what) const {
    throw UsageError(builder_.unsupported(what, node.getLoc().line) + "; " + kAdvice);
  }

  void collectFunctions(TIntermNode* root) {
    TIntermAggregate* sequence = root ? root->getAsAggregate() : nullptr;
    if (!sequence) return;
    for (TIntermNode* child : sequence->getSequence()) {
      TIntermAggregate* aggregate = child->getAsAggregate();
      if (aggregate && aggregate->getOp() == glslang::EOpFunction) {
        functions_[aggregate->getName().c_str()] = aggregate;
      } else if (aggregate && aggregate->getOp() == glslang::EOpLinkerObjects) {
        continue;
      } else {
        globals_.push_back(child);
      }
    }
  }

  // --- statements -----------------------------------------------------

  void statement(TIntermNode* node) {
    if (!node) return;
    if (TIntermAggregate* aggregate = node->getAsAggregate()) {
      if (aggregate->getOp() == glslang::EOpSequence) {
        for (TIntermNode* child : aggregate->getSequence()) statement(child);
        return;
      }
    }
    snapshotBefore(node->getLoc().line);
    if (glslang::TIntermLoop* loop = node->getAsLoopNode()) {
      unrolled(*loop);
      return;
    }
    if (glslang::TIntermSelection* selection = node->getAsSelectionNode()) {
      ifElse(*selection);
      return;
    }
    if (node->getAsSwitchNode()) refuse(*node, "a switch");
    if (const glslang::TIntermBranch* branch = node->getAsBranchNode()) {
      switch (branch->getFlowOp()) {
        case glslang::EOpReturn:
          refuse(*node, "a return before the end of a function");
        case glslang::EOpKill:
          refuse(*node, "discard");
        default:
          refuse(*node, "break/continue");
      }
    }
    // A declaration without initializer is a bare symbol: nothing to do.
    if (node->getAsSymbolNode()) return;
    if (TIntermTyped* typed = node->getAsTyped()) {
      if (isInt(*typed)) {
        intStatement(*typed);
      } else {
        expression(*typed);
      }
      return;
    }
    refuse(*node, "this statement");
  }

  // --- loops and the ints that count them ------------------------------
  // A for loop whose counter is known when the shader is compiled (GLSL ES
  // 1.00 appendix A's form, which every catalog loop has) is unrolled:
  // its ints are compile-time values, never oracle values.

  static bool isInt(const TIntermTyped& node) {
    const glslang::TBasicType type = node.getBasicType();
    return (type == glslang::EbtInt || type == glslang::EbtUint) && node.getType().isScalar();
  }

  static constexpr int kMaxIterations = 1024;

  void unrolled(glslang::TIntermLoop& loop) {
    if (!loop.getTerminal() || !loop.testFirst() || !loop.getTest())
      refuse(loop, loop.testFirst() ? "a while loop" : "a do-while loop");
    for (int iteration = 0;; ++iteration) {
      if (!compileTimeBool(*loop.getTest())) return;
      if (iteration == kMaxIterations)
        refuse(loop, fmt::format("a loop of more than {} iterations", kMaxIterations));
      const NestingGuard inLoop(loops_);
      statement(loop.getBody());
      intStatement(*loop.getTerminal());
    }
  }

  // An int assignment, ++ or --: updates the compile-time value.
  void intStatement(TIntermTyped& node) {
    using namespace glslang;
    if (TIntermUnary* unary = node.getAsUnaryNode()) {
      const TOperator op = unary->getOp();
      const int step = op == EOpPostIncrement || op == EOpPreIncrement   ? 1
                       : op == EOpPostDecrement || op == EOpPreDecrement ? -1
                                                                         : 0;
      if (step != 0) {
        long long& variable = ints_[intVariable(*unary->getOperand())];
        variable = wrapped(static_cast<unsigned long long>(variable + step), unary->getType());
        return;
      }
    }
    if (TIntermBinary* binary = node.getAsBinaryNode()) {
      const TOperator op = binary->getOp();
      if (op == EOpAssign || op == EOpAddAssign || op == EOpSubAssign) {
        const auto value = static_cast<unsigned long long>(compileTimeInt(*binary->getRight()));
        long long& variable = ints_[intVariable(*binary->getLeft())];
        const auto before = static_cast<unsigned long long>(variable);
        variable = wrapped(op == EOpAssign      ? value
                           : op == EOpAddAssign ? before + value
                                                : before - value,
                           binary->getLeft()->getType());
        return;
      }
    }
    refuse(node, "this int statement");
  }

  Key intVariable(TIntermTyped& node) const {
    TIntermSymbol* symbol = node.getAsSymbolNode();
    if (!symbol) refuse(node, "an int l-value that is not a variable");
    return symbolKey(*symbol);
  }

  // An int or uint result as GLSL has it: the low-order 32 bits of the
  // exact value ("overflow ... will result in the low-order 32 bits",
  // GLSL 4.60 section 5.9), signed or not by the node's type.
  static long long wrapped(unsigned long long exact, const glslang::TType& type) {
    const auto low = static_cast<std::uint32_t>(exact);
    if (type.getBasicType() == glslang::EbtUint) return static_cast<long long>(low);
    return static_cast<long long>(static_cast<std::int32_t>(low));
  }

  long long compileTimeInt(TIntermTyped& node) const {
    using namespace glslang;
    if (glslang::TIntermConstantUnion* constant = node.getAsConstantUnion()) {
      const TConstUnion& value = constant->getConstArray()[0];
      return node.getType().getBasicType() == EbtUint ? static_cast<long long>(value.getUConst())
                                                      : value.getIConst();
    }
    if (TIntermSymbol* symbol = node.getAsSymbolNode()) {
      auto found = ints_.find(symbolKey(*symbol));
      if (found == ints_.end())
        refuse(node, fmt::format("the int {}, whose value is not known when the shader is compiled",
                                 symbol->getName().c_str()));
      return found->second;
    }
    if (TIntermBinary* binary = node.getAsBinaryNode()) {
      // In unsigned 64-bit arithmetic, which wraps, then to 32 bits.
      const auto a = static_cast<unsigned long long>(compileTimeInt(*binary->getLeft()));
      const auto b = static_cast<unsigned long long>(compileTimeInt(*binary->getRight()));
      switch (binary->getOp()) {
        case EOpAdd:
          return wrapped(a + b, node.getType());
        case EOpSub:
          return wrapped(a - b, node.getType());
        case EOpMul:
          return wrapped(a * b, node.getType());
        default:
          break;
      }
    }
    refuse(node, "this int expression");
  }

  bool compileTimeBool(TIntermTyped& node) const {
    using namespace glslang;
    TIntermBinary* binary = node.getAsBinaryNode();
    if (!binary || !isInt(*binary->getLeft()) || !isInt(*binary->getRight()))
      refuse(node, "a loop condition that is not a comparison of ints");
    const long long a = compileTimeInt(*binary->getLeft());
    const long long b = compileTimeInt(*binary->getRight());
    switch (binary->getOp()) {
      case EOpLessThan:
        return a < b;
      case EOpLessThanEqual:
        return a <= b;
      case EOpGreaterThan:
        return a > b;
      case EOpGreaterThanEqual:
        return a >= b;
      case EOpEqual:
        return a == b;
      case EOpNotEqual:
        return a != b;
      default:
        refuse(node, "this loop condition");
    }
  }

  // Both ways are lowered from the same state; each variable either way
  // changed becomes a choice between its two values (ProgramBuilder::select).
  // The line of a block's first statement.
  static int firstLine(TIntermNode& block) {
    TIntermAggregate* sequence = block.getAsAggregate();
    if (sequence && sequence->getOp() == glslang::EOpSequence && !sequence->getSequence().empty())
      return firstLine(*sequence->getSequence().front());
    return block.getLoc().line;
  }

  void ifElse(glslang::TIntermSelection& node) {
    const Value condition = this->condition(*node.getCondition());
    const std::map<Key, Value> before = variables_;
    const std::map<Key, long long> intsBefore = ints_;
    std::map<Key, Value> afterThen, afterElse;
    statement(node.getTrueBlock());
    // A capture on the then way's last line is taken with the then way's
    // values, before they are set aside for the else way: its first
    // statement is where main goes past that line.
    if (node.getFalseBlock()) snapshotBefore(firstLine(*node.getFalseBlock()));
    afterThen = std::move(variables_);
    variables_ = before;
    statement(node.getFalseBlock());
    afterElse = std::move(variables_);
    variables_ = before;
    if (ints_ != intsBefore) refuse(node, "an int assigned under a condition");
    const auto same = [](const Value& a, const Value& b) {
      return a.regs == b.regs && a.refusal == b.refusal;
    };
    for (const auto& [key, value] : afterElse)
      if (!afterThen.count(key)) assignedOneWayOnly_[key] = node.getLoc().line;
    for (const auto& [key, then] : afterThen) {
      auto otherwise = afterElse.find(key);
      // Declared inside one way only (a block's local), or written one way
      // only where it was unset before: not a value after the if.
      if (otherwise == afterElse.end()) {
        assignedOneWayOnly_[key] = node.getLoc().line;
        continue;
      }
      variables_[key] = same(then, otherwise->second)
                            ? then
                            : builder_.select(condition, then, otherwise->second,
                                              node.getLoc().line, refuser(node));
    }
  }

  Value condition(TIntermTyped& node) {
    const Value value = expression(node);
    if (value.refusal.empty() && (value.shape.kind != Kind::Bool || value.regs.size() != 1))
      refuse(node, "a condition that is not one bool");
    return value;
  }

  Refuse refuser(const TIntermNode& node) const {
    return [this, &node](const std::string& what) { refuse(node, what); };
  }

  // Lowers a function's body; returns the value of its final `return`.
  Value functionBody(TIntermAggregate& function, bool allowReturnValue) {
    const glslang::TIntermSequence& parts = function.getSequence();
    if (parts.size() < 2 || !parts[1]) return Value{};
    TIntermAggregate* body = parts[1]->getAsAggregate();
    if (!body) {
      statement(parts[1]);
      return Value{};
    }
    const glslang::TIntermSequence& statements = body->getSequence();
    for (std::size_t k = 0; k < statements.size(); ++k) {
      const glslang::TIntermBranch* branch = statements[k]->getAsBranchNode();
      if (branch && branch->getFlowOp() == glslang::EOpReturn && k + 1 == statements.size()) {
        if (!branch->getExpression()) return Value{};
        if (!allowReturnValue) refuse(*branch, "a return value from main()");
        return expression(*branch->getExpression());
      }
      statement(statements[k]);
    }
    return Value{};
  }

  // --- expressions ----------------------------------------------------

  Value expression(TIntermTyped& node) {
    const int line = node.getLoc().line;
    // Lowering recurses once per level of nesting: a generated expression
    // thousands of operators long would overflow the stack. No listing
    // nests anywhere near this deep.
    const NestingGuard nested(nesting_);
    if (nesting_ > kMaxNesting)
      refuse(node, fmt::format("an expression nested more than {} deep", kMaxNesting));
    if (glslang::TIntermConstantUnion* constant = node.getAsConstantUnion())
      return constantValue(*constant);
    if (TIntermSymbol* symbol = node.getAsSymbolNode()) return read(*symbol);
    if (TIntermBinary* binary = node.getAsBinaryNode()) return binaryExpression(*binary, line);
    if (TIntermUnary* unary = node.getAsUnaryNode()) return unaryExpression(*unary, line);
    if (TIntermAggregate* aggregate = node.getAsAggregate())
      return aggregateExpression(*aggregate, line);
    if (glslang::TIntermSelection* selection = node.getAsSelectionNode()) {
      TIntermTyped* then = selection->getTrueBlock()->getAsTyped();
      TIntermTyped* otherwise = selection->getFalseBlock()->getAsTyped();
      if (!then || !otherwise) refuse(node, "this ?: expression");
      const Value chosen = condition(*selection->getCondition());
      const SelectionGuard operands(selectionDepths_, callStack_.size());
      const Value whenTrue = expression(*then);
      const Value whenFalse = expression(*otherwise);
      return builder_.select(chosen, whenTrue, whenFalse, line, refuser(node));
    }
    refuse(node, "this expression");
  }

  Shape shapeOf(const TIntermTyped& node) const {
    const glslang::TType& type = node.getType();
    if (type.isArray()) refuse(node, "an array");
    Shape shape;
    switch (type.getBasicType()) {
      case glslang::EbtFloat:
        shape.kind = Kind::Float;
        break;
      case glslang::EbtBool:
        shape.kind = Kind::Bool;
        break;
      case glslang::EbtInt:
      case glslang::EbtUint:
        refuse(node, "an int value");
      case glslang::EbtDouble:
        refuse(node, "a double value");
      case glslang::EbtSampler:
        shape.kind = Kind::Opaque;
        return shape;
      default:
        refuse(node, fmt::format("a value of type {}", type.getBasicTypeString().c_str()));
    }
    if (type.isMatrix()) {
      shape.columns = type.getMatrixCols();
      shape.rows = type.getMatrixRows();
    } else {
      shape.rows = type.getVectorSize();
    }
    return shape;
  }

  Value constantValue(const glslang::TIntermConstantUnion& node) {
    const Shape shape = shapeOf(node);
    const glslang::TConstUnionArray& data = node.getConstArray();
    Value value{shape, {}, {}};
    for (int k = 0; k < shape.size(); ++k) {
      const double number =
          shape.kind == Kind::Bool ? (data[k].getBConst() ? 1.0 : 0.0) : data[k].getDConst();
      value.regs.push_back(builder_.literal(number, shape.kind == Kind::Bool));
    }
    return value;
  }

  // An int constant used as an index or a swizzle selector.
  int constantIndex(TIntermTyped& node) const {
    glslang::TIntermConstantUnion* constant = node.getAsConstantUnion();
    if (!constant) refuse(node, "an index that is not a constant");
    return constant->getConstArray()[0].getIConst();
  }

  Value read(TIntermSymbol& symbol) {
    const Key key = symbolKey(symbol);
    const std::string name = symbol.getName().c_str();
    if (const auto literal = literals_.find(name); literal != literals_.end())
      return Value{Shape{}, {builder_.literal(literal->second, false)}, {}};
    noteName(name, key, isPipelineOutput(symbol));
    auto found = variables_.find(key);
    if (found != variables_.end()) return checkedRead(found->second, symbol);
    const int line = symbol.getLoc().line;
    if (name.rfind("gl_", 0) == 0) {
      const Value value =
          builtinVariable(name, symbol.getType().isArray() ? Shape{} : shapeOf(symbol), line);
      variables_[key] = value;
      return value;
    }
    const Shape shape = shapeOf(symbol);
    const glslang::TStorageQualifier storage = symbol.getQualifier().storage;
    Value value{shape, {}, {}};
    if (shape.kind == Kind::Opaque) {
      value.refusal =
          builder_.unsupported(fmt::format("the sampler {} outside texture()", name), line);
    } else if (storage == glslang::EvqUniform && shape.kind == Kind::Bool) {
      value.refusal = builder_.unsupported(
          fmt::format("the bool uniform {} (snell sets float, vec2-4, mat3 and mat4 uniforms only)",
                      name),
          line);
    } else if (storage == glslang::EvqUniform) {
      value.regs = builder_.uniform(name, shape.size(), line, shape.columns);
    } else if (storage == glslang::EvqVaryingIn) {
      value.regs = builder_.input(name, shape.size(), line);
    } else {
      refuse(symbol, fmt::format("reading {} before it is assigned", name));
    }
    variables_[key] = value;
    return value;
  }

  // Legacy fixed-function state (gl_ModelViewMatrix, gl_TextureMatrix[1],
  // gl_Vertex), by the names of the state table (core/legacy_builtins.h)
  // that manifests bind; any other built-in (gl_FragCoord, ...) is refused
  // where a requested value needs it.
  Value builtinVariable(const std::string& name, Shape shape, int line) {
    Value value{shape, {}, {}};
    const std::optional<LegacyBuiltin> legacy = findLegacyBuiltin(name);
    if (!legacy) {
      value.refusal = builder_.unsupported("the built-in " + name, line);
    } else if (legacy->kind == LegacyBuiltinKind::Attribute) {
      value.regs = builder_.input(name, shape.size(), line);
    } else {
      value.regs = builder_.uniform(name, shape.size(), line, shape.columns);
    }
    return value;
  }

  Value checkedRead(const Value& value, const TIntermTyped& node) const {
    // A component written from a value the oracle cannot follow taints the
    // whole variable: the refusal goes on, not a missing component.
    if (!value.refusal.empty()) return value;
    if (std::find(value.regs.begin(), value.regs.end(), kUnassigned) != value.regs.end())
      refuse(node, "reading a component before it is assigned");
    return value;
  }

  // Outputs are requested by name. A pipeline output keeps its name: a
  // local or a struct member of the same name declared later does not
  // take it over.
  void noteName(const std::string& name, Key key, bool pipelineOutput) {
    if (!(inMain_ || !inFunction_)) return;
    if (pipelineOutput) {
      outputKeys_.insert(key);
    } else if (const auto bound = names_.find(name);
               bound != names_.end() && outputKeys_.count(bound->second)) {
      return;
    }
    names_[name] = key;
  }

  static bool isPipelineOutput(const TIntermSymbol& symbol) {
    const glslang::TStorageQualifier storage = symbol.getQualifier().storage;
    return storage == glslang::EvqVaryingOut || storage == glslang::EvqPosition ||
           storage == glslang::EvqFragColor;
  }
  // A member of an interface block (gl_PerVertex's gl_Position), not of a
  // struct of the shader's own.
  static bool isBlockMember(TIntermBinary& node) {
    const TIntermTyped* base = node.getLeft();
    return base && base->getType().getBasicType() == glslang::EbtBlock;
  }

  Value binaryExpression(TIntermBinary& node, int line) {
    using namespace glslang;
    const TOperator op = node.getOp();
    switch (op) {
      case EOpAssign:
      case EOpAddAssign:
      case EOpSubAssign:
      case EOpMulAssign:
      case EOpDivAssign:
      case EOpVectorTimesScalarAssign:
      case EOpMatrixTimesScalarAssign:
        return assignment(node, line);
      case EOpVectorSwizzle: {
        const Value base = expression(*node.getLeft());
        std::vector<int> picks;
        for (TIntermNode* selector : node.getRight()->getAsAggregate()->getSequence())
          picks.push_back(constantIndex(*selector->getAsTyped()));
        return base.pick(picks, shapeOf(node));
      }
      case EOpIndexDirect: {
        TIntermSymbol* array = node.getLeft()->getAsSymbolNode();
        if (array && array->getType().isArray()) {
          // gl_TextureMatrix[1]: one entry of the state table.
          const std::string name =
              fmt::format("{}[{}]", array->getName().c_str(), constantIndex(*node.getRight()));
          if (name.rfind("gl_", 0) != 0) refuse(node, "an array");
          return builtinVariable(name, shapeOf(node), line);
        }
        const Value base = expression(*node.getLeft());
        const int index = constantIndex(*node.getRight());
        if (base.shape.columns > 1) return base.column(index);
        return base.pick({index}, shapeOf(node));
      }
      case EOpIndexDirectStruct: {
        const auto [key, name] = member(node);
        noteName(name, key, isBlockMember(node));
        auto found = variables_.find(key);
        if (found == variables_.end() && node.getLeft()->getQualifier().storage == EvqUniform) {
          // A block's members (`uniform Params { float eta; };`, named or
          // not) are not a struct's; an anonymous block's name is glslang's.
          const std::string holder = node.getLeft()->getAsSymbolNode()->getName().c_str();
          const bool block = node.getLeft()->getType().getBasicType() == EbtBlock;
          const std::string where =
              block ? fmt::format("the uniform block member {}",
                                  holder.rfind("anon@", 0) == 0 ? name : holder + "." + name)
                    : fmt::format("the uniform struct member {}.{}", holder, name);
          refuse(node, fmt::format("{} (snell sets uniforms of float, vec2-4, mat3 and mat4 "
                                   "types, not members of a {}: declare {} as a uniform of its "
                                   "own)",
                                   where, block ? "block" : "struct", name));
        }
        if (found == variables_.end())
          refuse(node, fmt::format("reading {} before it is assigned", name));
        return checkedRead(found->second, node);
      }
      case EOpIndexIndirect:
        refuse(node, "an index that is not a constant");
      default:
        break;
    }
    const Value left = expression(*node.getLeft());
    const Value right = expression(*node.getRight());
    return builder_.binary(op, left, right, shapeOf(node), line,
                           [&](const std::string& what) { refuse(node, what); });
  }

  // gl_Position and the other members of an interface block, by name.
  std::pair<Key, std::string> member(TIntermBinary& node) const {
    TIntermSymbol* block = node.getLeft()->getAsSymbolNode();
    if (!block) refuse(node, "a struct member");
    const int index = constantIndex(*node.getRight());
    const glslang::TTypeList& fields = *block->getType().getStruct();
    return {memberKey(*block, index), fields[index].type->getFieldName().c_str()};
  }

  Value assignment(TIntermBinary& node, int line) {
    using namespace glslang;
    refuseInsideSelection(node, "an assignment");
    Value value = expression(*node.getRight());
    if (node.getOp() != EOpAssign) {
      const Value current = expression(*node.getLeft());
      TOperator op = EOpNull;
      switch (node.getOp()) {
        case EOpAddAssign:
          op = EOpAdd;
          break;
        case EOpSubAssign:
          op = EOpSub;
          break;
        case EOpDivAssign:
          op = EOpDiv;
          break;
        default:
          op = EOpMul;
          break;
      }
      if (node.getOp() == EOpMulAssign && (current.shape.columns > 1 || value.shape.columns > 1))
        refuse(node, "a matrix *= ");
      value = builder_.binary(op, current, value, shapeOf(*node.getLeft()), line,
                              [&](const std::string& what) { refuse(node, what); });
    }
    store(*node.getLeft(), value);
    return value;
  }

  // Writes `value` into the l-value `target` (a variable, a swizzle or a
  // component or column of one).
  void store(TIntermTyped& target, const Value& value) {
    std::vector<int> positions;
    TIntermTyped* base = &target;
    while (true) {
      TIntermBinary* binary = base->getAsBinaryNode();
      if (!binary) break;
      if (binary->getOp() == glslang::EOpIndexDirectStruct) break;
      std::vector<int> picks;
      const Shape baseShape = shapeOf(*binary->getLeft());
      if (binary->getOp() == glslang::EOpVectorSwizzle) {
        for (TIntermNode* selector : binary->getRight()->getAsAggregate()->getSequence())
          picks.push_back(constantIndex(*selector->getAsTyped()));
      } else if (binary->getOp() == glslang::EOpIndexDirect) {
        const int index = constantIndex(*binary->getRight());
        if (baseShape.columns > 1) {
          for (int r = 0; r < baseShape.rows; ++r) picks.push_back(index * baseShape.rows + r);
        } else {
          picks.push_back(index);
        }
      } else {
        refuse(target, "this assignment target");
      }
      if (positions.empty()) {
        positions = picks;
      } else {
        for (int& p : positions) p = picks[static_cast<std::size_t>(p)];
      }
      base = binary->getLeft();
    }
    Key key = 0;
    std::string name;
    bool pipelineOutput = false;
    if (TIntermSymbol* symbol = base->getAsSymbolNode()) {
      key = symbolKey(*symbol);
      name = symbol->getName().c_str();
      pipelineOutput = isPipelineOutput(*symbol);
    } else if (TIntermBinary* binary = base->getAsBinaryNode()) {
      std::tie(key, name) = member(*binary);
      pipelineOutput = isBlockMember(*binary);
    } else {
      refuse(target, "this assignment target");
    }
    if (pipelineOutput) noteOutput(name);
    noteName(name, key, pipelineOutput);
    auto found = variables_.find(key);
    if (found == variables_.end()) {
      const Shape shape = shapeOf(*base);
      found = variables_.emplace(key, Value{shape, std::vector<Reg>(shape.size(), kUnassigned), {}})
                  .first;
    }
    Value& variable = found->second;
    if (positions.empty()) {
      variable = value;
      variable.shape = shapeOf(*base);
      return;
    }
    if (!value.refusal.empty()) variable.refusal = value.refusal;
    for (std::size_t k = 0; k < positions.size(); ++k)
      variable.regs[static_cast<std::size_t>(positions[k])] =
          value.regs.empty() ? kUnassigned : value.regs[k];
  }

  void noteOutput(const std::string& name) {
    if (std::find(writtenOutputs_.begin(), writtenOutputs_.end(), name) == writtenOutputs_.end())
      writtenOutputs_.push_back(name);
  }

  Value unaryExpression(TIntermUnary& node, int line) {
    if (node.getOp() == glslang::EOpConvIntToFloat || node.getOp() == glslang::EOpConvUintToFloat)
      return Value{
          shapeOf(node),
          {builder_.literal(static_cast<double>(compileTimeInt(*node.getOperand())), false)},
          {}};
    const Value operand = expression(*node.getOperand());
    if (node.getOp() == glslang::EOpTranspose) return transposed(operand, shapeOf(node));
    if (node.getOp() == glslang::EOpMatrixInverse) {
      if (options_.doubleOnly) return builder_.inverse(operand, line);
      Value value{shapeOf(node), {}, {}};
      value.refusal = builder_.located(
          "inverse() has no precision in GLSL 4.60 section 4.7.1, so no interval bounds a value "
          "computed with it",
          line);
      return value;
    }
    return builder_.unary(
        node.getOp(), operand, shapeOf(node), line,
        [&](const std::string& what) { refuse(node, what); }, calledName(node));
  }

  // transpose(m): the same registers in the other order; exact.
  static Value transposed(const Value& matrix, Shape result) {
    Value value{result, {}, matrix.refusal};
    if (!matrix.refusal.empty()) return value;
    for (int c = 0; c < result.columns; ++c)
      for (int r = 0; r < result.rows; ++r)
        value.regs.push_back(matrix.regs[static_cast<std::size_t>(r * matrix.shape.rows + c)]);
    return value;
  }

  // texture(sampler, P) in the reference image's program: a uniform
  // samplerCube or sampler2D and its coordinates, nothing else.
  Value followedLookup(TIntermAggregate& node, int line) {
    const glslang::TIntermSequence& args = node.getSequence();
    TIntermSymbol* sampler = args.empty() ? nullptr : args[0]->getAsSymbolNode();
    if (node.getOp() != glslang::EOpTexture || args.size() != 2 || !sampler)
      refuse(node, "this texture function (texture(sampler, P) is followed)");
    const glslang::TSampler& type = sampler->getType().getSampler();
    const bool cube = type.dim == glslang::EsdCube;
    if ((!cube && type.dim != glslang::Esd2D) || type.isArrayed() || type.isShadow())
      refuse(node, "a lookup in a sampler other than samplerCube or sampler2D");
    const Value coordinates = expression(*args[1]->getAsTyped());
    return builder_.lookup(sampler->getName().c_str(), cube, coordinates, line);
  }

  Value aggregateExpression(TIntermAggregate& node, int line) {
    if (node.getOp() == glslang::EOpFunctionCall) return call(node);
    const auto refuseHere = [&](const std::string& what) { refuse(node, what); };
    std::vector<Value> args;
    const bool lookup = node.isTexture() || node.isSampling() || node.isImage();
    if (lookup && options_.doubleOnly) return followedLookup(node, line);
    for (TIntermNode* child : node.getSequence()) {
      TIntermTyped* typed = child->getAsTyped();
      if (!typed) refuse(node, "this call");
      if (lookup) {
        // The arguments of a lookup still count: an unsupported one is named.
        if (typed->getBasicType() != glslang::EbtSampler) expression(*typed);
        continue;
      }
      args.push_back(expression(*typed));
    }
    if (lookup) {
      Value value{shapeOf(node), {}, {}};
      value.refusal = builder_.unsupported(
          "a texture lookup (the derived oracle follows values up to a lookup, not through it)",
          line);
      value.shape.kind = Kind::Float;
      return value;
    }
    if (node.getOp() == glslang::EOpFtransform) {
      // gl_ModelViewProjectionMatrix * gl_Vertex, as the hand-written
      // oracles take it (GLSL 1.20 section 8.5 asks only for the
      // fixed-function transform's result, which is that product).
      const Value matrix =
          builtinVariable("gl_ModelViewProjectionMatrix", Shape{Kind::Float, 4, 4}, line);
      const Value vertex = builtinVariable("gl_Vertex", Shape{Kind::Float, 4, 1}, line);
      return builder_.binary(glslang::EOpMatrixTimesVector, matrix, vertex, shapeOf(node), line,
                             refuseHere);
    }
    if (node.isConstructor()) return builder_.construct(shapeOf(node), args, line, refuseHere);
    return builder_.builtin(node.getOp(), args, shapeOf(node), line, refuseHere, calledName(node));
  }

  // The name of the function a call node calls, read from the source at
  // the node's location (glslang keeps no name for a built-in's call): the
  // location is the call's closing parenthesis, or inside its argument
  // list (a one-argument call takes its argument's). Empty where the text
  // there is not such a call.
  std::string calledName(const TIntermNode& node) const {
    const glslang::TSourceLoc& loc = node.getLoc();
    std::size_t start = 0;
    for (int line = 1; line < loc.line; ++line) {
      start = parsedText_.find('\n', start);
      if (start == std::string::npos) return {};
      ++start;
    }
    const std::size_t end = std::min(parsedText_.find('\n', start), parsedText_.size());
    const std::string text = parsedText_.substr(start, end - start);
    if (loc.column <= 0 || static_cast<std::size_t>(loc.column) > text.size()) return {};
    // Leftwards to the unmatched '(' that opens the argument list.
    const std::size_t at = static_cast<std::size_t>(loc.column - 1);
    std::size_t open = text[at] == ')' ? at : at + 1;
    int depth = text[at] == ')' ? 1 : 0;
    while (open > 0) {
      const char c = text[--open];
      if (c == ')') ++depth;
      if (c == '(' && depth-- == 0) break;
      if (c == '(' && depth == 0 && text[at] == ')') break;
    }
    if (text[open] != '(') return {};
    // A one-argument call's location is its argument's: only where that is
    // the first thing in the parentheses is the call known to be this node
    // (`vec3(x++)` is not a call of vec3 by the ++).
    if (text[at] != ')' && text.find_first_not_of(" \t", open + 1) != at) return {};
    const auto identifierByte = [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    };
    std::size_t last = open;
    while (last > 0 && text[last - 1] == ' ') --last;
    std::size_t first = last;
    while (first > 0 && identifierByte(text[first - 1])) --first;
    return first < last ? text.substr(first, last - first) : std::string{};
  }

  // `f(` of glslang's mangled `f(f1;`.
  static std::string functionName(const TIntermAggregate& function) {
    const std::string mangled = function.getName().c_str();
    return mangled.substr(0, mangled.find('(') + 1);
  }

  // The first return statement of `function` that is not its body's last
  // statement, or null.
  static const TIntermNode* earlyReturn(TIntermAggregate& function) {
    struct Finder : glslang::TIntermTraverser {
      const TIntermNode* last = nullptr;
      const TIntermNode* found = nullptr;
      bool visitBranch(glslang::TVisit, glslang::TIntermBranch* branch) override {
        if (branch->getFlowOp() == glslang::EOpReturn && branch != last && !found) found = branch;
        return true;
      }
    } finder;
    const glslang::TIntermSequence& parts = function.getSequence();
    if (parts.size() < 2 || !parts[1]) return nullptr;
    if (TIntermAggregate* body = parts[1]->getAsAggregate(); body && !body->getSequence().empty())
      finder.last = body->getSequence().back();
    parts[1]->traverse(&finder);
    return finder.found;
  }

  // A user function, inlined: its `in` and `inout` parameters bound to the
  // arguments; its `out` and `inout` parameters copied out to the
  // arguments when it returns (GLSL 4.60 section 6.1.1).
  Value call(TIntermAggregate& node) {
    auto found = functions_.find(node.getName().c_str());
    if (found == functions_.end())
      refuse(node, fmt::format("a call of {} (no definition)", node.getName().c_str()));
    TIntermAggregate& function = *found->second;
    if (std::find(callStack_.begin(), callStack_.end(), &function) != callStack_.end())
      refuse(node, "recursion");
    const glslang::TIntermSequence& parameters =
        function.getSequence()[0]->getAsAggregate()->getSequence();
    const glslang::TIntermSequence& arguments = node.getSequence();
    const auto storageOf = [&](std::size_t k) {
      return parameters[k]->getAsSymbolNode()->getQualifier().storage;
    };
    const auto writesBack = [&](std::size_t k) {
      return storageOf(k) == glslang::EvqOut || storageOf(k) == glslang::EvqInOut;
    };
    for (std::size_t k = 0; k < parameters.size(); ++k)
      if (writesBack(k))
        refuseInsideSelection(
            node, fmt::format("a call of {}) with an out parameter", functionName(function)));
    // An out argument's value on the way in is not the callee's to read.
    std::vector<Value> args(arguments.size());
    for (std::size_t k = 0; k < arguments.size(); ++k)
      if (storageOf(k) != glslang::EvqOut) args[k] = expression(*arguments[k]->getAsTyped());
    // A return before the end (a ray march's `if (hit) return t;` in a
    // loop) is outside the subset; the call's value is refused, so a
    // fragment capture computed from it can still be read back and fed in.
    if (const TIntermNode* early = earlyReturn(function)) {
      const std::string refusal = builder_.unsupported(
          fmt::format("a return before the end of {})", functionName(function)),
          early->getLoc().line);
      // Its out and inout arguments are as unknown as its value.
      for (std::size_t k = 0; k < parameters.size(); ++k) {
        if (!writesBack(k)) continue;
        Value unknown{shapeOf(*arguments[k]->getAsTyped()), {}, {}};
        unknown.refusal = refusal;
        store(*arguments[k]->getAsTyped(), unknown);
      }
      Value refused{
          node.getType().getBasicType() == glslang::EbtVoid ? Shape{} : shapeOf(node), {}, {}};
      refused.refusal = refusal;
      return refused;
    }
    for (std::size_t k = 0; k < parameters.size(); ++k) {
      const Key key = symbolKey(*parameters[k]->getAsSymbolNode());
      if (storageOf(k) == glslang::EvqOut)
        variables_.erase(key);  // unset on entry, whatever an earlier call left
      else
        variables_[key] = args[k];
    }
    callStack_.push_back(&function);
    const bool wasInMain = inMain_;
    const bool wasInFunction = inFunction_;
    inMain_ = false;
    inFunction_ = true;
    Value result = functionBody(function, /*allowReturnValue=*/true);
    inMain_ = wasInMain;
    inFunction_ = wasInFunction;
    callStack_.pop_back();
    for (std::size_t k = 0; k < parameters.size(); ++k) {
      if (!writesBack(k)) continue;
      TIntermSymbol& parameter = *parameters[k]->getAsSymbolNode();
      const auto value = variables_.find(symbolKey(parameter));
      if (value != variables_.end()) {
        store(*arguments[k]->getAsTyped(), value->second);
        continue;
      }
      Value unset{shapeOf(parameter), {}, {}};
      unset.refusal = builder_.located(
          fmt::format("{0}) may leave its out parameter {1} unset, so the argument has no value "
                      "after the call; assign {1} on every way through {0})",
                      functionName(function), parameter.getName().c_str()),
          node.getLoc().line);
      store(*arguments[k]->getAsTyped(), unset);
    }
    return result;
  }

  Variable output(const std::string& name) {
    auto key = names_.find(name);
    if (key == names_.end())
      throw UsageError(fmt::format(
          "{}: the derived oracle was asked for '{}', which the shader's main() does not "
          "compute; name an output or a local of main()",
          source_.file, name));
    const auto snapshot = snapshots_.find(name);
    const auto variable = variables_.find(key->second);
    if (snapshot == snapshots_.end() && variable == variables_.end()) {
      const auto oneWay = assignedOneWayOnly_.find(key->second);
      throw UsageError(
          oneWay != assignedOneWayOnly_.end()
              ? fmt::format("{}:{}: '{}' is assigned on one way of this if only, so main() "
                            "leaves it unset on the other; give it a value on both ways (an "
                            "else, or before the if)",
                            source_.file, oneWay->second, name)
              : fmt::format("{}: '{}' is never assigned by main()", source_.file, name));
    }
    const Value& value = snapshot != snapshots_.end() ? snapshot->second : variable->second;
    if (!value.refusal.empty())
      throw UsageError(fmt::format("{} (needed for '{}'); {}", value.refusal, name, kAdvice));
    if (std::find(value.regs.begin(), value.regs.end(), kUnassigned) != value.regs.end())
      throw UsageError(
          fmt::format("{}: '{}' is not completely assigned by main()", source_.file, name));
    return Variable{name, value.regs};
  }

  const ShaderSource& source_;
  const std::string& parsedText_;
  ProgramBuilder builder_;
  LowerOptions options_;
  const std::map<std::string, double>& literals_;  // withLiteralsNamed's uniforms
  std::vector<OutputRequest> requests_;
  std::map<std::string, Value> snapshots_;
  std::vector<std::string> fed_;  // requests read back and fed in, not computed
  std::map<std::string, Value> fedValues_;
  int lastLine_ = 0;  // of the statement snapshotBefore saw last
  int loops_ = 0;     // loop bodies being lowered
  std::map<std::string, TIntermAggregate*> functions_;
  std::vector<TIntermNode*> globals_;
  std::map<Key, Value> variables_;
  // Variables an if left unset on one of its ways, and the if's line.
  std::map<Key, int> assignedOneWayOnly_;
  std::map<Key, long long> ints_;  // the compile-time ints (loop counters, their bounds)
  std::map<std::string, Key> names_;
  std::set<Key> outputKeys_;  // names_'s pipeline outputs
  std::vector<std::string> writtenOutputs_;
  std::vector<TIntermAggregate*> callStack_;
  bool inMain_ = false;
  bool inFunction_ = false;
};

}  // namespace

bool testsVulkanMacro(const std::string& text) {
  for (std::size_t at = text.find("VULKAN"); at != std::string::npos;
       at = text.find("VULKAN", at + 1)) {
    const auto identifierByte = [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    };
    const bool startsWord = at == 0 || !identifierByte(text[at - 1]);
    const bool endsWord = at + 6 == text.size() || !identifierByte(text[at + 6]);
    if (startsWord && endsWord) return true;
  }
  return false;
}

Program lowerShader(const ShaderSource& source, const std::vector<std::string>& outputs,
                    LowerOptions options) {
  std::vector<OutputRequest> requests;
  for (const std::string& name : outputs) requests.push_back({name, 0});
  return lowerOutputs(source, requests, options);
}

namespace {

// glslang's parse of `text`; its log where it does not compile.
struct Parsed {
  std::unique_ptr<glslang::TShader> shader;
  std::string log;
};
Parsed parse(const ShaderSource& source, const std::string& text, LowerOptions options) {
  const EShLanguage stage = source.stage == Stage::Vertex ? EShLangVertex : EShLangFragment;
  Parsed parsed{std::make_unique<glslang::TShader>(stage), {}};
  const char* strings = text.c_str();
  const int length = static_cast<int>(text.size());
  const char* name = source.file.c_str();
  parsed.shader->setStringsWithLengthsAndNames(&strings, &length, &name, 1);
  if (options.vulkanMacros) parsed.shader->setPreamble("#define VULKAN 100\n");
  if (!parsed.shader->parse(GetDefaultResources(), 110, false, EShMsgDefault)) {
    parsed.log = parsed.shader->getInfoLog();
    parsed.log.erase(parsed.log.find_last_not_of(" \t\r\n") + 1);
    if (parsed.log.empty()) parsed.log = "(glslang gave no reason)";
  }
  return parsed;
}

}  // namespace

Program lowerOutputs(const ShaderSource& source, const std::vector<OutputRequest>& outputs,
                     LowerOptions options) {
  ensureGlslangInitialised();
  const std::string text = withoutConstQualifiers(source.text);
  const NamedLiterals named = withLiteralsNamed(text);
  if (!named.values.empty()) {
    // Where the named text does not compile (a literal where GLSL needs a
    // constant expression) or is refused (an operation outside the subset
    // on literals alone, acos(-1.0), int(4.0), which glslang folds from
    // the text as written), the text as written is lowered instead.
    const Parsed parsed = parse(source, named.text, options);
    if (parsed.log.empty()) {
      try {
        Lowering lowering(source, named.text, parsed.shader->getIntermediate()->getTreeRoot(),
                          options, named.values);
        return lowering.run(outputs);
      } catch (const UsageError&) {
      }
    }
  }
  const Parsed parsed = parse(source, text, options);
  if (!parsed.log.empty())
    throw UsageError(
        fmt::format("{}: glslang cannot compile the shader for the derived oracle:\n{}",
                    source.file, parsed.log));
  Lowering lowering(source, text, parsed.shader->getIntermediate()->getTreeRoot(), options, {});
  return lowering.run(outputs);
}

}  // namespace snell::derived
