#pragma once
// Cura's socket framing (libArcus 4.13, shared/reference/cura-integration.md §2), as bytes on the wire.
//
// The stream is a sequence of 4-byte big-endian words and message bodies:
//   0x00000000                 keep-alive (skipped by the reader)
//   0xF0F0F0F0                 close request / close answer
//   0x2BAD0100 size type body  one message: signature 0x2BAD, protocol 1.0; `size` bytes of protobuf
//                              `body`; `type` the 32-bit FNV-1a hash of the message's full name
//                              ("cura.proto.GCodeLayer").
// Pure functions only; sockets live in communication/arcus/TcpStream.h.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace mixengine {

inline constexpr std::uint32_t kArcusKeepAlive = 0;
inline constexpr std::uint32_t kArcusClose = 0xF0F0F0F0u;
inline constexpr std::uint32_t kArcusHeader = 0x2BAD0100u;  ///< signature 0x2BAD, version 1.0
inline constexpr std::size_t kArcusHeaderBytes = 12;        ///< header, size and type words
/// libArcus refuses bodies above 500 MiB; so does the engine (a Slice carries whole meshes).
inline constexpr std::uint32_t kArcusMaxBodyBytes = 500u * 1024u * 1024u;

/// libArcus's message type id: 32-bit FNV-1a of the full type name.
std::uint32_t arcusTypeId(std::string_view full_name);

/// The 12 bytes that precede a body of `body_bytes` bytes of type `type_id`.
std::array<unsigned char, kArcusHeaderBytes> arcusFrameHeader(std::uint32_t body_bytes,
                                                              std::uint32_t type_id);

/// One big-endian word as bytes, and back.
std::array<unsigned char, 4> arcusWord(std::uint32_t value);
std::uint32_t arcusReadWord(const unsigned char* bytes);

/// What a first word announces. A header word with the right signature and another version is
/// WrongVersion; any other word is Garbage.
enum class ArcusWordKind { KeepAlive, Close, Header, WrongVersion, Garbage };
ArcusWordKind classifyArcusWord(std::uint32_t word);

}  // namespace mixengine
