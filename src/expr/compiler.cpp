#include "expr/compiler.hpp"

#include "expr/intrinsics.hpp"

namespace openmss::expr {
namespace {

// 0, 1 or 2 for IF's e2, e3, e4 given the value of e1.
std::size_t ifChoice(double condition) { return condition < 0.0 ? 0 : (condition == 0.0 ? 1 : 2); }

bool isConstant(const SyntaxNode& node) {
  switch (node.kind) {
    case NodeKind::Number:
      return true;
    case NodeKind::Time:
    case NodeKind::Host:
    case NodeKind::DataCall:  // the data is bound after compilation
    case NodeKind::Delay:     // reads the run's history
      return false;
    case NodeKind::If:
      if (!isConstant(node.children[0])) return false;
      return isConstant(node.children[1 + ifChoice(foldConstant(node.children[0]))]);
    default:
      for (const SyntaxNode& child : node.children) {
        if (!isConstant(child)) return false;
      }
      return true;
  }
}

class Compiler {
 public:
  ProgramCode run(const SyntaxNode& root, std::size_t hostCount) {
    for (std::size_t k = 0; k < hostCount; ++k) {
      add(OpCode::LoadHost, {}, static_cast<std::uint32_t>(k));
    }
    code_.timeSlot = add(OpCode::LoadTime, {}, 0);
    code_.result = emit(root);
    assignPartials();
    return std::move(code_);
  }

 private:
  std::uint32_t add(OpCode op, std::initializer_list<std::uint32_t> operands, std::uint32_t aux,
                    Builtin builtin = Builtin::Abs) {
    return addWith(op, std::vector<std::uint32_t>(operands), aux, builtin);
  }

  std::uint32_t addWith(OpCode op, const std::vector<std::uint32_t>& operands, std::uint32_t aux,
                        Builtin builtin) {
    Instruction ins;
    ins.op = op;
    ins.builtin = builtin;
    ins.aux = aux;
    ins.firstOperand = static_cast<std::uint32_t>(code_.operands.size());
    ins.operandCount = static_cast<std::uint16_t>(operands.size());
    for (std::size_t j = 0; j < operands.size(); ++j) {
      code_.operands.push_back(operands[j]);
      if (code_.instructions[operands[j]].op != OpCode::Constant) {
        ins.varyingOperands |= std::uint64_t{1} << j;
      }
    }
    code_.instructions.push_back(ins);
    return static_cast<std::uint32_t>(code_.instructions.size() - 1);
  }

  std::uint32_t constantSlot(double value) {
    code_.constants.push_back(value);
    return add(OpCode::Constant, {}, static_cast<std::uint32_t>(code_.constants.size() - 1));
  }

  std::uint32_t emit(const SyntaxNode& node) {
    if (isConstant(node)) return constantSlot(foldConstant(node));
    switch (node.kind) {
      case NodeKind::Time:
        code_.usesTime = true;
        return code_.timeSlot;
      case NodeKind::Host:
        return static_cast<std::uint32_t>(node.hostIndex);
      case NodeKind::Negate:
        return add(OpCode::Negate, {emit(node.children[0])}, 0);
      case NodeKind::Add:
      case NodeKind::Subtract:
      case NodeKind::Multiply:
      case NodeKind::Divide:
      case NodeKind::Power: {
        const std::uint32_t left = emit(node.children[0]);
        const std::uint32_t right = emit(node.children[1]);
        return add(binaryOp(node.kind), {left, right}, 0);
      }
      case NodeKind::Call: {
        std::vector<std::uint32_t> args;
        for (const SyntaxNode& child : node.children) args.push_back(emit(child));
        return addWith(OpCode::Call, args, 0, node.builtin);
      }
      case NodeKind::If:
        return emitIf(node);
      case NodeKind::DataCall: {
        std::vector<std::uint32_t> args;
        for (const SyntaxNode& child : node.children) args.push_back(emit(child));
        return addWith(OpCode::DataCall, args, static_cast<std::uint32_t>(node.dataIndex),
                       Builtin::Abs);
      }
      case NodeKind::Delay: {
        // Operands e_delayed and e_delay: e_delayed is needed here for a zero delay; e_history
        // is a separate time-only program (Program::DelayCall), since it is read at TIME - delay.
        const std::uint32_t delayed = emit(node.children[0]);
        const std::uint32_t delay = emit(node.children[1]);
        // TIME is the third operand: the value moves along the history as time passes.
        code_.usesTime = true;
        return add(OpCode::Delay, {delayed, delay, code_.timeSlot},
                   static_cast<std::uint32_t>(node.delayIndex));
      }
      case NodeKind::Number:
        break;
    }
    return constantSlot(node.number);
  }

