#include "settings/formula/Operators.h"

#include <string_view>

#include "settings/formula/FormulaError.h"
#include "settings/formula/Numeric.h"

namespace mixengine::formula {

namespace {

using detail::BinaryOp;
using detail::CompareOp;
using detail::EvalProblem;
using detail::UnaryOp;

const char* symbolOf(BinaryOp op) {
    switch (op) {
        case BinaryOp::Add:
            return "+";
        case BinaryOp::Sub:
            return "-";
        case BinaryOp::Mul:
            return "*";
        case BinaryOp::Div:
            return "/";
        case BinaryOp::FloorDiv:
            return "//";
        case BinaryOp::Mod:
            return "%";
        case BinaryOp::Pow:
            return "**";
    }
    return "?";
}

[[noreturn]] void unsupported(BinaryOp op, const Value& a, const Value& b) {
    throw EvalProblem(std::string("unsupported operand type(s) for ") + symbolOf(op) + ": '" +
                      std::string(typeName(a)) + "' and '" + std::string(typeName(b)) + "'");
}

bool isIntLike(const Value& v) {
    return v.is<bool>() || v.is<std::int64_t>();
}

Value intArithmetic(BinaryOp op, std::int64_t a, std::int64_t b) {
    switch (op) {
        case BinaryOp::Add:
            return addInt(a, b);
        case BinaryOp::Sub:
            return subInt(a, b);
        case BinaryOp::Mul:
            return mulInt(a, b);
        case BinaryOp::Div:
            return trueDivideInt(a, b);
        case BinaryOp::FloorDiv:
            return floorDivInt(a, b);
        case BinaryOp::Mod:
            return modInt(a, b);
        case BinaryOp::Pow:
            return powInt(a, b);
    }
    return Value();
}

Value floatArithmetic(BinaryOp op, double a, double b) {
    switch (op) {
        case BinaryOp::Add:
            return a + b;
        case BinaryOp::Sub:
            return a - b;
        case BinaryOp::Mul:
            return a * b;
        case BinaryOp::Div:
            return trueDivide(a, b);
        case BinaryOp::FloorDiv:
            return floorDivFloat(a, b);
        case BinaryOp::Mod:
            return modFloat(a, b);
        case BinaryOp::Pow:
            return powFloat(a, b);
    }
    return Value();
}

// `seq * times`; its size (with the elements of nested lists: each copy is a deep copy) is taken
// from the budget before anything is allocated.
template <typename Sequence>
Sequence repeat(const Value& seq, std::int64_t times, detail::Budget& budget) {
    const Sequence& s = seq.as<Sequence>();
    Sequence out;
    if (times <= 0 || s.empty())
        return out;
    budget.takeRepeated(static_cast<std::uint64_t>(times), detail::Budget::elementCount(seq));
    out.reserve(s.size() * static_cast<std::size_t>(times));
    for (std::int64_t i = 0; i < times; ++i)
        out.insert(out.end(), s.begin(), s.end());
    return out;
}

Value sequenceArithmetic(BinaryOp op, const Value& a, const Value& b, detail::Budget& budget) {
    if (op == BinaryOp::Add && a.is<std::string>() && b.is<std::string>()) {
        budget.take(a.as<std::string>().size() + b.as<std::string>().size());
        return a.as<std::string>() + b.as<std::string>();
    }
    if (op == BinaryOp::Add && a.is<List>() && b.is<List>()) {
        budget.take(detail::Budget::elementCount(a) + detail::Budget::elementCount(b));
        List joined = a.as<List>();
        joined.insert(joined.end(), b.as<List>().begin(), b.as<List>().end());
        return joined;
    }
    if (op == BinaryOp::Mul) {
        const Value& seq = isIntLike(b) ? a : b;
        const Value& count = isIntLike(b) ? b : a;
        if (isIntLike(count) && seq.is<std::string>())
            return repeat<std::string>(seq, asInt(count), budget);
        if (isIntLike(count) && seq.is<List>())
            return repeat<List>(seq, asInt(count), budget);
    }
    if (op == BinaryOp::Mod && a.is<std::string>()) {
        throw EvalProblem("printf-style string formatting with % is not supported");
    }
    unsupported(op, a, b);
}

// Whether `pattern` occurs in `text`, in time linear in both lengths (std::string::find can take
// their product: ~2 * 10^10 comparisons for 'a' * 150000 + 'b' in 'a' * 300000). Knuth-Morris-Pratt
// for long patterns.
bool containsText(std::string_view text, std::string_view pattern) {
    constexpr std::size_t kShortPattern = 16;
    if (pattern.size() <= kShortPattern)
        return text.find(pattern) != std::string_view::npos;
    std::vector<std::size_t> border(pattern.size(), 0);  // longest proper prefix that is a suffix
    for (std::size_t i = 1, k = 0; i < pattern.size(); ++i) {
        while (k > 0 && pattern[i] != pattern[k])
            k = border[k - 1];
        k += pattern[i] == pattern[k] ? 1 : 0;
        border[i] = k;
    }
    for (std::size_t i = 0, k = 0; i < text.size(); ++i) {
        while (k > 0 && text[i] != pattern[k])
            k = border[k - 1];
        k += text[i] == pattern[k] ? 1 : 0;
        if (k == pattern.size())
            return true;
    }
    return false;
}

bool contains(const Value& container, const Value& item) {
    if (container.is<std::string>()) {
        if (!item.is<std::string>()) {
            throw EvalProblem("'in <string>' requires string as left operand, not " +
                              std::string(typeName(item)));
        }
        return containsText(container.as<std::string>(), item.as<std::string>());
    }
    if (container.is<List>()) {
        for (const Value& element : container.as<List>()) {
            if (pythonEquals(element, item))
                return true;
        }
        return false;
    }
    throw EvalProblem("argument of type '" + std::string(typeName(container)) + "' is not iterable");
}

std::partial_ordering fromStrong(std::strong_ordering o) {
    if (o < 0)
        return std::partial_ordering::less;
    if (o > 0)
        return std::partial_ordering::greater;
    return std::partial_ordering::equivalent;
}

// The length in bytes of the character (a byte and the UTF-8 continuation bytes after it) at `at`.
std::size_t characterLength(std::string_view text, std::size_t at) {
    std::size_t length = 1;
    while (at + length < text.size() && (static_cast<unsigned char>(text[at + length]) & 0xC0) == 0x80)
        ++length;
    return length;
}

std::size_t normalizeIndex(const Value& index, std::size_t size, const char* what) {
    if (!isIntLike(index)) {
        throw EvalProblem(std::string(what) + " indices must be integers, not " +
                          std::string(typeName(index)));
    }
    std::int64_t i = asInt(index);
    const auto n = static_cast<std::int64_t>(size);
    if (i < 0)
        i += n;
    if (i < 0 || i >= n)
        throw EvalProblem(std::string(what) + " index out of range");
    return static_cast<std::size_t>(i);
}

}  // namespace

Value unaryOp(UnaryOp op, const Value& v) {
    if (op == UnaryOp::Not)
        return !truthy(v);
    if (v.is<double>())
        return op == UnaryOp::Negate ? -v.as<double>() : v.as<double>();
    if (isIntLike(v))
        return op == UnaryOp::Negate ? negInt(asInt(v)) : asInt(v);
    throw EvalProblem(std::string("bad operand type for unary ") + (op == UnaryOp::Negate ? "-" : "+") +
                      ": '" + std::string(typeName(v)) + "'");
}

Value binaryOp(BinaryOp op, const Value& a, const Value& b, detail::Budget& budget) {
    if (a.isNumber() && b.isNumber()) {
        if (a.is<double>() || b.is<double>())
            return floatArithmetic(op, asDouble(a), asDouble(b));
        return intArithmetic(op, asInt(a), asInt(b));
    }
    return sequenceArithmetic(op, a, b, budget);
}

std::partial_ordering pythonOrder(const Value& a, const Value& b, const char* symbol) {
    if (a.isNumber() && b.isNumber()) {
        if (a.is<double>() && b.is<double>())
            return a.as<double>() <=> b.as<double>();
        if (a.is<double>())
            return 0 <=> compareIntDouble(asInt(b), a.as<double>());
        if (b.is<double>())
            return compareIntDouble(asInt(a), b.as<double>());
        return fromStrong(asInt(a) <=> asInt(b));
    }
    if (a.is<std::string>() && b.is<std::string>()) {
        // UTF-8 byte order is code point order.
        return fromStrong(a.as<std::string>().compare(b.as<std::string>()) <=> 0);
    }
    if (a.is<List>() && b.is<List>()) {
        const List& x = a.as<List>();
        const List& y = b.as<List>();
        for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
            if (!pythonEquals(x[i], y[i]))
                return pythonOrder(x[i], y[i], symbol);
        }
        return fromStrong(x.size() <=> y.size());
    }
    throw EvalProblem(std::string("'") + symbol + "' not supported between instances of '" +
                      std::string(typeName(a)) + "' and '" + std::string(typeName(b)) + "'");
}

