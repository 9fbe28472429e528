#include "toolpaths/infill/cross/SierpinskiSequence.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <list>
#include <numeric>

namespace mixengine {
namespace {

constexpr float kAllowedError = 0.01f;  ///< mm of curve that count as no error
constexpr int kMaxRounds = 999;

using Iter = std::list<int>::iterator;

/// The cut through the tree while it is being chosen.
class Walk {
  public:
    explicit Walk(SierpinskiTree& tree) : tree_(tree), max_depth_(tree.maxDepth()) {
        seq_.push_back(SierpinskiTree::kRoot);
    }

    void lowerBound();
    void settle();
    void dither();
    std::vector<int> result() const { return {seq_.begin(), seq_.end()}; }

  private:
    SierpinskiNode& at(Iter it) { return tree_.node(*it); }
    bool constrainedBackward(Iter it);
    bool constrainedForward(Iter it);
    bool constrainedRange(Iter begin, Iter end);
    /// [it, next) or, for a triangle entered by AB, [prev, next): the triangles sharing a side AB.
    Iter pairBegin(Iter it);
    /// The iterators of the triangles above `levels`' end, by depth (0 … levels − 1).
    std::vector<std::vector<Iter>> byDepth(int levels);
    bool subdivideAll();
    bool bubbleUpConstraintErrors();
    Iter subdivide(Iter begin, Iter end, bool redistribute);
    void exchangeInnerErrors(Iter begin, Iter end);
    void redistributeLeftover(Iter begin, Iter end, bool subdivision_errors);
    void balance(Iter begin, Iter end);

