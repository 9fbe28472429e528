#include "mesh/formats/FileBytes.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>
#include <utility>

#include "common/Error.h"

namespace mixengine {

namespace {

/// Closes a POSIX file descriptor at scope exit.
struct Descriptor {
    int fd = -1;
    ~Descriptor() {
        if (fd >= 0) {
            ::close(fd);
        }
    }
};

[[noreturn]] void failRead(const std::filesystem::path& file, int error) {
    throw InputError(file.string() + ": cannot read model file: " + std::generic_category().message(error));
}

/// Reads a non-regular file (pipe, device) to its end.
std::unique_ptr<char[]> readStream(const std::filesystem::path& file, int fd, std::size_t& size) {
    std::size_t capacity = 1 << 16;
    auto buffer = std::make_unique_for_overwrite<char[]>(capacity);
    size = 0;
    for (;;) {
        if (size == capacity) {
            auto bigger = std::make_unique_for_overwrite<char[]>(capacity * 2);
            std::memcpy(bigger.get(), buffer.get(), size);
            buffer = std::move(bigger);
            capacity *= 2;
        }
        const ssize_t got = ::read(fd, buffer.get() + size, capacity - size);
        if (got < 0 && errno == EINTR) {
            continue;
        }
        if (got < 0) {
            failRead(file, errno);
        }
        if (got == 0) {
            return buffer;
        }
        size += static_cast<std::size_t>(got);
    }
}

}  // namespace

FileBytes FileBytes::read(const std::filesystem::path& file) {
    Descriptor in{::open(file.c_str(), O_RDONLY | O_CLOEXEC)};
    if (in.fd < 0) {
        failRead(file, errno);
    }
    struct stat info {};
    if (::fstat(in.fd, &info) != 0) {
        failRead(file, errno);
    }
    if (S_ISDIR(info.st_mode)) {
        throw InputError(file.string() + ": cannot read model file: it is a directory");
    }
    FileBytes bytes;
    if (!S_ISREG(info.st_mode)) {
        bytes.buffer_ = readStream(file, in.fd, bytes.size_);
        bytes.data_ = bytes.buffer_.get();
        return bytes;
    }
    bytes.size_ = static_cast<std::size_t>(info.st_size);
    if (bytes.size_ == 0) {
        return bytes;
    }
    void* map = ::mmap(nullptr, bytes.size_, PROT_READ, MAP_PRIVATE | MAP_POPULATE, in.fd, 0);
    if (map == MAP_FAILED) {
        failRead(file, errno);
    }
    bytes.data_ = static_cast<const char*>(map);
    bytes.mapped_ = true;
    return bytes;
}

FileBytes::FileBytes(FileBytes&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)),
      size_(std::exchange(other.size_, 0)),
      mapped_(std::exchange(other.mapped_, false)),
      buffer_(std::move(other.buffer_)) {}

FileBytes& FileBytes::operator=(FileBytes&& other) noexcept {
    std::swap(data_, other.data_);
    std::swap(size_, other.size_);
    std::swap(mapped_, other.mapped_);
    std::swap(buffer_, other.buffer_);
    return *this;
}

FileBytes::~FileBytes() {
    if (mapped_) {
        ::munmap(const_cast<char*>(data_), size_);
    }
}

}  // namespace mixengine
