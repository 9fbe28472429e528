#pragma once
// Asks the kernel to back a large, freshly reserved buffer with huge pages (Linux madvise, a hint
// that may be ignored). First-touch page faults dominate filling buffers of tens of megabytes in
// virtual machines; with 2 MB pages there are 512 times fewer. No effect below 4 MB.
#include <cstddef>

namespace mixengine {

void adviseHugePages(const void* data, std::size_t bytes);

}  // namespace mixengine
