// The element tree built from expat's callbacks (see xml_document.h).
#include "interchange/xml_document.h"

#include <expat.h>

#include <limits>
#include <string>

namespace glint {

const std::string* XmlElement::attribute(std::string_view key) const {
    for (const auto& [name, value] : attributes)
        if (name == key) return &value;
    return nullptr;
}

namespace {

struct TreeBuilder {
    XML_Parser parser;
    XmlElement root;                 // a holder: the document element becomes its only child
    std::vector<XmlElement*> open;   // the elements whose end tag is still to come
    bool tooDeep = false;
};

// Deeper nesting is refused: the tree is freed recursively, and no format read here nests deeply.
constexpr size_t kMaxDepth = 64;

void onStart(void* data, const XML_Char* name, const XML_Char** attributes) {
    auto* builder = static_cast<TreeBuilder*>(data);
    if (builder->open.size() > kMaxDepth) {
        builder->tooDeep = true;
        XML_StopParser(builder->parser, XML_FALSE);
        return;
    }
    XmlElement element;
    element.name = name;
    element.line = static_cast<int>(XML_GetCurrentLineNumber(builder->parser));
    element.column = static_cast<int>(XML_GetCurrentColumnNumber(builder->parser)) + 1;
    for (int i = 0; attributes[i]; i += 2) element.attributes.emplace_back(attributes[i], attributes[i + 1]);
    XmlElement* parent = builder->open.back();
    parent->children.push_back(std::move(element));
    builder->open.push_back(&parent->children.back());
}

void onEnd(void* data, const XML_Char*) { static_cast<TreeBuilder*>(data)->open.pop_back(); }

void onText(void* data, const XML_Char* text, int length) {
    static_cast<TreeBuilder*>(data)->open.back()->text.append(text, static_cast<size_t>(length));
}

}  // namespace

Result<XmlElement> parseXml(std::string_view text, const std::string& file) {
    if (text.size() > static_cast<size_t>(std::numeric_limits<int>::max()))
        return makeError("the file is too large to read as XML", {file, 0, 0});
    TreeBuilder builder;
    builder.parser = XML_ParserCreate("UTF-8");
    GLINT_CHECK(builder.parser != nullptr);
    builder.open.push_back(&builder.root);
    XML_SetUserData(builder.parser, &builder);
    XML_SetElementHandler(builder.parser, onStart, onEnd);
    XML_SetCharacterDataHandler(builder.parser, onText);
    XML_SetParamEntityParsing(builder.parser, XML_PARAM_ENTITY_PARSING_NEVER);
    // Pointers into children stay valid only while no sibling is added after them: an element's
    // children are appended only while it is the innermost open one, so earlier siblings are closed.
    const XML_Status status = XML_Parse(builder.parser, text.data(), static_cast<int>(text.size()), XML_TRUE);
    Result<XmlElement> result = makeError("no element", {file, 1, 1});
    if (builder.tooDeep) {
        result = makeError("elements nested more than " + std::to_string(kMaxDepth) + " deep",
                           {file, static_cast<int>(XML_GetCurrentLineNumber(builder.parser)),
                            static_cast<int>(XML_GetCurrentColumnNumber(builder.parser)) + 1});
    } else if (status != XML_STATUS_OK) {
        result = makeError(std::string("not well-formed XML: ") + XML_ErrorString(XML_GetErrorCode(builder.parser)),
                           {file, static_cast<int>(XML_GetCurrentLineNumber(builder.parser)),
                            static_cast<int>(XML_GetCurrentColumnNumber(builder.parser)) + 1});
    } else if (builder.root.children.size() == 1) {
        result = std::move(builder.root.children.front());
    }
    XML_ParserFree(builder.parser);
    return result;
}

}  // namespace glint
