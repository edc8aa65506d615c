// Reading the inputs of one MaterialX shader node (MaterialX 1.38/1.39 documents): constant
// values in any of the colour spaces MaterialX names for Rec. 709 primaries, connections through
// node graphs to constants, and image nodes, which become texture references. What it cannot
// follow (a procedural graph, a multiply) is a warning and the input keeps its default. It does
// not know what the inputs mean; materialx_shaders.h maps them onto OpenPBR.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "interchange/xml_document.h"
#include "texture/material_texture.h"
#include "util/diagnostic.h"

namespace glint {

// An image an input reads: the file (fileprefix applied, relative to the document), how it is
// encoded, the channel a scalar reads (nothing: the first), its tiling and whether it is a
// tangent-space normal map.
struct MaterialXImage {
    std::string file;
    TextureColorSpace colorSpace = TextureColorSpace::Linear;
    std::optional<TextureChannel> channel;
    glm::vec2 tiling{1.0f, 1.0f};
    bool normalMap = false;
};

// One input the file sets: its value in linear Rec. 709 (scalars repeated in all three), or the
// image that drives it (value then holds the shader's default, filled in by the caller).
struct MaterialXInput {
    glm::vec3 value{0.0f};
    std::optional<MaterialXImage> image;
    SourceLocation where;
};
using MaterialXInputs = std::map<std::string, MaterialXInput>;  // by input name

// The document: the root element, top-level elements by name, the file name for messages.
struct MaterialXDocument {
    const XmlElement* root = nullptr;
    std::string file;
    std::map<std::string, const XmlElement*> topLevel;
    SourceLocation at(const XmlElement& element) const { return {file, element.line, element.column}; }
};

// The inputs `shader` sets. Malformed values (a colour with two numbers, a connection to a node
// that does not exist) are errors; graphs it cannot follow are warnings.
Result<MaterialXInputs> readShaderInputs(const MaterialXDocument& document, const XmlElement& shader,
                                         std::vector<Diagnostic>& warnings);

// A value attribute of `type` ("float", "color3", "vector3", "boolean", "integer") as three
// floats; an error for anything else or a malformed number.
Result<glm::vec3> parseMaterialXValue(const std::string& text, const std::string& type, SourceLocation where);

}  // namespace glint
