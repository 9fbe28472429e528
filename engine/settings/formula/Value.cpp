#include "settings/formula/Value.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <system_error>

#include "settings/formula/Numeric.h"

namespace mixengine::formula {

namespace {

template <class... Fs>
struct Overloaded : Fs... {
    using Fs::operator()...;
};
template <class... Fs>
Overloaded(Fs...) -> Overloaded<Fs...>;

// Python's repr of a str: single quotes unless the text holds ' and no ", escapes for the quote,
// the backslash and control characters. Bytes >= 0x80 (UTF-8) are printable and kept.
std::string quoteString(const std::string& s) {
    const bool useDouble = s.find('\'') != std::string::npos && s.find('"') == std::string::npos;
    const char quote = useDouble ? '"' : '\'';
    std::string out(1, quote);
    for (const char c : s) {
        const auto u = static_cast<unsigned char>(c);
        if (c == quote || c == '\\') {
            out += '\\';
            out += c;
        } else if (c == '\n') {
            out += "\\n";
        } else if (c == '\r') {
            out += "\\r";
        } else if (c == '\t') {
            out += "\\t";
        } else if (u < 0x20 || u == 0x7f) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02x", u);
            out += buf;
        } else {
            out += c;
        }
    }
    out += quote;
    return out;
}

std::string listStr(const List& list) {
    std::string out = "[";
    for (std::size_t i = 0; i < list.size(); ++i) {
        if (i > 0)
            out += ", ";
        out += toPythonRepr(list[i]);
    }
    out += ']';
    return out;
}

}  // namespace

std::string_view typeName(const Value& v) {
    return std::visit(Overloaded{
                          [](const NoneValue&) { return std::string_view("NoneType"); },
                          [](bool) { return std::string_view("bool"); },
                          [](std::int64_t) { return std::string_view("int"); },
                          [](double) { return std::string_view("float"); },
                          [](const std::string&) { return std::string_view("str"); },
                          [](const List&) { return std::string_view("list"); },
                          [](const FunctionRef&) { return std::string_view("builtin_function_or_method"); },
                      },
                      v.storage());
}

bool truthy(const Value& v) {
    return std::visit(Overloaded{
                          [](const NoneValue&) { return false; },
                          [](bool b) { return b; },
                          [](std::int64_t i) { return i != 0; },
                          [](double d) { return d != 0.0; },
                          [](const std::string& s) { return !s.empty(); },
                          [](const List& l) { return !l.empty(); },
                          [](const FunctionRef&) { return true; },
                      },
                      v.storage());
}

bool pythonEquals(const Value& a, const Value& b) {
    if (a.isNumber() && b.isNumber()) {
        if (a.is<double>() || b.is<double>()) {
            if (a.is<double>() && b.is<double>())
                return a.as<double>() == b.as<double>();
            return a.is<double>() ? compareIntDouble(asInt(b), a.as<double>()) == 0
                                  : compareIntDouble(asInt(a), b.as<double>()) == 0;
        }
        return asInt(a) == asInt(b);
    }
    if (a.is<List>() && b.is<List>()) {
        const List& x = a.as<List>();
        const List& y = b.as<List>();
        if (x.size() != y.size())
            return false;
        for (std::size_t i = 0; i < x.size(); ++i) {
            if (!pythonEquals(x[i], y[i]))
                return false;
        }
        return true;
    }
    return a == b;
}

std::string floatRepr(double d) {
    if (std::isnan(d))
        return "nan";
    if (std::isinf(d))
        return d > 0 ? "inf" : "-inf";
    // Shortest round-trip digits in scientific form, e.g. "1.2345e+02" or "-5e-324".
    char buf[64];
    const auto res = std::to_chars(buf, buf + sizeof buf, d, std::chars_format::scientific);
    std::string sci(buf, res.ptr);
    const bool negative = sci[0] == '-';
    if (negative)
        sci.erase(0, 1);
    const std::size_t e = sci.find('e');
    const int exponent = std::stoi(sci.substr(e + 1));
    std::string digits = sci.substr(0, e);
    if (digits.size() > 1)
        digits.erase(1, 1);  // drop the '.'
    // Python: value = 0.DIGITS * 10**decpt; exponent notation when decpt <= -4 or decpt > 16.
    const int decpt = exponent + 1;
    std::string out = negative ? "-" : "";
    if (decpt <= -4 || decpt > 16) {
        out += digits[0];
        if (digits.size() > 1)
            out += "." + digits.substr(1);
        char expBuf[16];
        std::snprintf(expBuf, sizeof expBuf, "e%c%02d", exponent < 0 ? '-' : '+', std::abs(exponent));
        return out + expBuf;
    }
    if (decpt <= 0)
        return out + "0." + std::string(static_cast<std::size_t>(-decpt), '0') + digits;
    const auto intDigits = static_cast<std::size_t>(decpt);
    if (digits.size() <= intDigits)
        return out + digits + std::string(intDigits - digits.size(), '0') + ".0";
    return out + digits.substr(0, intDigits) + "." + digits.substr(intDigits);
}

std::string toPythonStr(const Value& v) {
    return std::visit(Overloaded{
                          [](const NoneValue&) { return std::string("None"); },
                          [](bool b) { return std::string(b ? "True" : "False"); },
                          [](std::int64_t i) { return std::to_string(i); },
                          [](double d) { return floatRepr(d); },
                          [](const std::string& s) { return s; },
                          [](const List& l) { return listStr(l); },
                          [](const FunctionRef& f) {
                              std::string_view name = builtinName(f.id);
                              if (name.starts_with("math."))
                                  name.remove_prefix(5);
                              return "<built-in function " + std::string(name) + ">";
                          },
                      },
                      v.storage());
}

std::string toPythonRepr(const Value& v) {
    if (v.is<std::string>())
        return quoteString(v.as<std::string>());
    return toPythonStr(v);
}

}  // namespace mixengine::formula
