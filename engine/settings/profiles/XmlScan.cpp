#include "settings/profiles/XmlScan.h"

#include <cctype>
#include <map>

#include "common/Error.h"
#include "common/TextFile.h"

namespace mixengine {
namespace {

using Namespaces = std::map<std::string, std::string>;  ///< prefix ("" = default) → URI

void appendUtf8(std::string& out, unsigned long code) {
    if (code < 0x80) {
        out += static_cast<char>(code);
    } else if (code < 0x800) {
        out += static_cast<char>(0xC0 | (code >> 6));
        out += static_cast<char>(0x80 | (code & 0x3F));
    } else if (code < 0x10000) {
        out += static_cast<char>(0xE0 | (code >> 12));
        out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (code & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (code >> 18));
        out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (code & 0x3F));
    }
}

class Scanner {
  public:
    Scanner(std::string_view text, const std::string& source) : text_(text), source_(source) {}

    XmlElement document() {
        skipMisc();
        if (!at("<"))
            fail("no root element");
        XmlElement root = element(Namespaces{{"xml", "http://www.w3.org/XML/1998/namespace"}});
        skipMisc();
        if (pos_ < text_.size())
            fail("text after the root element");
        return root;
    }

  private:
    [[noreturn]] void fail(const std::string& problem) const {
        std::size_t line = 1;
        for (std::size_t i = 0; i < pos_ && i < text_.size(); ++i)
            line += text_[i] == '\n';
        throw InputError(source_ + ":" + std::to_string(line) + ": XML: " + problem);
    }

    bool at(std::string_view s) const { return text_.substr(pos_, s.size()) == s; }

    void skipPast(std::string_view end, const char* what) {
        std::size_t found = text_.find(end, pos_);
        if (found == std::string_view::npos)
            fail(std::string("unterminated ") + what);
        pos_ = found + end.size();
    }

