// Cura's socket framing on the wire (communication/arcus/WireFormat.h) and the writer that keeps
// every frame header whole for libArcus's reader (communication/arcus/TcpStream.h).
//
// The reader here reads as libArcus 4.13 does (Socket_p.h receiveNextMessage): each header word
// with one recv(fd, buf, 4), the body with recv(remaining); a header recv that returns 1 to 3
// bytes is what loses a message in Cura. It reads slowly, through a 4 KiB receive buffer, so the
// writer's queue backs up all the time — the condition under which Cura lost layer 23 (issue 29).
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <poll.h>
#include <sys/socket.h>

#include "communication/arcus/TcpStream.h"
#include "communication/arcus/WireFormat.h"
#include "unit/communication/LoopbackPeer.h"

namespace mixengine {
namespace {

TEST(WireFormat, TypeIdsAreLibArcusFnv1a) {
    // FNV-1a 32 of the full names (offset basis 2166136261, prime 16777619), computed by hand
    // from the definition: "" is the basis, "a" is (basis ^ 0x61) * prime mod 2^32.
    EXPECT_EQ(arcusTypeId(""), 2166136261u);
    EXPECT_EQ(arcusTypeId("a"), 0xe40c292cu);
    EXPECT_EQ(arcusTypeId("foobar"), 0xbf9cf968u);
}

TEST(WireFormat, FrameHeaderIsBigEndianSignatureSizeType) {
    const auto header = arcusFrameHeader(0x01020304u, 0xA0B0C0D0u);
    const std::vector<unsigned char> expected = {0x2B, 0xAD, 0x01, 0x00, 0x01, 0x02,
                                                 0x03, 0x04, 0xA0, 0xB0, 0xC0, 0xD0};
    EXPECT_EQ(std::vector<unsigned char>(header.begin(), header.end()), expected);
    EXPECT_EQ(arcusReadWord(header.data() + 8), 0xA0B0C0D0u);
}

TEST(WireFormat, WordsAreClassifiedAsLibArcusReadsThem) {
    EXPECT_EQ(classifyArcusWord(0), ArcusWordKind::KeepAlive);
    EXPECT_EQ(classifyArcusWord(0xF0F0F0F0u), ArcusWordKind::Close);
    EXPECT_EQ(classifyArcusWord(0x2BAD0100u), ArcusWordKind::Header);
    EXPECT_EQ(classifyArcusWord(0x2BAD0200u), ArcusWordKind::WrongVersion);
    EXPECT_EQ(classifyArcusWord(0x2BAD0101u), ArcusWordKind::WrongVersion);
    EXPECT_EQ(classifyArcusWord(0xDEADBEEFu), ArcusWordKind::Garbage);
}

/// A reader as slow as Cura's can be: a 4 KiB receive buffer, reading as libArcus reads.
class SlowPeer : public unit::LoopbackPeer {
  public:
    SlowPeer() : LoopbackPeer(4096) {}

    /// Reads `frames` frames as libArcus does; returns how many header words came short.
    int readLikeLibArcus(int frames, std::vector<std::string>& bodies, std::mt19937& random) {
        int short_words = 0;
        while (static_cast<int>(bodies.size()) < frames) {
            unsigned char words[3][4];
            for (auto& word : words) {
                const ssize_t got = recvWhenReadable(word, 4);
                if (got != 4)
                    return short_words + 1;  // libArcus has lost the framing here
            }
            if (arcusReadWord(words[0]) != kArcusHeader)
                return short_words + 1;
            std::string body(arcusReadWord(words[1]), '\0');
            for (std::size_t at = 0; at < body.size();) {
                const std::size_t want = std::min<std::size_t>(body.size() - at, 1 + random() % 3000);
                const ssize_t got = recvWhenReadable(body.data() + at, want);
                if (got <= 0)
                    return short_words + 1;
                at += static_cast<std::size_t>(got);
                if (random() % 8 == 0)
                    std::this_thread::sleep_for(std::chrono::microseconds(random() % 300));
            }
            bodies.push_back(std::move(body));
        }
        return short_words;
    }

  private:
    ssize_t recvWhenReadable(void* buffer, std::size_t size) {
        pollfd p{connection(), POLLIN, 0};
        if (::poll(&p, 1, 10'000) != 1)
            return -1;
        return ::recv(connection(), buffer, size, 0);  // one call, as libArcus
    }
};

/// `stream` connected to `peer`.
void connectTo(SlowPeer& peer, TcpStream& stream) {
    std::thread acceptor([&] { peer.accept(); });
    ASSERT_EQ(TcpStream::connectTo("127.0.0.1", peer.port(), std::chrono::seconds(5), stream), "");
    acceptor.join();
}

std::string frameBody(int n, std::mt19937& random) {
    std::string body(random() % 9000, '\0');
    for (std::size_t i = 0; i < body.size(); ++i)
        body[i] = static_cast<char>('a' + (n + i) % 26);
    return body;
}

TEST(TcpStream, EveryHeaderWordReachesASlowLibArcusReaderWhole) {
    SlowPeer peer;
    TcpStream stream;
    connectTo(peer, stream);

    constexpr int kFrames = 600;
    std::mt19937 write_random(29), read_random(2926);
    std::vector<std::string> sent;
    for (int n = 0; n < kFrames; ++n)
        sent.push_back(frameBody(n, write_random));
    std::vector<std::string> received;
    int short_words = 0;
    std::thread reader([&] { short_words = peer.readLikeLibArcus(kFrames, received, read_random); });
    for (const std::string& body : sent) {
        const auto head =
            arcusFrameHeader(static_cast<std::uint32_t>(body.size()), arcusTypeId("test.Frame"));
        ASSERT_EQ(stream.writeUnit({reinterpret_cast<const char*>(head.data()), head.size()}, body),
                  IoResult::Ok);
    }
    reader.join();
    EXPECT_EQ(short_words, 0);
    ASSERT_EQ(received.size(), sent.size());
    EXPECT_TRUE(received == sent);
}

TEST(TcpStream, ConnectingWhereNobodyListensSaysWhy) {
    int port = 0;
    {
        SlowPeer gone;  // a port that was free a moment ago and has nobody listening now
        port = gone.port();
    }
    TcpStream stream;
    EXPECT_EQ(TcpStream::connectTo("127.0.0.1", port, std::chrono::seconds(2), stream), "Connection refused");
    EXPECT_EQ(stream.writeUnit("abcd"), IoResult::Closed);
}

TEST(TcpStream, ShutdownWakesAWriterBlockedOnAPeerThatDoesNotRead) {
    SlowPeer peer;
    TcpStream stream;
    connectTo(peer, stream);
    std::atomic<bool> blocked_writer_returned{false};
    IoResult last = IoResult::Ok;
    std::thread writer([&] {
        const std::string body(64 * 1024, 'x');
        const auto head = arcusFrameHeader(static_cast<std::uint32_t>(body.size()), 1);
        for (int n = 0; n < 10'000 && last == IoResult::Ok; ++n)  // far more than the buffers hold
            last = stream.writeUnit({reinterpret_cast<const char*>(head.data()), head.size()}, body);
        blocked_writer_returned = true;
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    EXPECT_FALSE(blocked_writer_returned);  // the peer reads nothing: the writer waits
    stream.shutdownBoth();
    writer.join();
    EXPECT_EQ(last, IoResult::Closed);
}

}  // namespace
}  // namespace mixengine
