// The engine's end of Cura's socket (communication/arcus/ArcusSession.h) against a peer written
// here from libArcus 4.13's protocol: the Slice arrives, results go out framed, the close
// handshake in both directions, a malformed frame is one ProtocolError, and Cura ending the talk
// (close request, connection gone, end() on SIGTERM) reaches waitForSlice() and send() at once.
// These tests also run in the ThreadSanitizer build of tests/sanitize/run.sh.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <thread>

#include <poll.h>
#include <sys/socket.h>

#include "Cura.pb.h"
#include "communication/arcus/ArcusSession.h"
#include "communication/arcus/WireFormat.h"
#include "unit/communication/LoopbackPeer.h"

namespace mixengine {
namespace {

using namespace std::chrono_literals;

/// Cura's side: listens on a free port, accepts the engine, reads and writes raw Arcus bytes.
class Peer : public unit::LoopbackPeer {
  public:
    void write(const std::string& bytes) { ::send(connection(), bytes.data(), bytes.size(), MSG_NOSIGNAL); }
    void writeWord(std::uint32_t word) {
        const auto bytes = arcusWord(word);
        write({reinterpret_cast<const char*>(bytes.data()), bytes.size()});
    }
    void writeMessage(const google::protobuf::Message& message) {
        const std::string body = message.SerializeAsString();
        const auto head =
            arcusFrameHeader(static_cast<std::uint32_t>(body.size()), arcusTypeId(message.GetTypeName()));
        write(std::string(reinterpret_cast<const char*>(head.data()), head.size()) + body);
    }
    /// Exactly `size` bytes, or fewer when the engine closes first.
    std::string read(std::size_t size) {
        std::string bytes(size, '\0');
        std::size_t done = 0;
        while (done < size) {
            pollfd p{connection(), POLLIN, 0};
            if (::poll(&p, 1, 10'000) != 1)
                break;
            const ssize_t got = ::recv(connection(), bytes.data() + done, size - done, 0);
            if (got <= 0)
                break;
            done += static_cast<std::size_t>(got);
        }
        bytes.resize(done);
        return bytes;
    }
    std::uint32_t readWord() {
        const std::string bytes = read(4);
        return bytes.size() == 4 ? arcusReadWord(reinterpret_cast<const unsigned char*>(bytes.data()))
                                 : 0xFFFFFFFFu;
    }
};

struct Connected {
    std::ostringstream log_text;
    Log log{log_text, 2};
    Peer peer;
    ArcusSession session{log};
    Connected() {
        std::thread acceptor([this] { peer.accept(); });
        session.connect("127.0.0.1", peer.port(), 5s);
        acceptor.join();
    }
};

cura::proto::Slice oneSettingSlice() {
    cura::proto::Slice slice;
    cura::proto::Setting* setting = slice.mutable_global_settings()->add_settings();
    setting->set_name("layer_height");
    setting->set_value("0.2");
    return slice;
}

TEST(ArcusSession, TakesTheSliceSendsFramedResultsAndClosesWithTheHandshake) {
    Connected c;
    c.peer.writeWord(kArcusKeepAlive);  // libArcus sends these every 500 ms
    c.peer.writeMessage(oneSettingSlice());
    const std::unique_ptr<cura::proto::Slice> slice = c.session.waitForSlice();
    ASSERT_NE(slice, nullptr);
    EXPECT_EQ(slice->global_settings().settings(0).value(), "0.2");

    cura::proto::Progress progress;
    progress.set_amount(0.5f);
    c.session.send(progress);
    const std::string body = progress.SerializeAsString();
    EXPECT_EQ(c.peer.readWord(), kArcusHeader);
    EXPECT_EQ(c.peer.readWord(), body.size());
    EXPECT_EQ(c.peer.readWord(), arcusTypeId("cura.proto.Progress"));
    EXPECT_EQ(c.peer.read(body.size()), body);

    std::thread cura([&c] {
        EXPECT_EQ(c.peer.readWord(), kArcusClose);  // the engine asks to close …
        c.peer.writeWord(kArcusClose);              // … and Cura answers, as libArcus does
        c.peer.closeConnection();
    });
    c.session.close(5s);
    cura.join();
    EXPECT_EQ(c.log_text.str().find("did not answer"), std::string::npos);
    EXPECT_THROW(c.session.send(progress), CuraEnded);
}

TEST(ArcusSession, CurasCloseRequestBeforeASliceEndsTheWaitAndIsAnswered) {
    Connected c;
    c.peer.writeWord(kArcusClose);
    EXPECT_EQ(c.session.waitForSlice(), nullptr);
    EXPECT_EQ(c.peer.readWord(), kArcusClose);
    EXPECT_EQ(c.peer.read(1), "");  // then the engine stops writing
}

TEST(ArcusSession, EndFromAnotherThreadWakesTheWaitAndStopsSending) {
    Connected c;
    std::thread terminator([&c] {
        std::this_thread::sleep_for(50ms);
        c.session.end();
    });
    EXPECT_EQ(c.session.waitForSlice(), nullptr);
    terminator.join();
    cura::proto::Progress progress;
    EXPECT_THROW(c.session.send(progress), CuraEnded);
}

TEST(ArcusSession, ConnectionGoneMidSliceIsCuraEnded) {
    Connected c;
    c.peer.writeMessage(oneSettingSlice());
    ASSERT_NE(c.session.waitForSlice(), nullptr);
    c.peer.closeConnection();
    cura::proto::GCodeLayer layer;
    layer.set_data(std::string(1 << 16, 'G'));
    // The engine hears of it from its reader or from the write that fails, whichever is first.
    EXPECT_THROW(
        {
            for (int i = 0; i < 1000; ++i)
                c.session.send(layer);
        },
        CuraEnded);
}

std::string protocolErrorOf(Connected& c) {
    try {
        c.session.waitForSlice();
    } catch (const ProtocolError& e) {
        return e.what();
    }
    return "no ProtocolError";
}

TEST(ArcusSession, MalformedFramesAreOneProtocolErrorNamingWhat) {
    {
        Connected c;
        c.peer.writeWord(0xDEADBEEFu);
        EXPECT_EQ(protocolErrorOf(c), "Cura socket: Header mismatch (0xdeadbeef is not a frame header)");
    }
    {
        Connected c;
        c.peer.writeWord(0x2BAD0200u);
        EXPECT_EQ(protocolErrorOf(c),
                  "Cura socket: protocol version mismatch (header 0x2bad0200, expected 0x2bad0100)");
    }
    {
        Connected c;
        const auto head = arcusFrameHeader(2, arcusTypeId("cura.proto.NoSuchMessage"));
        c.peer.write(std::string(reinterpret_cast<const char*>(head.data()), head.size()) + "\x08\x01");
        EXPECT_EQ(
            protocolErrorOf(c), "Cura socket: Unknown message type id 0x" + [] {
                char hex[16];
                std::snprintf(hex, sizeof hex, "%08x", arcusTypeId("cura.proto.NoSuchMessage"));
                return std::string(hex);
            }() + " (not in Cura.proto)");
    }
    {
        Connected c;
        const auto head = arcusFrameHeader(kArcusMaxBodyBytes + 1, arcusTypeId("cura.proto.Slice"));
        c.peer.write(std::string(reinterpret_cast<const char*>(head.data()), head.size()));
        EXPECT_EQ(protocolErrorOf(c),
                  "Cura socket: a message of 524288001 bytes is over libArcus's limit of "
                  "524288000 bytes");
    }
}

}  // namespace
}  // namespace mixengine
