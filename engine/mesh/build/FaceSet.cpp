#include "mesh/build/FaceSet.h"

#include <algorithm>
#include <limits>

#include "mesh/MemoryHint.h"
#include "mesh/build/VertexWelder.h"

namespace mixengine {

namespace {

constexpr std::uint32_t kEmpty = std::numeric_limits<std::uint32_t>::max();

}  // namespace

FaceSet::FaceSet(std::size_t max_faces) {
    const std::size_t capacity = tableCapacity(2 * max_faces);
    slots_.reserve(capacity);
    adviseHugePages(slots_.data(), capacity * sizeof(Key));
    slots_.assign(capacity, Key{kEmpty, kEmpty, kEmpty});
    mask_ = capacity - 1;
}

FaceSet::Key FaceSet::keyOf(const Face& face) {
    std::uint32_t a = face.v[0];
    std::uint32_t b = face.v[1];
    std::uint32_t c = face.v[2];
    if (a > b) {
        std::swap(a, b);
    }
    if (b > c) {
        std::swap(b, c);
    }
    if (a > b) {
        std::swap(a, b);
    }
    return {a, b, c};
}

std::size_t FaceSet::slotOf(const Key& key) const {
    return mixHash(key.a, key.b, key.c) & mask_;
}

bool FaceSet::insert(const Face& face) {
    const Key key = keyOf(face);
    for (std::size_t slot = slotOf(key);; slot = (slot + 1) & mask_) {
        if (slots_[slot] == key) {
            return false;
        }
        if (slots_[slot].a == kEmpty) {
            slots_[slot] = key;
            return true;
        }
    }
}

}  // namespace mixengine