bool compareOp(CompareOp op, const Value& a, const Value& b) {
    switch (op) {
        case CompareOp::Lt:
            return pythonOrder(a, b, "<") < 0;
        case CompareOp::Le:
            return pythonOrder(a, b, "<=") <= 0;
        case CompareOp::Gt:
            return pythonOrder(a, b, ">") > 0;
        case CompareOp::Ge:
            return pythonOrder(a, b, ">=") >= 0;
        case CompareOp::Eq:
            return pythonEquals(a, b);
        case CompareOp::Ne:
            return !pythonEquals(a, b);
        case CompareOp::In:
            return contains(b, a);
        case CompareOp::NotIn:
            return !contains(b, a);
    }
    return false;
}

Value subscript(const Value& container, const Value& index) {
    if (container.is<List>()) {
        const List& list = container.as<List>();
        return list[normalizeIndex(index, list.size(), "list")];
    }
    if (container.is<std::string>()) {
        const std::string& text = container.as<std::string>();
        std::size_t wanted = normalizeIndex(index, characterCount(text), "string");
        std::size_t begin = 0;
        while (wanted-- > 0)
            begin += characterLength(text, begin);
        return text.substr(begin, characterLength(text, begin));
    }
    throw EvalProblem("'" + std::string(typeName(container)) + "' object is not subscriptable");
}

List iterate(const Value& iterable, std::string_view context, detail::Budget& budget) {
    if (iterable.is<List>()) {
        budget.takeCopy(iterable);
        return iterable.as<List>();
    }
    if (iterable.is<std::string>()) {
        const std::string& text = iterable.as<std::string>();
        budget.take(characterCount(text) + text.size());  // the list's items and their characters
        List out;
        for (std::size_t i = 0; i < text.size(); i += characterLength(text, i))
            out.emplace_back(text.substr(i, characterLength(text, i)));
        return out;
    }
    throw EvalProblem(std::string(context) + ": '" + std::string(typeName(iterable)) +
                      "' object is not iterable");
}

std::size_t characterCount(std::string_view text) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < text.size(); i += characterLength(text, i))
        ++count;
    return count;
}

}  // namespace mixengine::formula