  static OpCode binaryOp(NodeKind kind) {
    switch (kind) {
      case NodeKind::Add:
        return OpCode::Add;
      case NodeKind::Subtract:
        return OpCode::Subtract;
      case NodeKind::Multiply:
        return OpCode::Multiply;
      case NodeKind::Divide:
        return OpCode::Divide;
      default:
        return OpCode::Power;
    }
  }

  // e1; Branch -> one of three blocks; e2 block; Jump; e3 block; Jump; e4 block; Join.
  std::uint32_t emitIf(const SyntaxNode& node) {
    if (isConstant(node.children[0])) {
      return emit(node.children[1 + ifChoice(foldConstant(node.children[0]))]);
    }
    const std::uint32_t condition = emit(node.children[0]);
    const auto firstTarget = static_cast<std::uint32_t>(code_.jumpTargets.size());
    code_.jumpTargets.resize(code_.jumpTargets.size() + 3);
    const std::uint32_t branch = add(OpCode::Branch, {condition}, firstTarget);
    std::uint32_t roots[3];
    std::uint32_t jumps[2];
    for (std::uint32_t b = 0; b < 3; ++b) {
      code_.jumpTargets[firstTarget + b] = static_cast<std::uint32_t>(code_.instructions.size());
      roots[b] = emit(node.children[1 + b]);
      if (b < 2) jumps[b] = add(OpCode::Jump, {}, 0);
    }
    const std::uint32_t join = add(OpCode::Join, {roots[0], roots[1], roots[2], branch}, 0);
    for (std::uint32_t jump : jumps) code_.instructions[jump].aux = join;
    return join;
  }

  void assignPartials() {
    std::uint32_t next = 0;
    for (Instruction& ins : code_.instructions) {
      ins.firstPartial = next;
      next += ins.operandCount;
    }
    code_.partialCount = next;
  }

  ProgramCode code_;
};

}  // namespace

double foldConstant(const SyntaxNode& node) {
  const auto child = [&](std::size_t k) { return foldConstant(node.children[k]); };
  switch (node.kind) {
    case NodeKind::Number:
      return node.number;
    case NodeKind::Negate:
      return -child(0);
    case NodeKind::Add:
      return child(0) + child(1);
    case NodeKind::Subtract:
      return child(0) - child(1);
    case NodeKind::Multiply:
      return child(0) * child(1);
    case NodeKind::Divide:
      return child(0) / child(1);
    case NodeKind::Power:
      return intrinsic::power(child(0), child(1));
    case NodeKind::Call: {
      double args[kMaxBuiltinArguments];
      for (std::size_t k = 0; k < node.children.size(); ++k) args[k] = child(k);
      return applyBuiltin(node.builtin, args, static_cast<int>(node.children.size()));
    }
    case NodeKind::If:
      return child(1 + ifChoice(child(0)));
    case NodeKind::Time:
    case NodeKind::Host:
    case NodeKind::DataCall:  // never constant (isConstant)
    case NodeKind::Delay:
      break;
  }
  return 0.0;
}

ProgramCode compileProgram(const SyntaxNode& root, std::size_t hostCount) {
  return Compiler().run(root, hostCount);
}

}  // namespace openmss::expr