    void skipSpace() {
        while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_])))
            ++pos_;
    }

    /// White space, comments, processing instructions and a DOCTYPE outside the root element.
    void skipMisc() {
        for (;;) {
            skipSpace();
            if (at("<?")) {
                skipPast("?>", "processing instruction");
            } else if (at("<!--")) {
                skipPast("-->", "comment");
            } else if (at("<!DOCTYPE")) {
                std::size_t close = text_.find('>', pos_);
                if (close == std::string_view::npos ||
                    text_.substr(pos_, close - pos_).find('[') != std::string_view::npos)
                    fail("DOCTYPE with an internal subset is not supported");
                pos_ = close + 1;
            } else {
                return;
            }
        }
    }

    std::string name() {
        std::size_t start = pos_;
        while (pos_ < text_.size()) {
            char c = text_[pos_];
            if (std::isspace(static_cast<unsigned char>(c)) || c == '=' || c == '>' || c == '/' || c == '<' ||
                c == '"' || c == '\'')
                break;
            ++pos_;
        }
        if (pos_ == start)
            fail("a name was expected");
        return std::string(text_.substr(start, pos_ - start));
    }

    /// Decodes character data up to (not including) `end`; entity and character references.
    std::string decode(std::string_view raw) {
        std::string out;
        for (std::size_t i = 0; i < raw.size(); ++i) {
            if (raw[i] != '&') {
                out += raw[i];
                continue;
            }
            std::size_t semi = raw.find(';', i);
            if (semi == std::string_view::npos)
                fail("'&' without ';'");
            std::string_view ref = raw.substr(i + 1, semi - i - 1);
            static const std::map<std::string_view, char> kNamed = {
                {"amp", '&'}, {"lt", '<'}, {"gt", '>'}, {"quot", '"'}, {"apos", '\''}};
            if (auto it = kNamed.find(ref); it != kNamed.end()) {
                out += it->second;
            } else if (ref.size() > 1 && ref[0] == '#') {
                const bool hex = ref[1] == 'x';
                const std::string digits(ref.substr(hex ? 2 : 1));
                if (digits.empty() || digits.find_first_not_of(hex ? "0123456789abcdefABCDEF"
                                                                   : "0123456789") != std::string::npos)
                    fail("bad character reference '&" + std::string(ref) + ";'");
                appendUtf8(out, std::stoul(digits, nullptr, hex ? 16 : 10));
            } else {
                fail("unknown entity '&" + std::string(ref) + ";'");
            }
            i = semi;
        }
        return out;
    }

    std::string attributeValue() {
        if (pos_ >= text_.size() || (text_[pos_] != '"' && text_[pos_] != '\''))
            fail("attribute value must be quoted");
        const char quote = text_[pos_++];
        std::size_t close = text_.find(quote, pos_);
        if (close == std::string_view::npos)
            fail("unterminated attribute value");
        std::string value = decode(text_.substr(pos_, close - pos_));
        pos_ = close + 1;
        return value;
    }

    static std::pair<std::string, std::string> splitQualified(const std::string& qualified) {
        auto colon = qualified.find(':');
        if (colon == std::string::npos)
            return {"", qualified};
        return {qualified.substr(0, colon), qualified.substr(colon + 1)};
    }

    void resolve(XmlElement& element, const std::string& qualified, const Namespaces& scope) {
        auto [prefix, local] = splitQualified(qualified);
        auto it = scope.find(prefix);
        if (it == scope.end() && !prefix.empty())
            fail("undeclared namespace prefix '" + prefix + "'");
        element.ns = it == scope.end() ? std::string() : it->second;
        element.name = local;
    }

    /// The start tag's attributes; returns true for an empty-element tag ("/>").
    bool attributes(XmlElement& element, Namespaces& scope) {
        for (;;) {
            skipSpace();
            if (at("/>")) {
                pos_ += 2;
                return true;
            }
            if (at(">")) {
                ++pos_;
                return false;
            }
            std::string key = name();
            skipSpace();
            if (!at("="))
                fail("attribute '" + key + "' has no value");
            ++pos_;
            skipSpace();
            std::string value = attributeValue();
            if (key == "xmlns")
                scope[""] = value;
            else if (key.rfind("xmlns:", 0) == 0)
                scope[key.substr(6)] = value;
            element.attributes.emplace_back(std::move(key), std::move(value));
        }
    }

    XmlElement element(Namespaces scope) {
        ++pos_;  // '<'
        XmlElement element;
        const std::string qualified = name();
        const bool empty = attributes(element, scope);
        resolve(element, qualified, scope);
        if (!empty)
            content(element, scope, qualified);
        return element;
    }

    void content(XmlElement& element, const Namespaces& scope, const std::string& qualified) {
        for (;;) {
            std::size_t lt = text_.find('<', pos_);
            if (lt == std::string_view::npos)
                fail("element <" + qualified + "> is not closed");
            if (element.children.empty())
                element.text += decode(text_.substr(pos_, lt - pos_));
            pos_ = lt;
            if (at("</")) {
                pos_ += 2;
                if (name() != qualified)
                    fail("closing tag does not match <" + qualified + ">");
                skipSpace();
                if (!at(">"))
                    fail("'>' expected");
                ++pos_;
                return;
            }
            if (at("<!--")) {
                skipPast("-->", "comment");
            } else if (at("<![CDATA[")) {
                std::size_t end = text_.find("]]>", pos_);
                if (end == std::string_view::npos)
                    fail("unterminated CDATA section");
                if (element.children.empty())
                    element.text += text_.substr(pos_ + 9, end - pos_ - 9);
                pos_ = end + 3;
            } else if (at("<?")) {
                skipPast("?>", "processing instruction");
            } else {
                element.children.push_back(this->element(scope));
            }
        }
    }

    std::string_view text_;
    const std::string& source_;
    std::size_t pos_ = 0;
};

}  // namespace

const std::string* XmlElement::attribute(std::string_view qualified_name) const {
    for (const auto& [key, value] : attributes) {
        if (key == qualified_name)
            return &value;
    }
    return nullptr;
}

std::vector<const XmlElement*> XmlElement::childrenNamed(std::string_view ns_uri,
                                                         std::string_view local) const {
    std::vector<const XmlElement*> found;
    for (const XmlElement& c : children) {
        if (c.ns == ns_uri && c.name == local)
            found.push_back(&c);
    }
    return found;
}

const XmlElement* XmlElement::child(std::string_view ns_uri, std::string_view local) const {
    for (const XmlElement& c : children) {
        if (c.ns == ns_uri && c.name == local)
            return &c;
    }
    return nullptr;
}

XmlElement parseXml(std::string_view text, const std::string& source) {
    const std::string normalised = normaliseLineEnds(text);
    std::string_view view = normalised;
    if (view.starts_with("\xEF\xBB\xBF"))
        view.remove_prefix(3);
    return Scanner(view, source).document();
}

}  // namespace mixengine
