#pragma once
// Internal to MeshBuilder: remembers which vertex sets have been used by a face, to drop
// duplicate faces (the same three vertices in any order or winding). Open addressing with the
// sorted index triple stored in the slot; sized once for the maximum number of faces.
// prefetch() lets a caller overlap the cache misses of a batch of insertions.
#include <cstdint>
#include <vector>

#include "mesh/Mesh.h"

namespace mixengine {

class FaceSet {
  public:
    explicit FaceSet(std::size_t max_faces);

    /// Records the face's vertex set; false when that set was recorded before.
    bool insert(const Face& face);

    /// Hints that insert(face) follows soon.
    void prefetch(const Face& face) const { __builtin_prefetch(&slots_[slotOf(keyOf(face))]); }

  private:
    struct Key {
        std::uint32_t a, b, c;
        bool operator==(const Key&) const = default;
    };

    static Key keyOf(const Face& face);
    std::size_t slotOf(const Key& key) const;

    std::vector<Key> slots_;
    std::size_t mask_ = 0;
};

}  // namespace mixengine
