#include "settings/formula/FormulaError.h"

namespace mixengine::formula {

namespace {

constexpr std::size_t kMaxQuotedLength = 120;
constexpr std::size_t kMaxProblemLength = 300;  // a problem may quote a value: int('1' * 10**6)

// `text` on one line: newlines and tabs escaped, cut with "..." when longer than `maxLength`.
std::string oneLine(std::string_view text, std::size_t maxLength) {
    std::string out;
    for (const char c : text) {
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
    if (out.size() > maxLength)
        out = out.substr(0, maxLength - 3) + "...";
    return out;
}

}  // namespace

FormulaError::FormulaError(std::string_view formula, std::string_view problem)
    : InputError("formula '" + oneLine(formula, kMaxQuotedLength) +
                 "': " + oneLine(problem, kMaxProblemLength)),
      formula_(formula),
      problem_(oneLine(problem, kMaxProblemLength)) {}

}  // namespace mixengine::formula
