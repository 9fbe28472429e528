#pragma once
// Whole-file input for the mesh readers.
//
// Contract:
//   - FileBytes::read() returns every byte of `file`, or throws InputError naming the file when it
//     cannot be opened or read (missing, a directory, permission denied, read error).
//   - Regular files are memory-mapped read-only and pre-faulted (no copy: a 41 MB STL maps in well
//     under a millisecond); other files (pipes, devices) are read into a buffer.
//   - An empty file gives an empty view; the format readers decide what that means.
//   - The view stays valid for the lifetime of the FileBytes object (move-only).
#include <cstddef>
#include <filesystem>
#include <memory>
#include <string_view>

namespace mixengine {

class FileBytes {
  public:
    static FileBytes read(const std::filesystem::path& file);

    FileBytes() = default;
    FileBytes(FileBytes&& other) noexcept;
    FileBytes& operator=(FileBytes&& other) noexcept;
    FileBytes(const FileBytes&) = delete;
    FileBytes& operator=(const FileBytes&) = delete;
    ~FileBytes();

    std::string_view view() const { return {data_, size_}; }
    std::size_t size() const { return size_; }

  private:
    const char* data_ = nullptr;
    std::size_t size_ = 0;
    bool mapped_ = false;             ///< data_ is an mmap of size_ bytes
    std::unique_ptr<char[]> buffer_;  ///< owns data_ when not mapped
};

}  // namespace mixengine
