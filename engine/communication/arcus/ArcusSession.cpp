#include "communication/arcus/ArcusSession.h"

#include "Cura.pb.h"

namespace mixengine {
namespace {

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

}  // namespace

void ArcusSession::Listener::stateChanged(Arcus::SocketState::SocketState state) {
    std::lock_guard lock(session_.mutex_);
    session_.state_ = state;
    session_.changed_.notify_all();
}

void ArcusSession::Listener::messageReceived() {
    std::lock_guard lock(session_.mutex_);
    ++session_.pending_messages_;
    session_.changed_.notify_all();
}

void ArcusSession::Listener::error(const Arcus::Error& error) {
    if (error.getErrorCode() == Arcus::ErrorCode::Debug) {
        session_.log_.debug("socket: " + error.getErrorMessage());
        return;
    }
    std::lock_guard lock(session_.mutex_);
    if (session_.failure_.empty())
        session_.failure_ = error.getErrorMessage().empty() ? "socket error" : error.getErrorMessage();
    session_.changed_.notify_all();
}

ArcusSession::ArcusSession(Log& log) : log_(log) {
    registerTypes(socket_);
    socket_.addListener(new Listener(*this));  // libArcus deletes its listeners with the socket
}

ArcusSession::~ArcusSession() {
    // libArcus 4.13 leaves its thread joinable when the socket ended in Error (its destructor
    // would then terminate the process); reset() joins it in that state.
    const auto state = socket_.getState();
    if (state == Arcus::SocketState::Error || state == Arcus::SocketState::Closed)
        socket_.reset();
}

void ArcusSession::throwIfFailed() {
    if (!failure_.empty())
        throw ProtocolError("Cura socket: " + failure_);
}

void ArcusSession::connect(const std::string& host, int port, std::chrono::milliseconds timeout) {
    log_.info("connecting to " + host + ":" + std::to_string(port));
    socket_.connect(host, port);
    std::unique_lock lock(mutex_);
    const bool settled = changed_.wait_for(lock, timeout, [this] {
        return state_ == Arcus::SocketState::Connected || isEnded(state_) || !failure_.empty();
    });
    if (!failure_.empty() || state_ != Arcus::SocketState::Connected) {
        const std::string why = !failure_.empty() ? failure_ : settled ? "connection closed" : "timed out";
        throw ProtocolError("cannot connect to Cura at " + host + ":" + std::to_string(port) + ": " + why);
    }
}

std::shared_ptr<cura::proto::Slice> ArcusSession::waitForSlice() {
    for (;;) {
        {
            std::unique_lock lock(mutex_);
            changed_.wait(lock,
                          [this] { return pending_messages_ > 0 || isEnded(state_) || !failure_.empty(); });
            throwIfFailed();
            if (pending_messages_ == 0)
                return nullptr;  // the frontend closed the connection
            --pending_messages_;
        }
        const Arcus::MessagePtr message = socket_.takeNextMessage();
        if (!message)
            continue;
        if (auto slice = std::dynamic_pointer_cast<cura::proto::Slice>(message))
            return slice;
        log_.warning("Cura socket: ignoring a " + message->GetTypeName() + " message (waiting for a Slice)");
    }
}

void ArcusSession::send(const Arcus::MessagePtr& message) {
    {
        std::lock_guard lock(mutex_);
        throwIfFailed();
        if (isEnded(state_))
            throw ProtocolError("Cura socket: the frontend closed the connection");
    }
    socket_.sendMessage(message);
}

void ArcusSession::close(std::chrono::milliseconds timeout) {
    {
        std::lock_guard lock(mutex_);
        if (isEnded(state_) || state_ == Arcus::SocketState::Initial)
            return;
    }
    socket_.close();
    std::unique_lock lock(mutex_);
    changed_.wait_for(lock, timeout, [this] { return state_ == Arcus::SocketState::Closed; });
}

}  // namespace mixengine
