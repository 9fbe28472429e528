#include "mesh/formats/ObjReader.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <unordered_map>

#include "common/Error.h"
#include "mesh/formats/FileBytes.h"
#include "mesh/formats/MessageText.h"
#include "mesh/formats/TextScan.h"

namespace mixengine {

namespace {

using Corner = std::uint32_t;
using IndexedTriangle = std::array<Corner, 3>;

struct ObjGroup {
    std::string name;
    std::vector<IndexedTriangle> triangles;
};

/// A positive index beyond the vertices read so far, checked once the whole file is read.
struct ForwardReference {
    std::size_t line = 0;
    std::uint64_t index = 0;  ///< 0-based
};

class ObjParser {
  public:
    ObjParser(std::string label, std::string default_name)
        : label_(std::move(label)), group_name_(std::move(default_name)) {}

    void parseLine(std::string_view line, std::size_t line_number);
    std::vector<TriangleSoup> finish(std::vector<std::string>& warnings) const;

  private:
    void parseVertex(TokenCursor& tokens);
    void parseFace(TokenCursor& tokens);
    Corner parseCorner(std::string_view token);
    void selectGroup(std::string_view rest_of_line);
    void noteIgnored(std::string_view keyword);
    [[noreturn]] void fail(const std::string& defect) const;

    std::string label_;
    std::string group_name_;
    std::size_t line_ = 0;
    std::vector<Vec3> vertices_;
    std::vector<ObjGroup> groups_;
    std::unordered_map<std::string, std::size_t> group_index_;
    std::size_t current_group_ = std::numeric_limits<std::size_t>::max();
    std::vector<Corner> polygon_;  ///< reused for every face
    std::vector<ForwardReference> forward_;
    std::size_t ignored_ = 0;
    std::string first_ignored_;
    std::size_t first_ignored_line_ = 0;
};

void ObjParser::fail(const std::string& defect) const {
    throw InputError(label_ + ": line " + std::to_string(line_) + ": " + defect);
}

void ObjParser::parseLine(std::string_view line, std::size_t line_number) {
    line_ = line_number;
    line = line.substr(0, line.find('#'));
    TokenCursor tokens(line);
    const std::string_view keyword = tokens.next();
    if (keyword == "v") {
        parseVertex(tokens);
    } else if (keyword == "f") {
        parseFace(tokens);
    } else if (keyword == "o" || keyword == "g") {
        selectGroup(line.substr(static_cast<std::size_t>(keyword.data() - line.data()) + 1));
    } else if (!keyword.empty() && keyword != "vt" && keyword != "vn" && keyword != "vp" && keyword != "s" &&
               keyword != "usemtl" && keyword != "mtllib") {
        noteIgnored(keyword);
    }
}

void ObjParser::parseVertex(TokenCursor& tokens) {
    double xyz[3];
    for (double& value : xyz) {
        const std::string_view token = tokens.next();
        if (token.empty()) {
            fail("vertex has fewer than 3 coordinates");
        }
        if (!parseNumber(token, value)) {
            fail("expected a number for a vertex coordinate, found " + quoteToken(token));
        }
        if (!std::isfinite(value)) {
            fail("non-finite vertex coordinate " + quoteToken(token));
        }
    }
    vertices_.push_back({xyz[0], xyz[1], xyz[2]});
}

Corner ObjParser::parseCorner(std::string_view token) {
    const std::string_view digits = token.substr(0, token.find('/'));
    long long index = 0;
    const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), index);
    if (digits.empty() || result.ec != std::errc() || result.ptr != digits.data() + digits.size()) {
        fail("bad face vertex index " + quoteToken(token));
    }
    const long long defined = static_cast<long long>(vertices_.size());
    if (index == 0) {
        fail("face vertex index 0 (OBJ indices start at 1)");
    }
    if (index < 0 && -index > defined) {
        fail("face vertex index " + std::to_string(index) + " out of range (" +
             plural(vertices_.size(), "vertex", "vertices") + " defined so far)");
    }
    const long long absolute = index < 0 ? defined + index : index - 1;
    if (absolute > static_cast<long long>(std::numeric_limits<Corner>::max())) {
        fail("face vertex index " + std::to_string(index) + " out of range");
    }
    if (absolute >= defined) {
        forward_.push_back({line_, static_cast<std::uint64_t>(absolute)});
    }
    return static_cast<Corner>(absolute);
}

