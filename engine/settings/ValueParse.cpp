#include "settings/ValueParse.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>

#include "common/Error.h"

namespace mixengine {
namespace {

std::string_view trim(std::string_view text) {
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front())))
        text.remove_prefix(1);
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
        text.remove_suffix(1);
    return text;
}

[[noreturn]] void fail(std::string_view key, std::string_view text, std::string_view expected) {
    throw InputError("setting '" + std::string(key) + "': value '" + std::string(text) + "' is not " +
                     std::string(expected));
}

bool tryReal(std::string_view text, double& out) {
    text = trim(text);
    if (!text.empty() && text.front() == '+')
        text.remove_prefix(1);
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc() && end == text.data() + text.size() && std::isfinite(out);
}

// Reads nested lists of numbers. The nesting is bounded (settings need 3 levels at most), so that
// no input can exhaust the stack; the rest is linear in the text's length.
class TreeParser {
  public:
    static constexpr int kMaxDepth = 32;

    TreeParser(std::string_view key, std::string_view text) : key_(key), text_(text) {}

    NumberTree parseAll() {
        NumberTree tree = parseNode();
        skipSpace();
        if (pos_ != text_.size())
            fail(key_, text_, "a list of numbers");
        return tree;
    }

  private:
    void skipSpace() {
        while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_])))
            ++pos_;
    }
    NumberTree parseNode() {
        skipSpace();
        if (pos_ < text_.size() && (text_[pos_] == '[' || text_[pos_] == '(')) {
            if (++depth_ > kMaxDepth)
                fail(key_, text_, "a list of numbers nested at most " + std::to_string(kMaxDepth) + " deep");
            NumberTree list = parseList();
            --depth_;
            return list;
        }
        std::size_t start = pos_;
        while (pos_ < text_.size() && text_[pos_] != ',' && text_[pos_] != ']' && text_[pos_] != ')')
            ++pos_;
        NumberTree leaf;
        leaf.is_leaf = true;
        if (!tryReal(text_.substr(start, pos_ - start), leaf.number))
            fail(key_, text_, "a list of numbers");
        return leaf;
    }
    NumberTree parseList() {
        const char close = text_[pos_] == '[' ? ']' : ')';
        ++pos_;
        NumberTree list;
        skipSpace();
        if (pos_ < text_.size() && text_[pos_] == close) {
            ++pos_;
            return list;
        }
        while (true) {
            list.children.push_back(parseNode());
            skipSpace();
            if (pos_ >= text_.size())
                fail(key_, text_, "a closed list");
            if (text_[pos_] == close) {
                ++pos_;
                return list;
            }
            if (text_[pos_] != ',')
                fail(key_, text_, "a list of numbers");
            ++pos_;
            skipSpace();
            if (pos_ < text_.size() && text_[pos_] == close) {  // trailing comma
                ++pos_;
                return list;
            }
        }
    }

    std::string_view key_;
    std::string_view text_;
    std::size_t pos_ = 0;
    int depth_ = 0;
};

Path pathFromTree(std::string_view key, std::string_view text, const NumberTree& polygon) {
    Path path;
    for (const NumberTree& point : polygon.children) {
        if (point.is_leaf || point.children.size() != 2 || !point.children[0].is_leaf ||
            !point.children[1].is_leaf)
            fail(key, text, "a polygon of [x, y] points");
        path.push_back({mmToMicrons(point.children[0].number), mmToMicrons(point.children[1].number)});
    }
    return path;
}

}  // namespace

bool parseBool(std::string_view key, std::string_view text) {
    std::string lower(trim(text));
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if (lower == "true" || lower == "yes" || lower == "on" || lower == "1")
        return true;
    if (lower == "false" || lower == "no" || lower == "off" || lower == "0" || lower.empty())
        return false;
    double number = 0;
    if (tryReal(lower, number))
        return number != 0.0;
    fail(key, text, "a boolean (True/False)");
}

double parseReal(std::string_view key, std::string_view text) {
    double value = 0;
    if (!tryReal(text, value))
        fail(key, text, "a number");
    return value;
}

long long parseInteger(std::string_view key, std::string_view text) {
    double value = parseReal(key, text);
    if (std::fabs(value) > 9.0e15)
        fail(key, text, "an integer in range");
    return std::llround(value);
}

coord_um parseLengthMicrons(std::string_view key, std::string_view text) {
    double mm = parseReal(key, text);
    if (std::fabs(mm) > 1.0e9)
        fail(key, text, "a length in range");
    return mmToMicrons(mm);
}

double parseRatio(std::string_view key, std::string_view text) {
    return parseReal(key, text) / 100.0;
}

NumberTree parseNumberTree(std::string_view key, std::string_view text) {
    return TreeParser(key, text).parseAll();
}

std::vector<double> parseRealList(std::string_view key, std::string_view text) {
    NumberTree tree = parseNumberTree(key, text);
    std::vector<double> values;
    for (const NumberTree& child : tree.children) {
        if (!child.is_leaf)
            fail(key, text, "a list of numbers");
        values.push_back(child.number);
    }
    if (tree.is_leaf)
        fail(key, text, "a list of numbers");
    return values;
}

Path parsePolygonMicrons(std::string_view key, std::string_view text) {
    NumberTree tree = parseNumberTree(key, text);
    if (tree.is_leaf)
        fail(key, text, "a polygon");
    return pathFromTree(key, text, tree);
}

Paths parsePolygonsMicrons(std::string_view key, std::string_view text) {
    NumberTree tree = parseNumberTree(key, text);
    if (tree.is_leaf)
        fail(key, text, "a list of polygons");
    Paths paths;
    for (const NumberTree& polygon : tree.children) {
        if (polygon.is_leaf)
            fail(key, text, "a list of polygons");
        paths.push_back(pathFromTree(key, text, polygon));
    }
    return paths;
}

std::array<std::array<double, 3>, 3> parseMatrix3(std::string_view key, std::string_view text) {
    NumberTree tree = parseNumberTree(key, text);
    std::array<std::array<double, 3>, 3> m{};
    if (tree.is_leaf || tree.children.size() != 3)
        fail(key, text, "a 3x3 matrix");
    for (std::size_t r = 0; r < 3; ++r) {
        const NumberTree& row = tree.children[r];
        if (row.is_leaf || row.children.size() != 3)
            fail(key, text, "a 3x3 matrix");
        for (std::size_t c = 0; c < 3; ++c) {
            if (!row.children[c].is_leaf)
                fail(key, text, "a 3x3 matrix");
            m[r][c] = row.children[c].number;
        }
    }
    return m;
}

}  // namespace mixengine
