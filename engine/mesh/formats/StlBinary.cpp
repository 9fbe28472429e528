// Binary STL: 80-byte header, uint32 triangle count, then 50-byte little-endian records.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "common/Error.h"
#include "mesh/MemoryHint.h"
#include "mesh/formats/MessageText.h"
#include "mesh/formats/StlFormats.h"

namespace mixengine {

static_assert(std::endian::native == std::endian::little,
              "the binary STL reader assumes a little-endian host");

namespace {

std::uint32_t headerCount(std::string_view bytes) {
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, sizeof(count));
    return count;
}

/// Checks the counter against the data; warns when the records are intact but the counter or the
/// length is off, throws when a record is cut short. Returns the number of records to read.
std::size_t checkedRecordCount(std::string_view label, std::string_view bytes,
                               std::vector<std::string>& warnings) {
    if (bytes.size() < kStlHeaderBytes) {
        throw InputError(std::string(label) + ": too short for a binary STL header: " +
                         plural(bytes.size(), "byte") + ", need 84");
    }
    const std::uint64_t claimed = headerCount(bytes);
    const std::size_t available = (bytes.size() - kStlHeaderBytes) / kStlRecordBytes;
    const std::size_t stray = (bytes.size() - kStlHeaderBytes) % kStlRecordBytes;
    if (claimed > available && stray != 0) {
        throw InputError(std::string(label) + ": truncated binary STL: header says " +
                         plural(claimed, "triangle") + ", file holds " + std::to_string(available) + " and " +
                         plural(stray, "byte") + " of a cut one");
    }
    if (claimed != available) {
        warnings.push_back(std::string(label) + ": binary STL header says " + plural(claimed, "triangle") +
                           ", file holds " + std::to_string(available) + "; reading " +
                           std::to_string(available));
    }
    if (stray != 0) {
        warnings.push_back(std::string(label) + ": ignoring " + plural(stray, "trailing byte") +
                           " after the binary STL triangles");
    }
    return available;
}

}  // namespace

bool binaryStlSizeMatches(std::string_view bytes) {
    if (bytes.size() < kStlHeaderBytes) {
        return false;
    }
    const std::uint64_t expected = kStlHeaderBytes + kStlRecordBytes * std::uint64_t{headerCount(bytes)};
    return expected == bytes.size();
}

void readBinaryStl(std::string_view label, std::string_view bytes, TriangleSoup& soup,
                   std::vector<std::string>& warnings) {
    const std::size_t count = checkedRecordCount(label, bytes, warnings);
    soup.triangles.reserve(soup.triangles.size() + count);  // filled once, not zeroed first
    adviseHugePages(soup.triangles.data(), soup.triangles.capacity() * sizeof(soup.triangles[0]));
    std::size_t bad_normals = 0;
    const char* record = bytes.data() + kStlHeaderBytes;
    for (std::size_t i = 0; i < count; ++i, record += kStlRecordBytes) {
        float f[12];
        std::memcpy(f, record, sizeof(f));
        if (!std::isfinite(f[0]) || !std::isfinite(f[1]) || !std::isfinite(f[2])) {
            ++bad_normals;
        }
        for (int k = 3; k < 12; ++k) {
            if (!std::isfinite(f[k])) {
                throw InputError(std::string(label) + ": binary STL triangle " + std::to_string(i + 1) +
                                 " has a non-finite vertex coordinate (" + std::to_string(f[k]) + ")");
            }
        }
        soup.triangles.push_back({Vec3{f[3], f[4], f[5]}, Vec3{f[6], f[7], f[8]}, Vec3{f[9], f[10], f[11]}});
    }
    if (bad_normals != 0) {
        warnings.push_back(std::string(label) + ": " + plural(bad_normals, "triangle") +
                           " with a non-finite normal (normals are ignored)");
    }
}

}  // namespace mixengine
