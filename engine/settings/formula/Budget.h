#pragma once
// The work and memory bounds of one formula evaluation, internal to the formula code.
//
// Formula values are deep copies (a list holds its items, not references to them), so `[big] * n`,
// `[x for a in s for b in s]` or a long string repeated in a comprehension could take any amount of
// memory or time. Every evaluation gets one Budget, which counts
//
//   steps     — syntax-tree nodes evaluated, comprehension iterations and the items built-ins walk
//               (sum, min, max, any, all, map, sorted, substring search);
//   elements  — every list item and string character the evaluation creates or copies, the items
//               of nested lists included: a list of two [x, y] points is 2 + 4 = 6 elements.
//
// Both are cumulative: a temporary counts even after it is freed. An operation checks its result's
// size before allocating it; going over either limit throws EvalProblem ("too large (more than N
// elements)" / "too much work (more than N steps)"), which evaluate() turns into a FormulaError.
// The largest formula or list value of Cura's 465 machine definitions and their profiles takes 181
// steps (a machine_disallowed_areas list) and 1,200 elements (a start G-code text).
#include <cstdint>

#include "settings/formula/Value.h"

namespace mixengine::formula::detail {

class Budget {
  public:
    /// About 20 ms of evaluation in a release build, under 1 s with AddressSanitizer.
    static constexpr std::uint64_t kMaxSteps = 1'000'000;
    /// At most ~40 MB of list items (40 bytes each, plus a heap block per nested list) or 1 MB of
    /// text, however they are combined. (With 2,000,000, `[[.0]] * 999999` was allowed and took the
    /// settings command to 366 MB: the value is copied a few times on its way to the output.)
    static constexpr std::uint64_t kMaxElements = 1'000'000;

    /// Counts `count` steps; throws when the total goes over kMaxSteps.
    void step(std::uint64_t count = 1);

    /// Counts `count` new elements; throws when the total goes over kMaxElements. Call it before
    /// allocating them.
    void take(std::uint64_t count);

    /// take(n * each), without overflow for any n and each.
    void takeRepeated(std::uint64_t n, std::uint64_t each);

    /// Counts the elements of a copy of `value` (see elementCount()).
    void takeCopy(const Value& value) { take(elementCount(value)); }

    /// The elements that make up `value`: string characters (bytes), list items, and the elements
    /// of nested items. Stops counting once over kMaxElements (the result is then kMaxElements + 1),
    /// so it is cheap on any value.
    static std::uint64_t elementCount(const Value& value);

    std::uint64_t steps() const { return steps_; }
    std::uint64_t elements() const { return elements_; }

  private:
    std::uint64_t steps_ = 0;
    std::uint64_t elements_ = 0;
};

}  // namespace mixengine::formula::detail
