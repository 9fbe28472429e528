// ASCII STL: `solid name` / `facet normal n n n` / `outer loop` / 3 x `vertex x y z` / `endloop` /
// `endfacet` / `endsolid name`, keywords in any case, any number of solid blocks.
#include <cmath>
#include <string>

#include "common/Error.h"
#include "mesh/formats/MessageText.h"
#include "mesh/formats/StlFormats.h"
#include "mesh/formats/TextScan.h"

namespace mixengine {

namespace {

class AsciiStlParser {
  public:
    AsciiStlParser(std::string_view label, std::string_view text, TriangleSoup& soup)
        : label_(label), cursor_(text), soup_(soup) {}

    void parse(std::vector<std::string>& warnings);

  private:
    void parseFacet();
    std::string_view facetToken();
    Vec3 readVertex();
    std::string_view skipNormal();  // returns the word after the normal
    [[noreturn]] void fail(const std::string& defect) const;

    std::string_view label_;
    TokenCursor cursor_;
    TriangleSoup& soup_;
    std::size_t solids_ = 0;
    std::size_t bad_normals_ = 0;
};

void AsciiStlParser::fail(const std::string& defect) const {
    throw InputError(std::string(label_) + ": line " + std::to_string(cursor_.line()) + ": " + defect);
}

void AsciiStlParser::parse(std::vector<std::string>& warnings) {
    bool in_solid = false;
    for (std::string_view token = cursor_.next(); !token.empty(); token = cursor_.next()) {
        if (sameWord(token, "facet")) {
            parseFacet();
        } else if (sameWord(token, "solid")) {
            ++solids_;
            in_solid = true;
            cursor_.skipRestOfLine();  // the solid's name
        } else if (sameWord(token, "endsolid")) {
            in_solid = false;
            cursor_.skipRestOfLine();
        } else {
            fail("unexpected " + quoteToken(token) + " in ASCII STL (expected 'facet' or 'endsolid')");
        }
    }
    const std::string prefix = std::string(label_) + ": ";
    if (solids_ > 1) {
        warnings.push_back(prefix + std::to_string(solids_) + " solid blocks merged into one part");
    }
    if (in_solid) {
        warnings.push_back(prefix + "ASCII STL ends without 'endsolid'");
    }
    if (bad_normals_ != 0) {
        warnings.push_back(prefix + plural(bad_normals_, "facet") +
                           " with a missing or non-finite normal (normals are ignored)");
    }
}

std::string_view AsciiStlParser::facetToken() {
    const std::string_view token = cursor_.next();
    if (token.empty()) {
        fail("file ends inside a facet (truncated ASCII STL)");
    }
    return token;
}

std::string_view AsciiStlParser::skipNormal() {
    // A normal may be missing altogether ("facet normal" then "outer loop"): the first word that
    // is not a number ends it and is handed back to the caller.
    bool good = true;
    for (int i = 0; i < 3; ++i) {
        double value = 0;
        const std::string_view token = facetToken();
        if (sameWord(token, "outer") || sameWord(token, "vertex")) {
            ++bad_normals_;
            return token;
        }
        if (!parseNumber(token, value) || !std::isfinite(value)) {
            good = false;
        }
    }
    if (!good) {
        ++bad_normals_;
    }
    return facetToken();
}

Vec3 AsciiStlParser::readVertex() {
    double xyz[3];
    for (double& value : xyz) {
        const std::string_view token = facetToken();
        if (!parseNumber(token, value)) {
            fail("expected a number for a vertex coordinate, found " + quoteToken(token));
        }
        if (!std::isfinite(value)) {
            fail("non-finite vertex coordinate " + quoteToken(token));
        }
    }
    return {xyz[0], xyz[1], xyz[2]};
}

void AsciiStlParser::parseFacet() {
    std::string_view token = facetToken();
    if (sameWord(token, "normal")) {
        token = skipNormal();
    } else {
        ++bad_normals_;
    }
    if (sameWord(token, "outer")) {
        if (!sameWord(facetToken(), "loop")) {
            fail("expected 'loop' after 'outer'");
        }
        token = facetToken();
    }
    std::array<Vec3, 3> triangle;
    std::size_t corners = 0;
    for (; sameWord(token, "vertex"); token = facetToken()) {
        if (corners == 3) {
            fail("facet has more than 3 vertices");
        }
        triangle[corners++] = readVertex();
    }
    if (sameWord(token, "endloop")) {
        token = facetToken();
    }
    if (!sameWord(token, "endfacet")) {
        fail("expected 'vertex' or 'endfacet', found " + quoteToken(token));
    }
    if (corners != 3) {
        fail("facet has " + plural(corners, "vertex", "vertices") + ", expected 3");
    }
    soup_.triangles.push_back(triangle);
}

bool isBinaryByte(unsigned char c) {
    return (c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\v' && c != '\f') || c == 0x7f;
}

}  // namespace

std::string_view asciiStlText(std::string_view bytes) {
    if (bytes.starts_with("\xEF\xBB\xBF")) {
        bytes.remove_prefix(3);
    }
    while (!bytes.empty() && (bytes.back() == '\0' || bytes.back() == '\x1A')) {
        bytes.remove_suffix(1);
    }
    return bytes;
}

bool looksLikeAsciiStl(std::string_view bytes) {
    std::size_t start = 0;
    while (start < bytes.size() && (isBlank(bytes[start]) || bytes[start] == '\n')) {
        ++start;
    }
    const std::string_view rest = bytes.substr(start);
    if (rest.size() < 5 || !sameWord(rest.substr(0, 5), "solid")) {
        return false;
    }
    if (rest.size() > 5 && !isBlank(rest[5]) && rest[5] != '\n') {
        return false;
    }
    for (const char c : bytes) {
        if (isBinaryByte(static_cast<unsigned char>(c))) {
            return false;
        }
    }
    return true;
}

void readAsciiStl(std::string_view label, std::string_view text, TriangleSoup& soup,
                  std::vector<std::string>& warnings) {
    AsciiStlParser parser(label, text, soup);
    parser.parse(warnings);
}

}  // namespace mixengine
