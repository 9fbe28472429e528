#include "slicing/PointMultimap.h"

namespace mixengine {
namespace {

std::uint64_t hashPoint(const Point2& p) {
    std::uint64_t h = static_cast<std::uint64_t>(p.X) * 0x9E3779B97F4A7C15ULL;
    h ^= static_cast<std::uint64_t>(p.Y) + 0x632BE59BD9B4E019ULL + (h << 6) + (h >> 2);
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ULL;
    return h ^ (h >> 32);
}

}  // namespace

void PointMultimap::reset(std::size_t id_count) {
    std::size_t capacity = 16;
    while (capacity < 2 * id_count)
        capacity *= 2;
    mask_ = capacity - 1;
    keys_.resize(capacity);
    heads_.assign(capacity, kNone);
    next_.assign(id_count, kNone);
}

std::size_t PointMultimap::slotOf(const Point2& point) const {
    std::size_t slot = static_cast<std::size_t>(hashPoint(point)) & mask_;
    while (heads_[slot] != kNone && !(keys_[slot] == point))
        slot = (slot + 1) & mask_;
    return slot;
}

void PointMultimap::insert(const Point2& point, std::int32_t id) {
    const std::size_t slot = slotOf(point);
    keys_[slot] = point;
    next_[static_cast<std::size_t>(id)] = heads_[slot];
    heads_[slot] = id;
}

std::int32_t PointMultimap::first(const Point2& point) const {
    return heads_[slotOf(point)];
}

}  // namespace mixengine
