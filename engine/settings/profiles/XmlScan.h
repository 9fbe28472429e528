#pragma once
// A small, strict XML reader for Cura's material files (*.xml.fdm_material): elements, attributes,
// character data, comments, processing instructions, CDATA, a DOCTYPE without an internal subset,
// the five predefined entities and numeric character references. Namespaces are resolved:
// every element carries its namespace URI (from `xmlns` / `xmlns:prefix` declarations in scope)
// and its local name, as ElementTree's "{uri}local" tags do. Line ends are normalised to "\n".
// Not supported (an InputError): DTD internal subsets and entities other than the predefined ones.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mixengine {

struct XmlElement {
    std::string ns;                                               ///< namespace URI; "" when none is in scope
    std::string name;                                             ///< local name (prefix removed)
    std::vector<std::pair<std::string, std::string>> attributes;  ///< qualified names as written
    std::string text;  ///< character data before the first child element (ElementTree's .text)
    std::vector<XmlElement> children;

    /// The attribute called `qualified_name`; nullptr when absent.
    const std::string* attribute(std::string_view qualified_name) const;
    /// Direct children with namespace `ns` and local name `name`, in document order.
    std::vector<const XmlElement*> childrenNamed(std::string_view ns, std::string_view name) const;
    /// The first such child, or nullptr.
    const XmlElement* child(std::string_view ns, std::string_view name) const;
};

/// Parses a whole document and returns its root element. Throws InputError naming `source` and
/// the line of the first problem.
XmlElement parseXml(std::string_view text, const std::string& source);

}  // namespace mixengine
