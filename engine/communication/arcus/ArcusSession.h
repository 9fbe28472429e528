#pragma once
// The engine's end of Cura's socket (shared/reference/cura-integration.md §2, §6), over Debian's
// libArcus: Cura listens, the engine connects, waits idle for one Slice, sends its results and
// closes with the 0xF0F0F0F0 handshake. libArcus does the framing, the keep-alives and the
// handshake; this class adds the waiting, the error policy and the message type table.
//
// Error policy: a connection that cannot be made, a frame that cannot be parsed, an unknown
// message type or a peer that goes away are thrown as ProtocolError (one line naming what
// happened); the caller ends the process cleanly. Nothing here calls exit().
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>

#include <Arcus/Socket.h>
#include <Arcus/SocketListener.h>

#include "common/Error.h"
#include "common/Log.h"

namespace cura::proto {
class Slice;
}

namespace mixengine {

class ProtocolError : public InputError {
  public:
    using InputError::InputError;
};

class ArcusSession {
  public:
    explicit ArcusSession(Log& log);
    /// Closes the connection if it is still open (bounded, see close()).
    ~ArcusSession();
    ArcusSession(const ArcusSession&) = delete;
    ArcusSession& operator=(const ArcusSession&) = delete;

    /// Connects to the frontend; throws ProtocolError when not connected within `timeout`.
    void connect(const std::string& host, int port, std::chrono::milliseconds timeout);

    /// Waits (idle, as long as it takes) for the Slice message. Returns nullptr when the frontend
    /// closes the connection first. Other known messages are logged and ignored; a fatal socket
    /// error, an unknown type or an unparsable frame throws ProtocolError.
    std::shared_ptr<cura::proto::Slice> waitForSlice();

    /// Queues a message for sending; throws ProtocolError if the connection is gone.
    void send(const Arcus::MessagePtr& message);

    /// Sends what is queued, then the close request, and waits at most `timeout` for the
    /// frontend's answer. libArcus waits for that answer without a limit, so a frontend that
    /// never answers gets its socket abandoned (its thread ends with the process) instead of
    /// a hang.
    void close(std::chrono::milliseconds timeout);

  private:
    /// What the socket's thread reports, shared with the listener so that a late report after
    /// the session is gone still lands in live memory.
    struct Shared {
        std::mutex mutex;
        std::condition_variable changed;
        Arcus::SocketState::SocketState state = Arcus::SocketState::Initial;
        int pending_messages = 0;
        std::string failure;  ///< the first fatal or protocol error, empty when none
        Log* log = nullptr;   ///< cleared when the session ends
    };

    class Listener : public Arcus::SocketListener {
      public:
        explicit Listener(std::shared_ptr<Shared> shared) : shared_(std::move(shared)) {}
        void stateChanged(Arcus::SocketState::SocketState state) override;
        void messageReceived() override;
        void error(const Arcus::Error& error) override;

      private:
        std::shared_ptr<Shared> shared_;
    };

    void throwIfFailed() const;  // caller holds shared_->mutex

    /// Ends the socket's thread before the socket is destroyed. libArcus 4.13's ~Socket ends the
    /// process (a joinable std::thread is deleted) when the socket has already reached Closed or
    /// Error; reset() joins the thread in those states. A socket still Closing or Connecting
    /// reaches one of them shortly: this waits for that at most `timeout`, then abandons the
    /// socket (its thread ends with the process) rather than risk the abort.
    void joinSocketThread(std::chrono::milliseconds timeout);

    Log& log_;
    std::shared_ptr<Shared> shared_ = std::make_shared<Shared>();
    std::unique_ptr<Arcus::Socket> socket_ = std::make_unique<Arcus::Socket>();
    bool thread_started_ = false;  ///< connect() was called: libArcus runs the socket's thread
};

}  // namespace mixengine
