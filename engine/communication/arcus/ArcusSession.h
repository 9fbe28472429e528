#pragma once
// The engine's end of Cura's socket (shared/reference/cura-integration.md §2, §6): Cura listens, the
// engine connects, waits idle for one Slice, sends its results as they are made and closes with
// the 0xF0F0F0F0 handshake. The framing is libArcus 4.13's (communication/arcus/WireFormat.h),
// written by communication/arcus/TcpStream.h so that Cura's libArcus reads every frame whole.
//
// Threads: a reader thread takes Cura's frames (the Slice, keep-alives, the close request) from
// connect() until the session ends; send() writes on the caller's thread, one message at a time.
//
// Ends: when Cura ends the talk — its close request, the connection closed or reset, or end()
// (e.g. on SIGTERM) — waitForSlice() returns nullptr and send() throws CuraEnded; the caller stops
// and exits 0. A frame Cura's protocol does not allow (bad signature or version, an unknown type,
// a body that does not parse or is over 500 MiB) is a ProtocolError naming it. Nothing here calls
// exit(), and no thread outlives the session.
#include <chrono>
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "common/Error.h"
#include "common/Log.h"
#include "communication/arcus/TcpStream.h"

namespace google::protobuf {
class Message;
}
namespace cura::proto {
class Slice;
}

namespace mixengine {

/// A frame that breaks Cura's protocol, or a connection that cannot be made: exit 1, one line.
class ProtocolError : public InputError {
  public:
    using InputError::InputError;
};

/// Cura ended the talk (close request, connection gone, or end()): not an error, exit 0.
class CuraEnded : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

class ArcusSession {
  public:
    explicit ArcusSession(Log& log);
    ~ArcusSession();  ///< ends the talk if still open and joins the reader
    ArcusSession(const ArcusSession&) = delete;
    ArcusSession& operator=(const ArcusSession&) = delete;

    /// Connects to the frontend; throws ProtocolError when not connected within `timeout`.
    void connect(const std::string& host, int port, std::chrono::milliseconds timeout);

    /// Waits (idle, as long as it takes) for the Slice message; nullptr when Cura ends the talk
    /// first. Other messages of Cura.proto are logged and ignored.
    std::unique_ptr<cura::proto::Slice> waitForSlice();

    /// Writes one message of Cura.proto; returns once the kernel holds all of it (blocks while Cura
    /// is not reading). Throws CuraEnded or ProtocolError. Callable from any thread.
    void send(const google::protobuf::Message& message);

    /// Throws CuraEnded or ProtocolError when the talk has ended (a cheap check for long work).
    void checkOpen();

    /// After the last message: the close request, then waits at most `timeout` for Cura's answer.
    void close(std::chrono::milliseconds timeout);

    /// From any thread (a signal watcher): ends the talk now. Blocked calls return or throw CuraEnded.
    void end();

  private:
    struct Inbox {
        std::mutex mutex;
        std::condition_variable changed;
        std::deque<std::unique_ptr<cura::proto::Slice>> slices;
        bool ended = false;            ///< Cura closed, reset or asked to close; or end()
        bool close_requested = false;  ///< Cura sent its close request (to be answered)
        std::string failure;           ///< the protocol error that stopped the reader
    };

    void readLoop();
    /// Reads exactly `size` bytes; false when the talk ended or the reader is stopping.
    bool readExact(char* buffer, std::size_t size);
    /// One word or frame from Cura; false when reading stops (ended or failed).
    bool readNext();
    bool readFrame();
    void dispatch(std::uint32_t type_id, const std::string& body);
    void fail(const std::string& why);
    void markEnded(bool close_requested);
    /// The close word (a request or the answer to Cura's), once; then no more writing.
    void sendCloseWord();
    void throwIfEnded();  // caller holds inbox_.mutex

    Log& log_;
    TcpStream stream_;
    Inbox inbox_;
    std::mutex write_mutex_;   ///< one unit on the wire at a time
    bool close_sent_ = false;  ///< under write_mutex_
    std::atomic<bool> stopping_{false};
    std::thread reader_;
};

}  // namespace mixengine
