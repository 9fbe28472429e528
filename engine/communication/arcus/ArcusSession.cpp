#include "communication/arcus/ArcusSession.h"

#include <future>
#include <thread>

#include "Cura.pb.h"

namespace mixengine {
namespace {

using namespace std::chrono_literals;

/// Every message type of Cura.proto that may appear as a top-level frame, both directions.
void registerTypes(Arcus::Socket& socket) {
    socket.registerMessageType(&cura::proto::Slice::default_instance());
    socket.registerMessageType(&cura::proto::Layer::default_instance());
    socket.registerMessageType(&cura::proto::LayerOptimized::default_instance());
    socket.registerMessageType(&cura::proto::Progress::default_instance());
    socket.registerMessageType(&cura::proto::GCodeLayer::default_instance());
    socket.registerMessageType(&cura::proto::PrintTimeMaterialEstimates::default_instance());
    socket.registerMessageType(&cura::proto::SettingList::default_instance());
    socket.registerMessageType(&cura::proto::GCodePrefix::default_instance());
    socket.registerMessageType(&cura::proto::SlicingFinished::default_instance());
    socket.registerMessageType(&cura::proto::SettingExtruder::default_instance());
}

bool isEnded(Arcus::SocketState::SocketState state) {
    return state == Arcus::SocketState::Closing || state == Arcus::SocketState::Closed ||
           state == Arcus::SocketState::Error;
}

/// One printable line for an Arcus error (libArcus appends raw payload bytes to some messages).
std::string describe(const Arcus::Error& error) {
    switch (error.getErrorCode()) {
        case Arcus::ErrorCode::UnknownMessageTypeError:
            return "unknown message type (not in Cura.proto)";
        case Arcus::ErrorCode::ParseFailedError:
            return "a message failed to parse";
        case Arcus::ErrorCode::ConnectionResetError:
            return "the frontend reset the connection";
        default:
            break;
    }
    std::string text = error.getErrorMessage();
    for (char& c : text) {
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f)
            c = '?';
    }
    return text.empty() ? "socket error" : text;
}

}  // namespace

void ArcusSession::Listener::stateChanged(Arcus::SocketState::SocketState state) {
    std::lock_guard lock(shared_->mutex);
    shared_->state = state;
    shared_->changed.notify_all();
}

void ArcusSession::Listener::messageReceived() {
    std::lock_guard lock(shared_->mutex);
    ++shared_->pending_messages;
    shared_->changed.notify_all();
}

void ArcusSession::Listener::error(const Arcus::Error& error) {
    std::lock_guard lock(shared_->mutex);
    if (error.getErrorCode() == Arcus::ErrorCode::Debug) {
        if (shared_->log)
            shared_->log->debug("socket: " + error.getErrorMessage());
        return;
    }
    if (shared_->failure.empty())
        shared_->failure = describe(error);
    shared_->changed.notify_all();
}

ArcusSession::ArcusSession(Log& log) : log_(log) {
    shared_->log = &log;
    registerTypes(*socket_);
    socket_->addListener(new Listener(shared_));  // libArcus deletes its listeners with the socket
}

ArcusSession::~ArcusSession() {
    close(2s);
    if (socket_)
        joinSocketThread(2s);
    std::lock_guard lock(shared_->mutex);
    shared_->log = nullptr;
}

void ArcusSession::joinSocketThread(std::chrono::milliseconds timeout) {
    std::unique_lock lock(shared_->mutex);
    const bool settled = shared_->changed.wait_for(lock, timeout, [this] {
        return (!thread_started_ && shared_->state == Arcus::SocketState::Initial) ||
               shared_->state == Arcus::SocketState::Closed || shared_->state == Arcus::SocketState::Error;
    });
    lock.unlock();
    if (!settled) {
        static_cast<void>(socket_.release());  // abandoned on purpose: its thread is still running
        return;
    }
    // The listener hears of a state after libArcus has stored it, so the socket agrees here.
    const auto state = socket_->getState();
    if (state == Arcus::SocketState::Closed || state == Arcus::SocketState::Error)
        socket_->reset();
}

void ArcusSession::throwIfFailed() const {
    if (!shared_->failure.empty())
        throw ProtocolError("Cura socket: " + shared_->failure);
}

void ArcusSession::connect(const std::string& host, int port, std::chrono::milliseconds timeout) {
    log_.info("connecting to " + host + ":" + std::to_string(port));
    socket_->connect(host, port);
    thread_started_ = true;
    std::unique_lock lock(shared_->mutex);
    const bool settled = shared_->changed.wait_for(lock, timeout, [this] {
        return shared_->state != Arcus::SocketState::Initial &&
               shared_->state != Arcus::SocketState::Connecting;
    });
    // Connected, or already closing because the frontend asked at once: both were connections.
    const bool connected = shared_->state == Arcus::SocketState::Connected ||
                           shared_->state == Arcus::SocketState::Closing ||
                           shared_->state == Arcus::SocketState::Closed;
    if (!shared_->failure.empty() || !connected) {
        const std::string why = !shared_->failure.empty() ? shared_->failure
                                : settled                 ? "socket error"
                                                          : "timed out";
        throw ProtocolError("cannot connect to Cura at " + host + ":" + std::to_string(port) + ": " + why);
    }
}

std::shared_ptr<cura::proto::Slice> ArcusSession::waitForSlice() {
    for (;;) {
        {
            std::unique_lock lock(shared_->mutex);
            shared_->changed.wait(lock, [this] {
                return shared_->pending_messages > 0 || isEnded(shared_->state) || !shared_->failure.empty();
            });
            throwIfFailed();
            if (shared_->pending_messages == 0)
                return nullptr;  // the frontend closed the connection
            --shared_->pending_messages;
        }
        const Arcus::MessagePtr message = socket_->takeNextMessage();
        if (!message)
            continue;
        if (auto slice = std::dynamic_pointer_cast<cura::proto::Slice>(message))
            return slice;
        log_.warning("Cura socket: ignoring a " + message->GetTypeName() + " message (waiting for a Slice)");
    }
}

void ArcusSession::send(const Arcus::MessagePtr& message) {
    {
        std::lock_guard lock(shared_->mutex);
        throwIfFailed();
        if (isEnded(shared_->state))
            throw ProtocolError("Cura socket: the frontend closed the connection");
    }
    socket_->sendMessage(message);
}

void ArcusSession::close(std::chrono::milliseconds timeout) {
    if (!socket_)
        return;
    {
        std::lock_guard lock(shared_->mutex);
        if (shared_->state != Arcus::SocketState::Connected)
            return;
    }
    auto closed = std::make_shared<std::promise<void>>();
    std::future<void> done = closed->get_future();
    std::thread closer([socket = socket_.get(), closed] {
        socket->close();
        closed->set_value();
    });
    if (done.wait_for(timeout) == std::future_status::ready) {
        closer.join();
        return;
    }
    log_.warning("Cura did not answer the close request within " + std::to_string(timeout.count()) +
                 " ms; leaving the connection");
    closer.detach();
    static_cast<void>(socket_.release());  // abandoned on purpose: in use by the detached closer
}

}  // namespace mixengine
