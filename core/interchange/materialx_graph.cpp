// Following a MaterialX shader's inputs to values and images (see materialx_graph.h).
#include "interchange/materialx_graph.h"

#include <charconv>
#include <cmath>
#include <initializer_list>
#include <sstream>

#include "display/display_chain.h"
#include "util/text.h"

namespace glint {
namespace {

// Connections further than this are refused: a loop, or a graph no exporter writes.
constexpr int kMaxConnectionDepth = 32;

struct Resolved {
    std::optional<glm::vec3> value;   // a constant, linear Rec. 709
    std::optional<MaterialXImage> image;
    std::string unfollowed;           // why neither: "a 'multiply' node", ...
};

// The nearest of `chain` (innermost first) that has the attribute, as MaterialX inherits
// colorspace and fileprefix from an element's ancestors.
std::string inherited(std::string_view key, std::initializer_list<const XmlElement*> chain) {
    for (const XmlElement* element : chain)
        if (element)
            if (const std::string* value = element->attribute(key)) return *value;
    return {};
}

const XmlElement* childNamed(const XmlElement& parent, const std::string& name, std::string_view tag = {}) {
    for (const XmlElement& child : parent.children)
        if (const std::string* n = child.attribute("name"); n && *n == name && (tag.empty() || child.name == tag)) return &child;
    return nullptr;
}

// Rec. 709 primaries in the colour spaces of MaterialX's cmlib: linear, the sRGB curve, gamma 2.2.
std::optional<glm::vec3> toLinearRec709(glm::vec3 value, const std::string& space) {
    if (space.empty() || space == "lin_rec709" || space == "raw" || space == "none") return value;
    if (space == "srgb_texture") return glm::vec3(decodeSrgb(value.r), decodeSrgb(value.g), decodeSrgb(value.b));
    if (space == "g22_rec709") return glm::pow(glm::max(value, glm::vec3(0.0f)), glm::vec3(2.2f));
    return std::nullopt;
}

class GraphReader {
public:
    GraphReader(const MaterialXDocument& document, std::vector<Diagnostic>& warnings)
        : document_(document), warnings_(warnings) {}

    Result<Resolved> input(const XmlElement& input, const XmlElement* node, const XmlElement* graph, int depth) {
        const SourceLocation where = document_.at(input);
        if (depth > kMaxConnectionDepth) return makeError("connections nested more than 32 deep (a loop?)", where);
        const std::string* type = input.attribute("type");
        if (const std::string* value = input.attribute("value")) {
            if (!type) return makeError("input '" + name(input) + "' has a value but no type", where);
            if (*type == "filename" || *type == "string") return Resolved{};
            auto parsed = parseMaterialXValue(*value, *type, where);
            if (!parsed) return parsed.error();
            if (*type != "color3" && *type != "color4") return Resolved{*parsed, {}, {}};
            const std::string space = inherited("colorspace", {&input, node, graph, document_.root});
            const auto linear = toLinearRec709(*parsed, space);
            if (!linear) {
                warnings_.push_back(makeError("warning: colour space '" + space +
                                                  "' is not one Glint converts (lin_rec709, srgb_texture, g22_rec709); "
                                                  "the value is read as linear Rec. 709", where));
                return Resolved{*parsed, {}, {}};
            }
            return Resolved{*linear, {}, {}};
        }
        if (const std::string* graphName = input.attribute("nodegraph")) {
            const auto found = document_.topLevel.find(*graphName);
            if (found == document_.topLevel.end() || found->second->name != "nodegraph")
                return makeError("input '" + name(input) + "' connects to node graph '" + *graphName + "', which the document does not hold", where);
            const XmlElement& target = *found->second;
            const std::string* outputName = input.attribute("output");
            const XmlElement* output = nullptr;
            for (const XmlElement& child : target.children)
                if (child.name == "output" && (!outputName || name(child) == *outputName)) output = output ? output : &child;
            if (!output)
                return makeError("node graph '" + *graphName + "' has no output" + (outputName ? " '" + *outputName + "'" : std::string()), where);
            return this->output(*output, &target, depth + 1);
        }
        if (const std::string* nodeName = input.attribute("nodename")) {
            const XmlElement* target = graph ? childNamed(*graph, *nodeName) : nullptr;
            if (!graph) {
                const auto found = document_.topLevel.find(*nodeName);
                target = found == document_.topLevel.end() ? nullptr : found->second;
            }
            if (!target)
                return makeError("input '" + name(input) + "' connects to node '" + *nodeName + "', which " +
                                     (graph ? "node graph '" + name(*graph) + "'" : std::string("the document")) + " does not hold", where);
            const std::string* outputName = input.attribute("output");
            return this->node(*target, outputName ? *outputName : std::string(), graph, depth + 1);
        }
        if (input.attribute("interfacename"))
            return Resolved{{}, {}, "an interface input of a node graph with its own definition"};
        return Resolved{};
    }

private:
    static std::string name(const XmlElement& element) {
        const std::string* n = element.attribute("name");
        return n ? *n : element.name;
    }

