#include "mesh/formats/ThreeMfPaint.h"

#include <zip.h>

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <string>

namespace mixengine {
namespace {

/// Reads hex digits backwards; past the start it gives -1.
class DigitsFromTheEnd {
  public:
    explicit DigitsFromTheEnd(std::string_view text) : text_(text), next_(text.size()) {}
    int next() {
        while (next_ > 0) {
            const char c = text_[--next_];
            if (c >= '0' && c <= '9')
                return c - '0';
            if (c >= 'a' && c <= 'f')
                return c - 'a' + 10;
            if (c >= 'A' && c <= 'F')
                return c - 'A' + 10;
        }
        return -1;
    }

  private:
    std::string_view text_;
    std::size_t next_;
};

constexpr int kMaxSplitDepth = 32;

/// Counts the leaf states of one (sub-)facet into `counts`; false on malformed input.
bool countLeaves(DigitsFromTheEnd& digits, std::vector<int>& counts, int depth) {
    const int code = digits.next();
    if (code < 0 || depth > kMaxSplitDepth)
        return false;
    const int split_sides = code & 3;
    if (split_sides == 0) {
        int state = code >> 2;
        if (state == 3) {
            const int extra = digits.next();
            if (extra < 0)
                return false;
            state += extra;
        }
        if (counts.size() <= static_cast<std::size_t>(state))
            counts.resize(static_cast<std::size_t>(state) + 1, 0);
        ++counts[static_cast<std::size_t>(state)];
        return true;
    }
    for (int child = 0; child <= split_sides; ++child) {
        if (!countLeaves(digits, counts, depth + 1))
            return false;
    }
    return true;
}

std::string readEntry(const std::filesystem::path& file, const char* entry) {
    int error = 0;
    std::unique_ptr<zip_t, int (*)(zip_t*)> archive(zip_open(file.c_str(), ZIP_RDONLY, &error), zip_close);
    if (!archive)
        return "";
    zip_stat_t stat;
    zip_stat_init(&stat);
    if (zip_stat(archive.get(), entry, ZIP_FL_NOCASE, &stat) != 0 || !(stat.valid & ZIP_STAT_SIZE))
        return "";
    std::unique_ptr<zip_file_t, int (*)(zip_file_t*)> in(zip_fopen(archive.get(), entry, ZIP_FL_NOCASE),
                                                         zip_fclose);
    if (!in)
        return "";
    std::string text(stat.size, '\0');
    const zip_int64_t got = zip_fread(in.get(), text.data(), stat.size);
    text.resize(got > 0 ? static_cast<std::size_t>(got) : 0);
    return text;
}

/// The local name of a tag or attribute ("m:triangle" → "triangle").
std::string_view localName(std::string_view name) {
    const auto colon = name.rfind(':');
    return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

/// The value of the attribute whose local name is `wanted` in the text of one tag ("" if absent).
std::string_view attribute(std::string_view tag, std::string_view wanted) {
    std::size_t at = 0;
    while ((at = tag.find('=', at)) != std::string_view::npos) {
        std::size_t name_end = at;
        while (name_end > 0 && tag[name_end - 1] == ' ')
            --name_end;
        std::size_t name_start = name_end;
        while (name_start > 0 && tag[name_start - 1] != ' ' && tag[name_start - 1] != '\t' &&
               tag[name_start - 1] != '\n')
            --name_start;
        const std::size_t quote = tag.find_first_of("\"'", at);
        if (quote == std::string_view::npos)
            return "";
        const std::size_t close = tag.find(tag[quote], quote + 1);
        if (close == std::string_view::npos)
            return "";
        if (localName(tag.substr(name_start, name_end - name_start)) == wanted)
            return tag.substr(quote + 1, close - quote - 1);
        at = close + 1;
    }
    return "";
}

}  // namespace

int paintedExtruder(std::string_view encoded) {
    DigitsFromTheEnd digits(encoded);
    std::vector<int> counts;
    if (encoded.empty() || !countLeaves(digits, counts, 0))
        return 0;
    const auto most = std::max_element(counts.begin(), counts.end());
    return static_cast<int>(most - counts.begin());
}

std::map<std::uint32_t, std::vector<int>> readPaintedFacets(const std::filesystem::path& file) {
    const std::string text = readEntry(file, "3D/3dmodel.model");
    std::map<std::uint32_t, std::vector<int>> painted;
    std::vector<int>* current = nullptr;
    std::vector<int> scratch;
    bool any = false;
    std::uint32_t current_id = 0;
    auto finishObject = [&] {
        if (current && any)
            painted[current_id] = *current;
    };
    for (std::size_t open = text.find('<'); open != std::string::npos; open = text.find('<', open + 1)) {
        const std::size_t close = text.find('>', open);
        if (close == std::string::npos)
            break;
        const std::string_view tag(text.data() + open + 1, close - open - 1);
        const std::string_view name = localName(tag.substr(0, tag.find_first_of(" \t\r\n/")));
        if (name == "object") {
            finishObject();
            scratch.clear();
            current = &scratch;
            any = false;
            current_id = static_cast<std::uint32_t>(
                std::strtoul(std::string(attribute(tag, "id")).c_str(), nullptr, 10));
        } else if (name == "triangle" && current) {
            std::string_view value = attribute(tag, "mmu_segmentation");
            if (value.empty())
                value = attribute(tag, "paint_color");
            current->push_back(paintedExtruder(value));
            any = any || current->back() != 0;
        }
        open = close;
    }
    finishObject();
    return painted;
}

}  // namespace mixengine
