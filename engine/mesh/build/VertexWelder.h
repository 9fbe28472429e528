#pragma once
// Internal to MeshBuilder: assigns one index per distinct integer position.
//
// Open addressing with linear probing; each 16-byte slot holds the position (three int32, so
// coordinates must lie within +-(2^31 - 1) microns — MeshBuilder limits them to +-1e9) and its
// index, so a lookup touches one cache line and never the vertex list. No allocation per vertex;
// the table doubles at load 1/2. Indices are given in order of first appearance (deterministic).
// prefetch() lets a caller overlap the cache misses of a batch of lookups.
#include <cstdint>
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

class VertexWelder {
  public:
    explicit VertexWelder(std::size_t expected_vertices);

    /// The index of `p`, appending it to the vertex list when it is new.
    std::uint32_t indexOf(const Point3& p);

    /// Hints that indexOf(p) follows soon.
    void prefetch(const Point3& p) const { __builtin_prefetch(&slots_[hashOf(p) & mask_]); }

    std::vector<Point3> takeVertices() { return std::move(vertices_); }

  private:
    struct Slot {
        std::int32_t x, y, z;
        std::uint32_t index;  ///< kEmpty when the slot is free
    };

    static std::uint64_t hashOf(const Point3& p);
    void rehash(std::size_t capacity);

    std::vector<Point3> vertices_;
    std::vector<Slot> slots_;
    std::size_t mask_ = 0;
};

/// Mixes three 64-bit words into a well-spread hash (shared by the welder and the face set).
inline std::uint64_t mixHash(std::uint64_t a, std::uint64_t b, std::uint64_t c) {
    std::uint64_t h = a * 0x9E3779B97F4A7C15ULL;
    h = (h ^ (h >> 29) ^ b) * 0xBF58476D1CE4E5B9ULL;
    h = (h ^ (h >> 32) ^ c) * 0x94D049BB133111EBULL;
    return h ^ (h >> 31);
}

/// The smallest power of two >= max(n, 16).
inline std::size_t tableCapacity(std::size_t n) {
    std::size_t capacity = 16;
    while (capacity < n) {
        capacity *= 2;
    }
    return capacity;
}

}  // namespace mixengine