    Result<Resolved> output(const XmlElement& output, const XmlElement* graph, int depth) {
        if (output.attribute("nodename") || output.attribute("value") || output.attribute("nodegraph"))
            return input(output, nullptr, graph, depth);
        return makeError("output '" + name(output) + "' connects to nothing", document_.at(output));
    }

    // The input `inputName` of node `node`, or nothing when the node does not set it.
    Result<Resolved> nodeInput(const XmlElement& node, std::string_view inputName, const XmlElement* graph, int depth) {
        for (const XmlElement& child : node.children)
            if (child.name == "input" && name(child) == inputName) return input(child, &node, graph, depth + 1);
        return Resolved{};
    }

    Result<Resolved> node(const XmlElement& node, const std::string& outputName, const XmlElement* graph, int depth) {
        const std::string& category = node.name;
        if (category == "constant" ) return nodeInput(node, "value", graph, depth);
        if (category == "dot" || category == "convert") return nodeInput(node, "in", graph, depth);
        if (category == "normalmap") {
            auto resolved = nodeInput(node, "in", graph, depth);
            if (resolved && resolved->image) resolved->image->normalMap = true;
            return resolved;
        }
        if (category == "separate3" || category == "separate4" || category == "extract") {
            auto resolved = nodeInput(node, "in", graph, depth);
            if (!resolved || !resolved->image) return resolved;
            int index = 0;
            if (category == "extract") {
                auto chosen = nodeInput(node, "index", graph, depth);
                if (!chosen) return chosen.error();
                index = chosen->value ? static_cast<int>(chosen->value->x) : 0;
            } else {
                const std::string suffix = outputName.size() == 4 ? outputName.substr(3) : std::string();
                index = suffix == "x" || suffix == "r" ? 0 : suffix == "y" || suffix == "g" ? 1 : suffix == "z" || suffix == "b" ? 2
                        : suffix == "w" || suffix == "a" ? 3 : -1;
            }
            if (index < 0 || index > 3) return Resolved{{}, {}, "a '" + category + "' output Glint does not know ('" + outputName + "')"};
            resolved->image->channel = static_cast<TextureChannel>(index);
            return resolved;
        }
        if (category == "image" || category == "tiledimage" || category == "gltf_image" || category == "gltf_colorimage" ||
            category == "gltf_normalmap")
            return image(node, outputName, graph, depth);
        return Resolved{{}, {}, "a '" + category + "' node"};
    }

