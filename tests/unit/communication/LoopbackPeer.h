#pragma once
// Cura's side of a socket test: a listener on 127.0.0.1 (a free port) that accepts the engine's
// connection, with an optional small receive buffer (a slow reader whose window fills).
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace mixengine::unit {

class LoopbackPeer {
  public:
    /// `receive_buffer_bytes` > 0: SO_RCVBUF of the accepted connection (inherited from the listener).
    explicit LoopbackPeer(int receive_buffer_bytes = 0) {
        listener_ = ::socket(AF_INET, SOCK_STREAM, 0);
        if (receive_buffer_bytes > 0)
            ::setsockopt(listener_, SOL_SOCKET, SO_RCVBUF, &receive_buffer_bytes,
                         sizeof receive_buffer_bytes);
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        ::bind(listener_, reinterpret_cast<sockaddr*>(&address), sizeof address);
        ::listen(listener_, 1);
        socklen_t length = sizeof address;
        ::getsockname(listener_, reinterpret_cast<sockaddr*>(&address), &length);
        port_ = ntohs(address.sin_port);
    }
    ~LoopbackPeer() {
        closeConnection();
        ::close(listener_);
    }
    LoopbackPeer(const LoopbackPeer&) = delete;
    LoopbackPeer& operator=(const LoopbackPeer&) = delete;

    int port() const { return port_; }
    void accept() { connection_ = ::accept(listener_, nullptr, nullptr); }
    int connection() const { return connection_; }
    void closeConnection() {
        if (connection_ >= 0)
            ::close(connection_);
        connection_ = -1;
    }

  private:
    int listener_ = -1;
    int connection_ = -1;
    int port_ = 0;
};

}  // namespace mixengine::unit
