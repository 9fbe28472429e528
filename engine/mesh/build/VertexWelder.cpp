#include "mesh/build/VertexWelder.h"

#include <limits>

#include "mesh/MemoryHint.h"

namespace mixengine {

namespace {

constexpr std::uint32_t kEmpty = std::numeric_limits<std::uint32_t>::max();

}  // namespace

std::uint64_t VertexWelder::hashOf(const Point3& p) {
    return mixHash(static_cast<std::uint64_t>(p.x), static_cast<std::uint64_t>(p.y),
                   static_cast<std::uint64_t>(p.z));
}

VertexWelder::VertexWelder(std::size_t expected_vertices) {
    vertices_.reserve(expected_vertices);
    adviseHugePages(vertices_.data(), vertices_.capacity() * sizeof(Point3));
    rehash(tableCapacity(2 * expected_vertices));
}

void VertexWelder::rehash(std::size_t capacity) {
    std::vector<Slot>().swap(slots_);
    slots_.reserve(capacity);
    adviseHugePages(slots_.data(), capacity * sizeof(Slot));
    slots_.assign(capacity, Slot{0, 0, 0, kEmpty});
    mask_ = capacity - 1;
    for (std::uint32_t i = 0; i < vertices_.size(); ++i) {
        const Point3& p = vertices_[i];
        std::size_t slot = hashOf(p) & mask_;
        while (slots_[slot].index != kEmpty) {
            slot = (slot + 1) & mask_;
        }
        slots_[slot] = {static_cast<std::int32_t>(p.x), static_cast<std::int32_t>(p.y),
                        static_cast<std::int32_t>(p.z), i};
    }
}

std::uint32_t VertexWelder::indexOf(const Point3& p) {
    const auto x = static_cast<std::int32_t>(p.x);
    const auto y = static_cast<std::int32_t>(p.y);
    const auto z = static_cast<std::int32_t>(p.z);
    std::size_t slot = hashOf(p) & mask_;
    for (; slots_[slot].index != kEmpty; slot = (slot + 1) & mask_) {
        const Slot& s = slots_[slot];
        if (s.x == x && s.y == y && s.z == z) {
            return s.index;
        }
    }
    const auto index = static_cast<std::uint32_t>(vertices_.size());
    vertices_.push_back(p);
    slots_[slot] = {x, y, z, index};
    if (2 * vertices_.size() > slots_.size()) {
        rehash(2 * slots_.size());
    }
    return index;
}

}  // namespace mixengine
