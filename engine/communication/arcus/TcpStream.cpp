#include "communication/arcus/TcpStream.h"

#include <cerrno>
#include <cstddef>
#include <cstring>
#include <thread>

#include <fcntl.h>
#include <linux/sockios.h>
#include <linux/tcp.h>
#include <netdb.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <sys/uio.h>
#include <unistd.h>

#include "communication/arcus/WireFormat.h"

namespace mixengine {
namespace {

using Clock = std::chrono::steady_clock;

// tcp_info::tcpi_state values (Linux's include/net/tcp_states.h; <linux/tcp.h> does not name them).
constexpr unsigned kTcpEstablished = 1;
constexpr unsigned kTcpCloseWait = 8;

int remainingMs(Clock::time_point deadline) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    return left > 0 ? static_cast<int>(left) : 0;
}

/// Waits for a non-blocking connect() on `fd`; returns 0 or the errno that ended it.
int finishConnect(int fd, Clock::time_point deadline) {
    pollfd p{fd, POLLOUT, 0};
    int ready = 0;
    do {
        ready = ::poll(&p, 1, remainingMs(deadline));
    } while (ready < 0 && errno == EINTR);
    if (ready == 0)
        return ETIMEDOUT;
    int error = 0;
    socklen_t length = sizeof error;
    if (ready < 0 || ::getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &length) != 0)
        return errno;
    return error;
}

/// One attempt at `address`: a blocking, connected socket with Nagle off, or -1 with `error` set.
int connectOne(const addrinfo& address, Clock::time_point deadline, int& error) {
    const int fd =
        ::socket(address.ai_family, address.ai_socktype | SOCK_CLOEXEC | SOCK_NONBLOCK, address.ai_protocol);
    if (fd < 0) {
        error = errno;
        return -1;
    }
    error = ::connect(fd, address.ai_addr, address.ai_addrlen) == 0 ? 0 : errno;
    if (error == EINPROGRESS)
        error = finishConnect(fd, deadline);
    const int no_delay = 1;
    if (error == 0 && (::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK) != 0 ||
                       ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &no_delay, sizeof no_delay) != 0))
        error = errno;
    if (error != 0) {
        ::close(fd);
        return -1;
    }
    return fd;
}

int queuedBytes(int fd, unsigned long request) {
    int bytes = 0;
    return ::ioctl(fd, request, &bytes) == 0 ? bytes : -1;
}

/// Whether a unit written now starts a new segment whose first piece holds a whole frame header.
bool atFrameBoundary(int fd) {
    const int unsent = queuedBytes(fd, SIOCOUTQNSD);
    const int queued = queuedBytes(fd, SIOCOUTQ);  // read before the window: the estimate errs low
    if (unsent < 0 || queued < 0)
        return true;  // not a TCP socket we can ask: nothing to wait for
    if (unsent > 0)
        return false;
    tcp_info info{};
    socklen_t length = sizeof info;
    const bool has_window = ::getsockopt(fd, IPPROTO_TCP, TCP_INFO, &info, &length) == 0 &&
                            length >= offsetof(tcp_info, tcpi_snd_wnd) + sizeof info.tcpi_snd_wnd;
    if (has_window && info.tcpi_state != kTcpEstablished && info.tcpi_state != kTcpCloseWait)
        return true;  // the connection is going or gone: the write tells the caller
    if (!has_window)
        return queued == 0;
    const long long room = static_cast<long long>(info.tcpi_snd_wnd) - queued;
    return room >= static_cast<long long>(kArcusHeaderBytes);
}

}  // namespace

std::string TcpStream::connectTo(const std::string& host, int port, std::chrono::milliseconds timeout,
                                 TcpStream& out) {
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    addrinfo* found = nullptr;
    const std::string service = std::to_string(port);
    if (const int status = ::getaddrinfo(host.c_str(), service.c_str(), &hints, &found); status != 0)
        return gai_strerror(status);
    const Clock::time_point deadline = Clock::now() + timeout;
    int error = ENOENT;
    for (const addrinfo* a = found; a != nullptr && out.fd_ < 0; a = a->ai_next)
        out.fd_ = connectOne(*a, deadline, error);
    ::freeaddrinfo(found);
    if (out.fd_ >= 0)
        return "";
    return error == ETIMEDOUT ? "timed out" : std::strerror(error);
}

TcpStream::~TcpStream() {
    if (fd_ >= 0)
        ::close(fd_);
}

bool TcpStream::waitForFrameBoundary() {
    auto pause = std::chrono::microseconds(20);
    while (!atFrameBoundary(fd_)) {
        if (shut_down_)
            return false;
        std::this_thread::sleep_for(pause);
        pause = std::min(pause * 2, std::chrono::microseconds(2000));
    }
    return !shut_down_;
}

IoResult TcpStream::writeUnit(std::string_view head, std::string_view body) {
    if (fd_ < 0 || !waitForFrameBoundary())
        return IoResult::Closed;
    iovec parts[2] = {{const_cast<char*>(head.data()), head.size()},
                      {const_cast<char*>(body.data()), body.size()}};
    iovec* part = parts;
    int count = body.empty() ? 1 : 2;
    while (count > 0) {
        msghdr message{};
        message.msg_iov = part;
        message.msg_iovlen = static_cast<std::size_t>(count);
        const ssize_t sent = ::sendmsg(fd_, &message, MSG_NOSIGNAL);
        if (sent < 0 && errno == EINTR)
            continue;
        if (sent < 0)
            return IoResult::Closed;
        auto left = static_cast<std::size_t>(sent);
        while (count > 0 && left >= part->iov_len) {  // skip what went, resume inside a part
            left -= part->iov_len;
            ++part;
            --count;
        }
        if (count > 0) {
            part->iov_base = static_cast<char*>(part->iov_base) + left;
            part->iov_len -= left;
        }
    }
    return IoResult::Ok;
}

IoResult TcpStream::readSome(char* buffer, std::size_t size, std::chrono::milliseconds wait,
                             std::size_t& read) {
    read = 0;
    if (fd_ < 0 || shut_down_)
        return IoResult::Closed;
    pollfd p{fd_, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(wait.count()));
    if (ready < 0 && errno == EINTR)
        return IoResult::Timeout;
    if (ready == 0)
        return IoResult::Timeout;
    const ssize_t got = ready < 0 ? -1 : ::recv(fd_, buffer, size, 0);
    if (got < 0 && (errno == EINTR || errno == EAGAIN))
        return IoResult::Timeout;
    if (got <= 0)
        return IoResult::Closed;
    read = static_cast<std::size_t>(got);
    return IoResult::Ok;
}

void TcpStream::shutdownWrite() {
    if (fd_ >= 0)
        ::shutdown(fd_, SHUT_WR);
}

void TcpStream::shutdownBoth() {
    shut_down_ = true;
    if (fd_ >= 0)
        ::shutdown(fd_, SHUT_RDWR);
}

}  // namespace mixengine
