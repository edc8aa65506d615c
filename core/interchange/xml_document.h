// A small XML element tree read with expat (Debian's libexpat1-dev), each element with the line
// and column where it starts, so that readers of XML formats (MaterialX) can locate every
// message. Elements, attributes and character data only: no namespaces resolved, no DTD, no
// external entities (expat is told not to read any).
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "util/diagnostic.h"

namespace glint {

struct XmlElement {
    std::string name;
    std::vector<std::pair<std::string, std::string>> attributes;  // in document order
    std::vector<XmlElement> children;
    std::string text;  // character data directly inside, whitespace kept
    int line = 0;      // 1-based start of the element's tag
    int column = 0;

    // The attribute's value, or nullptr when it is absent.
    const std::string* attribute(std::string_view key) const;
};

// Parses `text`; `file` names it in messages. Not well-formed XML is an error at the line and
// column where expat stopped ("file:12:5: mismatched tag").
Result<XmlElement> parseXml(std::string_view text, const std::string& file);

}  // namespace glint