    Result<Resolved> image(const XmlElement& node, const std::string& outputName, const XmlElement* graph, int depth) {
        const XmlElement* fileInput = childNamed(node, "file", "input");
        const std::string* file = fileInput ? fileInput->attribute("value") : nullptr;
        if (!file || trimmed(*file).empty()) return makeError("image node '" + name(node) + "' names no file", document_.at(node));
        MaterialXImage image;
        image.file = inherited("fileprefix", {fileInput, &node, graph, document_.root}) + std::string(trimmed(*file));
        const std::string space = inherited("colorspace", {fileInput, &node, graph, document_.root});
        if (space == "srgb_texture") {
            image.colorSpace = TextureColorSpace::Srgb;
        } else if (!space.empty() && space != "lin_rec709" && space != "raw" && space != "none") {
            warnings_.push_back(makeError("warning: image colour space '" + space + "' is read as linear Rec. 709", document_.at(*fileInput)));
        }
        if (const std::string* type = node.attribute("type"); type && *type == "float") image.channel = TextureChannel::R;
        if (node.name == "gltf_colorimage" && outputName == "outa") image.channel = TextureChannel::A;
        image.normalMap = node.name == "gltf_normalmap";
        const char* tilingInput = node.name == "tiledimage" ? "uvtiling" : node.name.rfind("gltf_", 0) == 0 ? "scale" : nullptr;
        if (tilingInput) {
            auto tiling = nodeInput(node, tilingInput, graph, depth);
            if (!tiling) return tiling.error();
            if (tiling->value) image.tiling = glm::vec2(tiling->value->x, tiling->value->y);
        }
        for (const XmlElement& child : node.children)
            if (child.name == "input" && (name(child) == "uvoffset" || name(child) == "offset" || name(child) == "rotate" ||
                                          name(child) == "texcoord"))
                warnings_.push_back(makeError("warning: image input '" + name(child) + "' is not carried (Glint's textures "
                                                  "have a tiling only)", document_.at(child)));
        return Resolved{{}, image, {}};
    }

    const MaterialXDocument& document_;
    std::vector<Diagnostic>& warnings_;
};

}  // namespace

Result<glm::vec3> parseMaterialXValue(const std::string& text, const std::string& type, SourceLocation where) {
    if (type == "boolean") {
        const std::string word(trimmed(text));
        if (word == "true") return glm::vec3(1.0f);
        if (word == "false") return glm::vec3(0.0f);
        return makeError("'" + text + "' is no boolean (true or false)", where);
    }
    const int count = type == "float" || type == "integer" ? 1 : type == "vector2" ? 2
                      : type == "color3" || type == "vector3" ? 3 : type == "color4" || type == "vector4" ? 4 : 0;
    if (count == 0) return makeError("inputs of type '" + type + "' are not read by Glint", where);
    glm::vec4 numbers(0.0f);
    std::stringstream parts(text);
    std::string part;
    int read = 0;
    while (std::getline(parts, part, ',')) {
        const std::string number(trimmed(part));
        float value = 0.0f;
        const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
        if (number.empty() || error != std::errc() || end != number.data() + number.size() || !std::isfinite(value))
            return makeError("'" + text + "' is not a " + type + " (" + std::to_string(count) + " comma-separated number" +
                                 (count > 1 ? "s" : "") + ")", where);
        if (read < 4) numbers[read] = value;
        ++read;
    }
    if (read != count)
        return makeError("'" + text + "' is not a " + type + ": " + std::to_string(count) + " number" + (count > 1 ? "s" : "") +
                             " expected, " + std::to_string(read) + " found", where);
    return count == 1 ? glm::vec3(numbers.x) : glm::vec3(numbers);
}

Result<MaterialXInputs> readShaderInputs(const MaterialXDocument& document, const XmlElement& shader,
                                         std::vector<Diagnostic>& warnings) {
    MaterialXInputs inputs;
    GraphReader reader(document, warnings);
    for (const XmlElement& child : shader.children) {
        if (child.name != "input") continue;
        const std::string* inputName = child.attribute("name");
        if (!inputName) return makeError("an input without a name", document.at(child));
        auto resolved = reader.input(child, &shader, nullptr, 0);
        if (!resolved) return resolved.error();
        if (!resolved->unfollowed.empty()) {
            warnings.push_back(makeError("warning: input '" + *inputName + "' is driven by " + resolved->unfollowed +
                                             ", which Glint does not evaluate; its default is used", document.at(child)));
            continue;
        }
        if (!resolved->value && !resolved->image) continue;
        inputs[*inputName] = MaterialXInput{resolved->value.value_or(glm::vec3(0.0f)), resolved->image, document.at(child)};
    }
    return inputs;
}

}  // namespace glint
