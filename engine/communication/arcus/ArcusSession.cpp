#include "communication/arcus/ArcusSession.h"

#include <algorithm>
#include <cstdio>

#include "Cura.pb.h"
#include "communication/arcus/WireFormat.h"

namespace mixengine {
namespace {

using namespace std::chrono_literals;

constexpr auto kReadWait = 200ms;             ///< how often the reader looks whether to stop
constexpr std::size_t kBodyChunk = 1u << 20;  ///< a body grows as it arrives, never ahead of it

std::string hex(std::uint32_t value) {
    char text[16];
    std::snprintf(text, sizeof text, "0x%08x", value);
    return text;
}

/// The full name of a Cura.proto message type with this id, or "" when there is none.
std::string curaTypeName(std::uint32_t type_id) {
    const google::protobuf::FileDescriptor* file = cura::proto::Slice::descriptor()->file();
    for (int i = 0; i < file->message_type_count(); ++i) {
        const std::string& name = file->message_type(i)->full_name();
        if (arcusTypeId(name) == type_id)
            return name;
    }
    return "";
}

std::string asText(const std::array<unsigned char, 4>& word) {
    return {reinterpret_cast<const char*>(word.data()), word.size()};
}

}  // namespace

ArcusSession::ArcusSession(Log& log) : log_(log) {}

ArcusSession::~ArcusSession() {
    stopping_ = true;
    stream_.shutdownBoth();
    if (reader_.joinable())
        reader_.join();
}

void ArcusSession::connect(const std::string& host, int port, std::chrono::milliseconds timeout) {
    log_.info("connecting to " + host + ":" + std::to_string(port));
    const std::string why = TcpStream::connectTo(host, port, timeout, stream_);
    if (!why.empty())
        throw ProtocolError("cannot connect to Cura at " + host + ":" + std::to_string(port) + ": " + why);
    reader_ = std::thread([this] { readLoop(); });
}

void ArcusSession::readLoop() {
    while (readNext()) {
    }
}

bool ArcusSession::readExact(char* buffer, std::size_t size) {
    std::size_t done = 0;
    while (done < size) {
        std::size_t got = 0;
        const IoResult result = stream_.readSome(buffer + done, size - done, kReadWait, got);
        if (stopping_)
            return false;
        if (result == IoResult::Closed) {  // closed or reset without a close request: the talk is over
            markEnded(false);
            stream_.shutdownBoth();  // a writer waiting for room wakes up
            return false;
        }
        done += got;
    }
    return true;
}

bool ArcusSession::readNext() {
    unsigned char bytes[4];
    if (!readExact(reinterpret_cast<char*>(bytes), sizeof bytes))
        return false;
    const std::uint32_t word = arcusReadWord(bytes);
    switch (classifyArcusWord(word)) {
        case ArcusWordKind::KeepAlive:
            return true;
        case ArcusWordKind::Close:
            markEnded(true);
            sendCloseWord();  // the answer to Cura's request is the same word
            return false;
        case ArcusWordKind::Header:
            return readFrame();
        case ArcusWordKind::WrongVersion:
            fail("protocol version mismatch (header " + hex(word) + ", expected " + hex(kArcusHeader) + ")");
            return false;
        case ArcusWordKind::Garbage:
            break;
    }
    fail("Header mismatch (" + hex(word) + " is not a frame header)");
    return false;
}

bool ArcusSession::readFrame() {
    unsigned char words[8];
    if (!readExact(reinterpret_cast<char*>(words), sizeof words))
        return false;
    const std::uint32_t size = arcusReadWord(words);
    const std::uint32_t type_id = arcusReadWord(words + 4);
    if (size > kArcusMaxBodyBytes) {
        fail("a message of " + std::to_string(size) + " bytes is over libArcus's limit of " +
             std::to_string(kArcusMaxBodyBytes) + " bytes");
        return false;
    }
    std::string body;
    while (body.size() < size) {
        const std::size_t at = body.size();
        body.resize(at + std::min<std::size_t>(kBodyChunk, size - at));
        if (!readExact(body.data() + at, body.size() - at))
            return false;
    }
    dispatch(type_id, body);
    std::lock_guard lock(inbox_.mutex);
    return inbox_.failure.empty();
}

void ArcusSession::dispatch(std::uint32_t type_id, const std::string& body) {
    const std::string name = curaTypeName(type_id);
    if (name.empty())
        return fail("Unknown message type id " + hex(type_id) + " (not in Cura.proto)");
    if (name != cura::proto::Slice::descriptor()->full_name()) {
        log_.warning("Cura socket: ignoring a " + name + " message");
        return;
    }
    auto slice = std::make_unique<cura::proto::Slice>();
    if (!slice->ParseFromString(body))
        return fail("a Slice message of " + std::to_string(body.size()) + " bytes failed to parse");
    std::lock_guard lock(inbox_.mutex);
    inbox_.slices.push_back(std::move(slice));
    inbox_.changed.notify_all();
}

void ArcusSession::fail(const std::string& why) {
    std::lock_guard lock(inbox_.mutex);
    if (inbox_.failure.empty())
        inbox_.failure = why;
    inbox_.changed.notify_all();
}

void ArcusSession::markEnded(bool close_requested) {
    std::lock_guard lock(inbox_.mutex);
    inbox_.ended = true;
    inbox_.close_requested = inbox_.close_requested || close_requested;
    inbox_.changed.notify_all();
}

void ArcusSession::sendCloseWord() {
    std::lock_guard lock(write_mutex_);
    if (close_sent_)
        return;
    close_sent_ = true;
    stream_.writeUnit(asText(arcusWord(kArcusClose)));  // as libArcus: the word, then stop writing
    stream_.shutdownWrite();
}

void ArcusSession::throwIfEnded() {
    if (!inbox_.failure.empty())
        throw ProtocolError("Cura socket: " + inbox_.failure);
    if (inbox_.ended)
        throw CuraEnded(inbox_.close_requested ? "Cura asked to close the connection"
                                               : "Cura closed the connection");
}

std::unique_ptr<cura::proto::Slice> ArcusSession::waitForSlice() {
    std::unique_lock lock(inbox_.mutex);
    inbox_.changed.wait(lock,
                        [this] { return !inbox_.slices.empty() || inbox_.ended || !inbox_.failure.empty(); });
    if (!inbox_.failure.empty())
        throw ProtocolError("Cura socket: " + inbox_.failure);
    if (inbox_.slices.empty())
        return nullptr;
    std::unique_ptr<cura::proto::Slice> slice = std::move(inbox_.slices.front());
    inbox_.slices.pop_front();
    return slice;
}

void ArcusSession::checkOpen() {
    std::lock_guard lock(inbox_.mutex);
    throwIfEnded();
}

void ArcusSession::send(const google::protobuf::Message& message) {
    {
        std::lock_guard lock(inbox_.mutex);
        throwIfEnded();
    }
    const std::string body = message.SerializeAsString();
    const auto head =
        arcusFrameHeader(static_cast<std::uint32_t>(body.size()), arcusTypeId(message.GetTypeName()));
    std::lock_guard lock(write_mutex_);
    const bool written =
        !close_sent_ &&
        stream_.writeUnit({reinterpret_cast<const char*>(head.data()), head.size()}, body) == IoResult::Ok;
    if (!written) {
        markEnded(false);
        std::lock_guard inbox_lock(inbox_.mutex);
        throwIfEnded();
    }
}

void ArcusSession::close(std::chrono::milliseconds timeout) {
    {
        std::lock_guard lock(inbox_.mutex);
        if (inbox_.ended || !inbox_.failure.empty())
            return;
    }
    sendCloseWord();
    std::unique_lock lock(inbox_.mutex);
    if (!inbox_.changed.wait_for(lock, timeout, [this] { return inbox_.ended || !inbox_.failure.empty(); }))
        log_.warning("Cura did not answer the close request within " + std::to_string(timeout.count()) +
                     " ms; closing anyway");
}

void ArcusSession::end() {
    markEnded(false);
    stream_.shutdownBoth();
}

}  // namespace mixengine
