#include "communication/arcus/WireFormat.h"

namespace mixengine {

std::uint32_t arcusTypeId(std::string_view full_name) {
    std::uint32_t hash = 2166136261u;
    for (const char c : full_name) {
        hash ^= static_cast<std::uint32_t>(static_cast<unsigned char>(c));
        hash *= 16777619u;
    }
    return hash;
}

std::array<unsigned char, 4> arcusWord(std::uint32_t value) {
    return {static_cast<unsigned char>(value >> 24), static_cast<unsigned char>(value >> 16),
            static_cast<unsigned char>(value >> 8), static_cast<unsigned char>(value)};
}

std::uint32_t arcusReadWord(const unsigned char* bytes) {
    return (std::uint32_t{bytes[0]} << 24) | (std::uint32_t{bytes[1]} << 16) |
           (std::uint32_t{bytes[2]} << 8) | std::uint32_t{bytes[3]};
}

std::array<unsigned char, kArcusHeaderBytes> arcusFrameHeader(std::uint32_t body_bytes,
                                                              std::uint32_t type_id) {
    std::array<unsigned char, kArcusHeaderBytes> bytes{};
    const std::uint32_t words[] = {kArcusHeader, body_bytes, type_id};
    for (std::size_t w = 0; w < 3; ++w) {
        const auto word = arcusWord(words[w]);
        for (std::size_t b = 0; b < 4; ++b)
            bytes[w * 4 + b] = word[b];
    }
    return bytes;
}

ArcusWordKind classifyArcusWord(std::uint32_t word) {
    if (word == kArcusKeepAlive)
        return ArcusWordKind::KeepAlive;
    if (word == kArcusClose)
        return ArcusWordKind::Close;
    if (word == kArcusHeader)
        return ArcusWordKind::Header;
    if ((word >> 16) == (kArcusHeader >> 16))
        return ArcusWordKind::WrongVersion;
    return ArcusWordKind::Garbage;
}

}  // namespace mixengine
