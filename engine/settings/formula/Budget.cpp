#include "settings/formula/Budget.h"

#include <string>

#include "settings/formula/FormulaError.h"

namespace mixengine::formula::detail {

namespace {

// Adds the elements of `value` to `total`, stopping once `total` is over `limit`.
void addElements(const Value& value, std::uint64_t limit, std::uint64_t& total) {
    if (value.is<std::string>()) {
        total += value.as<std::string>().size();
        return;
    }
    if (!value.is<List>())
        return;
    const List& list = value.as<List>();
    total += list.size();
    for (const Value& item : list) {
        if (total > limit)
            return;
        addElements(item, limit, total);
    }
}

}  // namespace

void Budget::step(std::uint64_t count) {
    if (count > kMaxSteps - steps_) {
        throw EvalProblem("too much work (more than " + std::to_string(kMaxSteps) + " evaluation steps)");
    }
    steps_ += count;
}

void Budget::take(std::uint64_t count) {
    if (count > kMaxElements - elements_) {
        throw EvalProblem("too large (more than " + std::to_string(kMaxElements) +
                          " elements: list items and string characters)");
    }
    elements_ += count;
}

void Budget::takeRepeated(std::uint64_t n, std::uint64_t each) {
    if (each != 0 && n > (kMaxElements + 1) / each)
        take(kMaxElements + 1);
    take(n * each);
}

std::uint64_t Budget::elementCount(const Value& value) {
    std::uint64_t total = 0;
    addElements(value, kMaxElements, total);
    return total > kMaxElements ? kMaxElements + 1 : total;
}

}  // namespace mixengine::formula::detail
