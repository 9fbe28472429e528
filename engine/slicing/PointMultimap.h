#pragma once
// A hash multimap from exact integer points to small integer ids (the end points of cut segments).
//
// Open addressing with linear probing over a power-of-two table sized for at most half load; the
// ids stored at one point are chained through a `next` array, so insert and lookup are O(1)
// expected and a whole cut is indexed in linear time. reset() keeps the memory for the next cut.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

class PointMultimap {
  public:
    static constexpr std::int32_t kNone = -1;

    /// Empties the map and prepares it for the ids 0 … id_count − 1.
    void reset(std::size_t id_count);
    /// Stores `id` at `point`; each id at most once.
    void insert(const Point2& point, std::int32_t id);
    /// The most recently inserted id at `point`, or kNone.
    std::int32_t first(const Point2& point) const;
    /// The id inserted at the same point before `id`, or kNone.
    std::int32_t nextAtSamePoint(std::int32_t id) const { return next_[static_cast<std::size_t>(id)]; }

  private:
    /// The slot holding `point`, or the empty slot where it would go.
    std::size_t slotOf(const Point2& point) const;

    std::vector<Point2> keys_;
    std::vector<std::int32_t> heads_;  ///< first id per slot; kNone marks an empty slot
    std::vector<std::int32_t> next_;
    std::size_t mask_ = 0;
};

}  // namespace mixengine
