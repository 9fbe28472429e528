#include "communication/OutputFile.h"

#include <unistd.h>

#include <cstdio>
#include <fstream>

#include "common/Error.h"

namespace mixengine {

void writeFileAtomically(const std::filesystem::path& path, std::string_view text) {
    writeFileAtomically(path, std::vector<std::string_view>{text});
}

void writeFileAtomically(const std::filesystem::path& path, const std::vector<std::string_view>& pieces) {
    namespace fs = std::filesystem;
    const fs::path temp = path.string() + ".tmp-" + std::to_string(::getpid());
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        if (!out)
            throw InputError(path.string() + ": cannot write output file");
        for (std::string_view text : pieces)
            out.write(text.data(), static_cast<std::streamsize>(text.size()));
        out.flush();
        if (!out) {
            out.close();
            std::error_code ignored;
            fs::remove(temp, ignored);
            throw InputError(path.string() + ": write failed (disk full?)");
        }
    }
    std::error_code ec;
    fs::rename(temp, path, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(temp, ignored);
        throw InputError(path.string() + ": cannot rename the finished file into place: " + ec.message());
    }
}

}  // namespace mixengine
