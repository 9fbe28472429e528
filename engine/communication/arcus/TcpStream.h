#pragma once
// The engine's TCP connection to Cura, written so that Cura's libArcus 4.13 always reads whole words.
//
// Why (issue 29): libArcus reads each of a frame's three header words with one recv(fd, buf, 4) and
// takes a short read as garbage — a short header word is dropped as if it were a keep-alive, a short
// size word is "Size invalid" — after which it has lost the framing and skips messages ("Header
// mismatch"). recv() returns less than 4 bytes whenever the receive queue ends inside a word, i.e.
// when a TCP segment boundary falls inside the first 12 bytes of a frame and the reader runs between
// the two segments. Boundaries land there when the sender's queue backs up: the kernel then appends
// a new write to the unsent tail of the queue (split where that buffer is full) or cuts a queued
// buffer where the peer's receive window ends — anywhere in the byte stream.
//
// So every unit (a frame or a lone word) is written with one call, and only when the socket is at a
// frame boundary: nothing unsent is queued (the unit starts a new segment) and the peer's window
// has room for at least a whole frame header past what is in flight (the first segment of the
// unit carries all of its header: Linux never sends less than the window allows, nor shrinks a
// window it has offered). Until then the writer waits in short sleeps; with a peer that keeps
// reading it never waits. Kernels without tcpi_snd_wnd (before 5.4) fall back to waiting until
// everything sent is acknowledged.
//
// Thread use: one thread writes, another may read at the same time; shutdownBoth() from any
// thread wakes both. Errors of the connection are values (IoResult), not exceptions.
#include <atomic>
#include <chrono>
#include <cstddef>
#include <string>
#include <string_view>

namespace mixengine {

enum class IoResult {
    Ok,       ///< all bytes written / some bytes read
    Timeout,  ///< nothing to read within the wait
    Closed    ///< the peer closed or reset the connection, or it was shut down here
};

class TcpStream {
  public:
    /// Connects to host:port (a name or an address, IPv4 or IPv6). Returns an empty string and
    /// sets `out` on success, else one line saying why (refused, timed out after `timeout`, …).
    static std::string connectTo(const std::string& host, int port, std::chrono::milliseconds timeout,
                                 TcpStream& out);

    TcpStream() = default;
    ~TcpStream();
    TcpStream(const TcpStream&) = delete;
    TcpStream& operator=(const TcpStream&) = delete;

    /// Writes `head` then `body` as one unit at a frame boundary (see above). Closed when the
    /// connection is gone or shut down while waiting or writing.
    IoResult writeUnit(std::string_view head, std::string_view body = {});

    /// Reads up to `size` bytes into `buffer`, waiting at most `wait`; `read` is how many arrived.
    IoResult readSome(char* buffer, std::size_t size, std::chrono::milliseconds wait, std::size_t& read);

    void shutdownWrite();  ///< no more writes (the peer reads end of stream after the last unit)
    void shutdownBoth();   ///< wakes a blocked reader and writer; both then see Closed

  private:
    /// Waits until a unit may start here; false when the stream was shut down meanwhile.
    bool waitForFrameBoundary();

    int fd_ = -1;
    std::atomic<bool> shut_down_{false};  ///< set by shutdownBoth(), read by the writer's wait
};

}  // namespace mixengine
