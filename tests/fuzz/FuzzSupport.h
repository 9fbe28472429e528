#pragma once
// Helpers shared by the libFuzzer targets (tests/fuzz/*_fuzz.cpp).
//
//   MemoryFile — an anonymous in-memory file (memfd) reachable by a path, so that the readers'
//                real path-based entry points (mmap, lib3mf's file reader) see each fuzz input
//                without touching the disk. Rewritten for every input.
//   buildAll() — runs buildMesh on every soup read, as the slice pipeline does after reading.
//
// A target catches exactly InputError (the engine's contract for bad input); any other exception
// escapes and libFuzzer reports it as a crash, as it does for sanitizer findings.
#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/Matrix3.h"
#include "mesh/build/MeshBuilder.h"
#include "mesh/formats/ModelReader.h"

namespace mixengine::fuzz {

class MemoryFile {
  public:
    explicit MemoryFile(const char* name) : fd_(::memfd_create(name, 0)) {
        if (fd_ < 0)
            throw std::runtime_error("memfd_create failed");
        path_ = "/proc/self/fd/" + std::to_string(fd_);
    }
    ~MemoryFile() { ::close(fd_); }
    MemoryFile(const MemoryFile&) = delete;
    MemoryFile& operator=(const MemoryFile&) = delete;

    /// Replaces the file's content with `size` bytes and returns its path.
    const std::filesystem::path& write(const std::uint8_t* data, std::size_t size) {
        if (::ftruncate(fd_, 0) != 0)
            throw std::runtime_error("ftruncate failed");
        std::size_t done = 0;
        while (done < size) {
            const ssize_t n = ::pwrite(fd_, data + done, size - done, static_cast<off_t>(done));
            if (n <= 0)
                throw std::runtime_error("pwrite failed");
            done += static_cast<std::size_t>(n);
        }
        return path_;
    }

  private:
    int fd_;
    std::filesystem::path path_;
};

inline void buildAll(const std::vector<TriangleSoup>& soups) {
    for (const TriangleSoup& soup : soups) {
        const Mesh mesh = buildMesh(soup, Matrix3{});
        (void)mesh.bounds();
    }
}

}  // namespace mixengine::fuzz
