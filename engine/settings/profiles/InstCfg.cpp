#include "settings/profiles/InstCfg.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

#include "common/Error.h"
#include "common/TextFile.h"

namespace mixengine {
namespace {

bool isWordChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || static_cast<unsigned char>(c) >= 0x80;
}

/// Python's str.isspace() for the ASCII range FastConfigParser's "\s" sees here.
bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

std::vector<std::string_view> splitLines(std::string_view text) {
    std::vector<std::string_view> lines;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos)
            end = text.size();
        lines.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return lines;
}

/// The length of a "[name]" prefix of `line` (name: word characters), or 0.
std::size_t headerLength(std::string_view line) {
    if (line.empty() || line.front() != '[')
        return 0;
    std::size_t k = 1;
    while (k < line.size() && isWordChar(line[k]))
        ++k;
    return k > 1 && k < line.size() && line[k] == ']' ? k + 1 : 0;
}

constexpr std::string_view kBlanks = " \t";

/// The first position at or after `from` that is not a blank (' ', '\t'), or the line's end.
std::size_t skipBlanks(std::string_view line, std::size_t from) {
    return std::min(line.find_first_not_of(kBlanks, from), line.size());
}

/// A line at column 0 that starts a new entry; fills `key` and `rest` (the value's first line).
bool entryStart(std::string_view line, std::string& key, std::string_view& rest) {
    const std::size_t k = std::min(line.find_first_of("= \t!<>["), line.size());
    if (k == 0)
        return false;
    std::size_t p = skipBlanks(line, k);
    if (p >= line.size() || line[p] != '=')
        return false;
    ++p;
    // FastConfigParser wants a character other than '=' after "=[ \t]*" (a line end counts).
    if (p < line.size() && line[p] == '=')
        return false;
    key = std::string(line.substr(0, k));
    rest = line.substr(skipBlanks(line, p));
    return true;
}

std::string finishValue(std::string value) {
    while (!value.empty() && isSpace(value.back()))
        value.pop_back();
    for (std::size_t p = value.find("\n\t"); p != std::string::npos; p = value.find("\n\t", p + 1))
        value.erase(p + 1, 1);
    return value;
}

struct Section {
    std::string name;
    std::vector<std::pair<std::string, std::string>> entries;
};

std::vector<Section> parseSections(std::string_view text) {
    std::vector<Section> sections;
    bool in_value = false;
    for (std::string_view line : splitLines(text)) {
        std::string_view head = line;
        if (sections.empty()) {  // before the first section, an indented header is found too
            while (!head.empty() && (head.front() == ' ' || head.front() == '\t'))
                head.remove_prefix(1);
        }
        if (const std::size_t length = headerLength(head)) {
            // "[name]" alone on its line opens a section; "[name]..." only ends the previous one.
            std::string name =
                length == head.size() ? std::string(head.substr(1, length - 2)) : std::string();
            if (!name.empty() || !sections.empty())
                sections.push_back({std::move(name), {}});
            in_value = false;
            continue;
        }
        if (sections.empty())
            continue;
        std::string key;
        std::string_view rest;
        if (entryStart(line, key, rest)) {
            sections.back().entries.emplace_back(std::move(key), std::string(rest));
            in_value = true;
        } else if (in_value) {
            sections.back().entries.back().second += '\n';
            sections.back().entries.back().second += line;
        }
    }
    return sections;
}

}  // namespace

const std::string* InstCfgFile::meta(std::string_view key) const {
    if (auto it = metadata.find(key); it != metadata.end())
        return &it->second;
    if (auto it = general.find(key); it != general.end())
        return &it->second;
    return nullptr;
}

const std::string& InstCfgFile::name() const {
    const std::string* n = meta("name");
    return n ? *n : id;
}

const std::string& InstCfgFile::definition() const {
    static const std::string kNone;
    const std::string* d = meta("definition");
    return d ? *d : kNone;
}

InstCfgFile parseInstCfg(std::string_view text, std::string id, std::string source) {
    InstCfgFile file;
    file.id = std::move(id);
    file.source = std::move(source);
    for (Section& section : parseSections(normaliseLineEnds(text))) {
        for (auto& [key, raw] : section.entries) {
            std::string value = finishValue(std::move(raw));
            if (section.name == "general") {
                file.general[key] = std::move(value);
            } else if (section.name == "metadata") {
                file.metadata[key] = std::move(value);
            } else if (section.name == "values") {
                file.values.emplace_back(key, std::move(value));
            }
        }
    }
    if (!file.general.count("definition"))
        throw InputError(file.source + ": no [general] definition; not an instance container");
    return file;
}

InstCfgFile readInstCfgFile(const std::filesystem::path& path) {
    const std::string text = readTextFile(path);
    std::string name = path.filename().string();
    if (name.ends_with(".inst.cfg"))
        name.resize(name.size() - 9);
    return parseInstCfg(text, unquotePlus(name), path.string());
}

ContainerValue containerValueFromText(const std::string& raw) {
    std::size_t first = 0;
    while (first < raw.size() && isSpace(raw[first]))
        ++first;
    if (first < raw.size() && raw[first] == '=')
        return {raw.substr(first + 1), true};
    return {raw, false};
}

std::string unquotePlus(std::string_view text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '+') {
            out += ' ';
        } else if (text[i] == '%' && i + 2 < text.size() &&
                   std::isxdigit(static_cast<unsigned char>(text[i + 1])) &&
                   std::isxdigit(static_cast<unsigned char>(text[i + 2]))) {
            out += static_cast<char>(std::stoi(std::string(text.substr(i + 1, 2)), nullptr, 16));
            i += 2;
        } else {
            out += text[i];
        }
    }
    return out;
}

}  // namespace mixengine
