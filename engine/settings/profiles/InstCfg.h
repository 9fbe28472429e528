#pragma once
// Reader for Cura's instance-container files (*.inst.cfg: variants, qualities, intents), following
// the parser Uranium 4.13 really uses for them (UM/FastConfigParser.py), not Python's configparser:
//   - line ends are normalised first ("\r\n" and "\r" become "\n", as Python's text mode does);
//   - a section starts at a line "[name]" (name made of letters, digits and '_');
//   - inside a section, a line starting at column 0 with `key =` (the key without spaces, tabs, '=',
//     '!', '<', '>' or '[') starts an entry; any other line — indented, blank, or a comment without
//     '=' — continues the previous value. A value is the rest of its first line and its
//     continuation lines joined with '\n', trailing white space removed, and a tab right after each
//     line break dropped ("\n\t" → "\n").
//   - As in Uranium, "#key = value" is an entry named "#key"; no setting has such a name, so
//     selectProfiles() drops it later with every other unknown key.
// A value whose text starts with '=' is a formula: ContainerValue{text after '=', is_formula}.
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "settings/ProfileStack.h"

namespace mixengine {

struct InstCfgFile {
    std::string id;      ///< the container id: the file name without ".inst.cfg", URL-decoded
    std::string source;  ///< the path (or a label) used in error messages
    std::map<std::string, std::string, std::less<>> general;   ///< [general]: name, version, definition
    std::map<std::string, std::string, std::less<>> metadata;  ///< [metadata]: type, quality_type, ...
    std::vector<std::pair<std::string, std::string>> values;   ///< [values] as written, in file order

    /// The [general] or [metadata] entry `key` ([metadata] wins, as in Uranium's metadata dict);
    /// nullptr when absent.
    const std::string* meta(std::string_view key) const;
    const std::string& name() const;        ///< [general] name, or the id when it has none
    const std::string& definition() const;  ///< [general] definition ("" when missing)
};

/// Parses `text`. `id` is the container id, `source` names the file in errors. Throws InputError
/// when there is no [general] section or it lacks `definition`.
InstCfgFile parseInstCfg(std::string_view text, std::string id, std::string source);

/// Reads and parses `path`; the id is derived from the file name (Uranium's unquote_plus of the name
/// without ".inst.cfg"). Throws InputError naming the file when it cannot be read or parsed.
InstCfgFile readInstCfgFile(const std::filesystem::path& path);

/// A raw [values] text as a stack value: a leading '=' (after white space) makes it a formula.
ContainerValue containerValueFromText(const std::string& raw);

/// Python's urllib.parse.unquote_plus: '+' → ' ', "%XX" → the byte XX.
std::string unquotePlus(std::string_view text);

}  // namespace mixengine