void ObjParser::parseFace(TokenCursor& tokens) {
    polygon_.clear();
    for (std::string_view token = tokens.next(); !token.empty(); token = tokens.next()) {
        polygon_.push_back(parseCorner(token));
    }
    if (polygon_.size() < 3) {
        fail("face has " + std::to_string(polygon_.size()) + " corners, need at least 3");
    }
    if (current_group_ == std::numeric_limits<std::size_t>::max()) {
        const auto [it, inserted] = group_index_.try_emplace(group_name_, groups_.size());
        if (inserted) {
            groups_.push_back({group_name_, {}});
        }
        current_group_ = it->second;
    }
    auto& triangles = groups_[current_group_].triangles;
    for (std::size_t i = 1; i + 1 < polygon_.size(); ++i) {
        triangles.push_back({polygon_[0], polygon_[i], polygon_[i + 1]});
    }
}

void ObjParser::selectGroup(std::string_view rest_of_line) {
    std::size_t first = 0;
    std::size_t last = rest_of_line.size();
    while (first < last && isBlank(rest_of_line[first])) {
        ++first;
    }
    while (last > first && isBlank(rest_of_line[last - 1])) {
        --last;
    }
    if (first < last) {
        group_name_ = std::string(rest_of_line.substr(first, last - first));
    }
    current_group_ = std::numeric_limits<std::size_t>::max();
}

void ObjParser::noteIgnored(std::string_view keyword) {
    if (ignored_++ == 0) {
        first_ignored_ = std::string(keyword);
        first_ignored_line_ = line_;
    }
}

std::vector<TriangleSoup> ObjParser::finish(std::vector<std::string>& warnings) const {
    for (const ForwardReference& ref : forward_) {
        if (ref.index >= vertices_.size()) {
            throw InputError(label_ + ": line " + std::to_string(ref.line) + ": face vertex index " +
                             std::to_string(ref.index + 1) + " out of range (file defines " +
                             plural(vertices_.size(), "vertex", "vertices") + ")");
        }
    }
    if (ignored_ != 0) {
        warnings.push_back(label_ + ": ignoring " + plural(ignored_, "unsupported OBJ statement") +
                           " (first " + quoteToken(first_ignored_) + " on line " +
                           std::to_string(first_ignored_line_) + ")");
    }
    std::vector<TriangleSoup> parts;
    for (const ObjGroup& group : groups_) {
        TriangleSoup& soup = parts.emplace_back();
        soup.name = group.name;
        soup.triangles.reserve(group.triangles.size());
        for (const IndexedTriangle& t : group.triangles) {
            soup.triangles.push_back({vertices_[t[0]], vertices_[t[1]], vertices_[t[2]]});
        }
    }
    if (parts.empty()) {
        throw InputError(label_ + ": contains no triangles");
    }
    return parts;
}

}  // namespace

std::vector<TriangleSoup> readObj(const std::filesystem::path& file, std::vector<std::string>& warnings) {
    const std::string label = file.string();
    const FileBytes bytes = FileBytes::read(file);
    if (bytes.size() == 0) {
        throw InputError(label + ": empty file");
    }
    ObjParser parser(label, file.stem().string());
    const std::string_view text = bytes.view();
    std::size_t line_number = 1;
    for (std::size_t start = 0; start < text.size(); ++line_number) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) {
            end = text.size();
        }
        parser.parseLine(text.substr(start, end - start), line_number);
        start = end + 1;
    }
    return parser.finish(warnings);
}

}  // namespace mixengine
