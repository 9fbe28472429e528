// Walks a parsed formula's node pool (Expression.h) and computes its Python value, within the
// bounds of one Budget (Budget.h): each node evaluated is a step, each value copied (a constant, a
// setting's or a comprehension variable's value, a subscript's item) counts its elements.
#include <algorithm>

#include "settings/formula/Builtins.h"
#include "settings/formula/Formula.h"
#include "settings/formula/Operators.h"

namespace mixengine::formula {

namespace {

using detail::ClauseKind;
using detail::EvalProblem;
using detail::Node;
using detail::NodeKind;

class Evaluator {
  public:
    Evaluator(const detail::ExpressionData& data, const Environment& env)
        : d_(data), env_(env), locals_(data.localCount) {}

    Value eval(std::uint32_t index) {
        budget_.step();
        const Node& n = d_.nodes[index];
        switch (n.kind) {
            case NodeKind::Constant:
                return counted(d_.constants[n.a]);
            case NodeKind::Setting:
                return counted(lookup(d_.names[n.a]));
            case NodeKind::Local:
                return counted(locals_[n.a]);
            case NodeKind::Unary:
                return unaryOp(static_cast<detail::UnaryOp>(n.op), eval(n.a));
            case NodeKind::Binary:
                return binaryOp(static_cast<detail::BinaryOp>(n.op), eval(n.a), eval(n.b), budget_);
            case NodeKind::And:
                return boolChain(n, false);
            case NodeKind::Or:
                return boolChain(n, true);
            case NodeKind::Compare:
                return compareChain(n);
            case NodeKind::IfElse:
                return truthy(eval(n.a)) ? eval(n.b) : eval(n.c);
            case NodeKind::ListDisplay:
                budget_.take(n.count);
                return arguments(n);
            case NodeKind::CallBuiltin:
                return callBuiltin(static_cast<Builtin>(n.op), arguments(n), budget_);
            case NodeKind::CallExternal:
                return counted(callExternal(d_.names[n.a], arguments(n)));
            case NodeKind::CallValue:
                return callValue(eval(n.a), arguments(n));
            case NodeKind::Subscript:
                return counted(subscript(eval(n.a), eval(n.b)));
            case NodeKind::Comprehension: {
                List out;
                runClauses(n, 0, out);
                return out;
            }
        }
        throw EvalProblem("internal: unknown node kind");
    }

  private:
    // A copy of a value made elsewhere (the Environment's, a constant, a variable): its elements
    // count. (A copy is made before it is counted; its original was counted, or is the
    // Environment's, so it is not larger than what the budget allowed so far.)
    Value counted(Value value) {
        budget_.takeCopy(value);
        return value;
    }

    Value lookup(const std::string& name) const {
        std::optional<Value> v = env_.lookup(name);
        if (!v)
            throw EvalProblem("unknown name '" + name + "'");
        return std::move(*v);
    }

    Value callExternal(const std::string& name, const std::vector<Value>& args) const {
        std::optional<Value> v = env_.callFunction(name, args);
        if (!v)
            throw EvalProblem("unknown function '" + name + "'");
        return std::move(*v);
    }

    Value callValue(const Value& callee, const std::vector<Value>& args) {
        if (!callee.is<FunctionRef>())
            throw EvalProblem("'" + std::string(typeName(callee)) + "' object is not callable");
        return callBuiltin(callee.as<FunctionRef>().id, args, budget_);
    }

    std::vector<Value> arguments(const Node& n) {
        std::vector<Value> values;
        values.reserve(n.count);
        for (std::uint32_t i = 0; i < n.count; ++i)
            values.push_back(eval(d_.children[n.first + i]));
        return values;
    }

    // `a or b or c` returns the first truthy operand (else the last); `and` the first falsy one.
    Value boolChain(const Node& n, bool stopWhen) {
        Value v;
        for (std::uint32_t i = 0; i < n.count; ++i) {
            v = eval(d_.children[n.first + i]);
            if (truthy(v) == stopWhen)
                return v;
        }
        return v;
    }

    Value compareChain(const Node& n) {
        Value left = eval(n.a);
        for (std::uint32_t i = 0; i < n.count; i += 2) {
            const auto op = static_cast<detail::CompareOp>(d_.children[n.first + i]);
            Value right = eval(d_.children[n.first + i + 1]);
            if (!compareOp(op, left, right))
                return false;
            left = std::move(right);
        }
        return true;
    }

    void runClauses(const Node& n, std::uint32_t clause, List& out) {
        if (clause * 3 >= n.count) {
            budget_.take(1);
            out.push_back(eval(n.a));
            return;
        }
        const std::uint32_t* c = &d_.children[n.first + clause * 3];
        if (static_cast<ClauseKind>(c[0]) == ClauseKind::If) {
            if (truthy(eval(c[1])))
                runClauses(n, clause + 1, out);
            return;
        }
        for (Value& item : iterate(eval(c[2]), "comprehension", budget_)) {
            budget_.step();
            locals_[c[1]] = std::move(item);
            runClauses(n, clause + 1, out);
        }
    }

    const detail::ExpressionData& d_;
    const Environment& env_;
    std::vector<Value> locals_;
    detail::Budget budget_;
};

}  // namespace

Value evaluate(const Expression& expression, const Environment& environment) {
    const detail::ExpressionData& data = expression.data();
    try {
        return Evaluator(data, environment).eval(data.root);
    } catch (const EvalProblem& e) {
        throw FormulaError(data.source, e.what());
    }
}

std::vector<std::string> referencedNames(const Expression& expression) {
    const detail::ExpressionData& d = expression.data();
    std::vector<std::string> names;
    for (const Node& n : d.nodes) {
        if (n.kind == NodeKind::Setting)
            names.push_back(d.names[n.a]);
        if (n.kind != NodeKind::CallExternal)
            continue;
        for (std::uint32_t i = 0; i < n.count; ++i) {
            const Node& arg = d.nodes[d.children[n.first + i]];
            if (arg.kind == NodeKind::Constant && d.constants[arg.a].is<std::string>()) {
                names.push_back(d.constants[arg.a].as<std::string>());
            }
        }
    }
    std::sort(names.begin(), names.end());
    names.erase(std::unique(names.begin(), names.end()), names.end());
    return names;
}

}  // namespace mixengine::formula