    SierpinskiTree& tree_;
    int max_depth_;
    std::list<int> seq_;
};

bool Walk::constrainedBackward(Iter it) {
    return it != seq_.begin() && at(it).direction == CrossDirection::AbToBc &&
           at(std::prev(it)).depth < at(it).depth;
}

bool Walk::constrainedForward(Iter it) {
    return std::next(it) != seq_.end() && at(it).direction == CrossDirection::AcToAb &&
           at(std::next(it)).depth < at(it).depth;
}

bool Walk::constrainedRange(Iter begin, Iter end) {
    for (Iter it = begin; it != end; ++it) {
        if (constrainedBackward(it) || constrainedForward(it))
            return true;
    }
    return false;
}

Iter Walk::pairBegin(Iter it) {
    return at(it).direction == CrossDirection::AbToBc && it != seq_.begin() ? std::prev(it) : it;
}

std::vector<std::vector<Iter>> Walk::byDepth(int levels) {
    std::vector<std::vector<Iter>> out(static_cast<std::size_t>(std::max(levels, 0)));
    for (Iter it = seq_.begin(); it != seq_.end(); ++it) {
        if (at(it).depth < levels)
            out[static_cast<std::size_t>(at(it).depth)].push_back(it);
    }
    return out;
}

/// A triangle entered by AC and left by AB waits for the next one, with which it subdivides.
bool waitsForNext(const SierpinskiNode& n, bool last) {
    return n.direction == CrossDirection::AcToAb && !last;
}

bool Walk::subdivideAll() {
    bool change = false;
    for (const std::vector<Iter>& level : byDepth(max_depth_)) {
        for (const Iter it : level) {
            const Iter end = std::next(it);
            if (waitsForNext(at(it), end == seq_.end()))
                continue;
            const Iter begin = pairBegin(it);
            const bool constrained = constrainedBackward(begin) || constrainedForward(it);
            float error = 0;
            for (Iter i = begin; i != end; ++i)
                error += at(i).subdivisionError();
            if (!at(it).leaf() && error >= 0 && !constrained) {
                subdivide(begin, end, true);
                change = true;
            }
        }
    }
    return change;
}

bool Walk::bubbleUpConstraintErrors() {
    bool moved = false;
    std::vector<std::vector<Iter>> levels = byDepth(max_depth_ + 1);
    for (auto level = levels.rbegin(); level != levels.rend(); ++level) {
        for (const Iter it : *level) {
            float error = at(it).valueError();
            const bool forward = constrainedForward(it), backward = constrainedBackward(it);
            if (error <= kAllowedError || !(forward || backward))
                continue;
            if (forward && backward)
                error *= 0.5f;  // half each way
            if (forward) {
                at(it).error_right -= error;
                at(std::next(it)).error_left += error;
            }
            if (backward) {
                at(it).error_left -= error;
                at(std::prev(it)).error_right += error;
            }
            moved = moved || std::abs(error) > kAllowedError;
        }
    }
    return moved;
}

Iter Walk::subdivide(Iter begin, Iter end, bool redistribute) {
    if (redistribute) {
        redistributeLeftover(begin, end, true);
        SierpinskiNode& first = at(begin);
        SierpinskiNode& last = at(std::prev(end));
        tree_.node(first.first_child).error_left += first.error_left;
        tree_.node(last.first_child + 1).error_right += last.error_right;
    }
    const bool at_front = begin == seq_.begin();
    const Iter before_first = at_front ? seq_.end() : std::prev(begin);
    for (Iter it = begin; it != end; ++it) {
        const int child = at(it).first_child;
        seq_.insert(begin, child);
        seq_.insert(begin, child + 1);
    }
    const Iter first_child = at_front ? seq_.begin() : std::next(before_first);
    const Iter last_child = std::prev(begin);
    seq_.erase(begin, end);
    if (redistribute)
        balance(first_child, std::next(last_child));
    return last_child;
}

/// Neighbours inside the range hand their shared error over (as CuraEngine does it).
void Walk::exchangeInnerErrors(Iter begin, Iter end) {
    for (Iter it = begin; it != end && std::next(it) != end; ++it) {
        SierpinskiNode& node = at(it);
        SierpinskiNode& next = at(std::next(it));
        float exchange = node.error_right;
        if (node.error_right < next.error_left)
            exchange = -exchange;
        node.error_right -= exchange;
        next.error_left += exchange;
    }
}

void Walk::redistributeLeftover(Iter begin, Iter end, bool subdivision_errors) {
    exchangeInnerErrors(begin, end);
    float superfluous = 0;
    for (Iter it = begin; it != end; ++it)
        superfluous += subdivision_errors ? at(it).subdivisionError() : at(it).valueError();
    if (superfluous < kAllowedError)
        return;
    SierpinskiNode& first = at(begin);
    SierpinskiNode& last = at(std::prev(end));
    const bool from_left = begin != seq_.begin() && first.error_left > kAllowedError;
    const bool from_right = end != seq_.end() && last.error_right > kAllowedError;
    if (from_left && from_right) {
        const float input = first.error_left + last.error_right;
        superfluous = std::min(superfluous, input);  // no more than came in
        const float to_left = superfluous * first.error_left / input;
        const float to_right = superfluous * last.error_right / input;
        first.error_left -= to_left;
        at(std::prev(begin)).error_right += to_left;
        last.error_right -= to_right;
        at(end).error_left += to_right;
    } else if (from_left) {
        superfluous = std::min(superfluous, first.error_left);
        first.error_left -= superfluous;
        at(std::prev(begin)).error_right += superfluous;
    } else if (from_right) {
        superfluous = std::min(superfluous, last.error_right);
        last.error_right -= superfluous;
        at(end).error_left += superfluous;
    }
}

/// Children short of their own curve get what they lack from their siblings with a surplus, in
/// proportion to it, passed along the range.
void Walk::balance(Iter begin, Iter end) {
    std::vector<SierpinskiNode*> nodes;
    for (Iter it = begin; it != end; ++it)
        nodes.push_back(&at(it));
    std::vector<std::size_t> order(nodes.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&nodes](std::size_t a, std::size_t b) {
        return nodes[a]->valueError() < nodes[b]->valueError();
    });
    std::vector<float> compensation(nodes.size(), 0.0f);
    float added = 0;
    std::size_t k = 0;
    for (; k < order.size() && nodes[order[k]]->valueError() < 0; ++k) {
        added -= nodes[order[k]]->valueError();
        compensation[order[k]] = -nodes[order[k]]->valueError();
    }
    if (added == 0)
        return;
    float remaining = 0;
    for (std::size_t r = k; r < order.size(); ++r)
        remaining += nodes[order[r]]->valueError();
    if (std::abs(remaining) < 0.0001f)
        return;
    for (std::size_t r = k; r < order.size(); ++r)
        compensation[order[r]] = -(added * nodes[order[r]]->valueError() / remaining);
    float energy = 0;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        nodes[i]->error_left -= energy;
        energy += compensation[i];
        nodes[i]->error_right += energy;
    }
}

void Walk::lowerBound() {
    for (int round = 0; round < kMaxRounds; ++round) {
        bool change = subdivideAll();
        change = bubbleUpConstraintErrors() || change;
        if (!change)
            break;
    }
}

void Walk::settle() {
    // As CuraEngine: the deepest level's triangles keep what they hold.
    for (const std::vector<Iter>& level : byDepth(max_depth_)) {
        for (const Iter it : level)
            redistributeLeftover(it, std::next(it), false);
    }
}

void Walk::dither() {
    float error = 0;
    for (Iter it = seq_.begin(); it != seq_.end(); ++it) {
        SierpinskiNode& node = at(it);
        const float boundary = (node.realized_mm + node.child_realized_mm) * 0.5f;
        const float value = node.erroredValue();
        const float boundary_error = value - boundary + error;
        const Iter end = std::next(it);
        if (waitsForNext(node, end == seq_.end()))
            continue;
        const Iter begin = pairBegin(it);
        if (!constrainedRange(begin, end) && boundary_error >= 0 && !node.leaf()) {
            it = subdivide(begin, end, false);
            error += value - node.child_realized_mm;
        } else {
            error += value - node.realized_mm;
        }
    }
}

}  // namespace

std::vector<int> crossSequence(SierpinskiTree& tree) {
    Walk walk(tree);
    walk.lowerBound();
    walk.settle();
    walk.dither();
    return walk.result();
}

}  // namespace mixengine
