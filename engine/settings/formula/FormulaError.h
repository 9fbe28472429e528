#pragma once
// Errors of the formula parser and evaluator.
//
//   FormulaError — a setting formula (a Python expression from a Cura definition or profile) could not
//                  be parsed or evaluated: syntax error, unknown name, wrong type, division by zero,
//                  math domain error, ... It is an InputError: the user's input is at fault.
//                  what() is one line: `formula '<text>': <problem>`, with newlines escaped and very
//                  long formulas (120 characters) and problems (300, e.g. quoting a huge value) shortened.
//
//   detail::EvalProblem — internal to the formula code: thrown by operators and built-ins, which do
//                  not know the formula text; evaluate() turns it into a FormulaError.
#include <string>
#include <string_view>

#include "common/Error.h"

namespace mixengine::formula {

class FormulaError : public InputError {
  public:
    FormulaError(std::string_view formula, std::string_view problem);

    const std::string& formula() const { return formula_; }
    const std::string& problem() const { return problem_; }

  private:
    std::string formula_;
    std::string problem_;
};

namespace detail {

class EvalProblem : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

}  // namespace detail

}  // namespace mixengine::formula
