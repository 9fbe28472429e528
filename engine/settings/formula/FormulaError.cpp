#include "settings/formula/FormulaError.h"

namespace mixengine::formula {

namespace {

constexpr std::size_t kMaxQuotedLength = 120;

// The formula on one line: newlines and tabs escaped, long formulas cut with "...".
std::string quoteFormula(std::string_view formula) {
    std::string out;
    for (const char c : formula) {
        if (c == '\n') {
            out += "\\n";
        } else if (c == '\r') {
            out += "\\r";
        } else if (c == '\t') {
            out += "\\t";
        } else {
            out += c;
        }
    }
    if (out.size() > kMaxQuotedLength)
        out = out.substr(0, kMaxQuotedLength - 3) + "...";
    return "formula '" + out + "'";
}

}  // namespace

FormulaError::FormulaError(std::string_view formula, std::string_view problem)
    : InputError(quoteFormula(formula) + ": " + std::string(problem)), formula_(formula), problem_(problem) {}

}  // namespace mixengine::formula
