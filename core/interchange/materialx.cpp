// MaterialX reader and writer (see materialx.h). Sections: reading · writing.
#include "interchange/materialx.h"

#include <cctype>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string_view>

#include "brdf/model_switch.h"
#include "interchange/material_values.h"
#include "interchange/materialx_graph.h"
#include "interchange/materialx_shaders.h"
#include "interchange/xml_document.h"
#include "texture/texture_edit.h"
#include "texture/texture_image.h"
#include "util/file_io.h"
#include "util/reference_confinement.h"
#include "util/referenced_file_error.h"
#include "util/text.h"

namespace glint {
namespace {

// --- reading --------------------------------------------------------------------------------

// The shortest decimal that reads back as the same float.
std::string shortestDecimal(float value) {
    char buffer[32];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
    return std::string(buffer, end);
}

// The image on `parameter` as a material texture, or a warning saying why it is not rendered (and
// the image kept as a texture reference). Its file is confined to the document's folder
// (util/reference_confinement.h).
// `key`: the texture's key in the material (the parameter, or a surface map's).
void addTexture(const std::string& parameter, const std::string& key, const MaterialXInput& input, const std::string& documentFile,
                ImportedMaterial& imported) {
    const MaterialXImage& image = *input.image;
    const auto warn = [&](const std::string& why) {
        imported.textures.push_back({parameter, image.file, ""});
        imported.warnings.push_back(makeError("warning: image '" + image.file + "' on '" + parameter + "' not rendered: " + why, input.where));
    };
    if (image.file.find("<UDIM>") != std::string::npos || image.file.find("<UVTILE>") != std::string::npos)
        return warn("Glint reads one image per texture, not UDIM tiles");
    if (static_cast<int>(imported.material.analytic()->textures.size()) >= kMaxMaterialTextures)
        return warn("a material holds at most " + std::to_string(kMaxMaterialTextures) + " textures");
    MaterialTexture texture;
    texture.parameter = key;
    texture.kind = TextureKind::Image;
    auto confined = confinedReference(image.file, {documentFile, input.where.line, input.where.column});
    if (!confined) return warn(confined.error().message);
    texture.file = confined->string();
    texture.colorSpace = image.colorSpace;
    texture.channel = image.channel.value_or(TextureChannel::R);
    texture.tiling = image.tiling;
    auto decoded = loadTextureImage(texture.file, texture.colorSpace);
    if (!decoded) return warn(referencedFileProblem(texture.file, decoded.error(), "image"));
    texture.image = *decoded;
    putTexture(*imported.material.analytic(), std::move(texture));  // table order, as every material keeps them
}

Result<ImportedMaterial> readMaterial(const MaterialXDocument& document, const std::string& name, const XmlElement& shader) {
    ImportedMaterial imported;
    auto inputs = readShaderInputs(document, shader, imported.warnings);
    if (!inputs) return inputs.error();
    const auto table = modelInfo(BrdfModel::OpenPbr).params;
    const MaterialXInputs openPbr = toOpenPbrInputs(shader.name, *inputs, table, imported.warnings);
    imported.material = Material::withDefaults(name, BrdfModel::OpenPbr);
    for (const auto& [parameter, input] : openPbr) {
        if (const char* map = surfaceMapOf(parameter)) {
            if (isNormalMapKey(map) && !input.image->normalMap)
                imported.warnings.push_back(makeError("warning: " + parameter + " is driven by an image without a normalmap node; "
                                                          "it is read as a tangent-space normal map", input.where));
            addTexture(parameter, map, input, document.file, imported);
            continue;
        }
        const ParamSpec& spec = table[findParam(table, parameter)];
        // MaterialX bounds few inputs (an index of 0 is valid there and harmless under a zero weight).
        const glm::vec3 kept = glm::clamp(input.value, glm::vec3(spec.validMin), glm::vec3(spec.validMax));
        if (kept != input.value)
            imported.warnings.push_back(makeError("warning: '" + parameter + "' is outside Glint's range [" + shortestDecimal(spec.validMin) + ", " +
                                                      shortestDecimal(spec.validMax) + "]; read as the nearest value in it", input.where));
        setParam(imported.material, parameter, kept);
        if (input.image) addTexture(parameter, parameter, input, document.file, imported);
    }
    GLINT_CHECK(!findOutOfRange(imported.material));
    return imported;
}

// "1.39" → 139; 0 when the attribute is missing or not a version.
int versionNumber(const std::string* version) {
    int major = 0, minor = 0;
    if (!version || std::sscanf(version->c_str(), "%d.%d", &major, &minor) != 2) return 0;
    return major * 100 + minor;
}

// --- writing --------------------------------------------------------------------------------

// MaterialX element names are identifiers ([A-Za-z_][A-Za-z0-9_]*; createValidName replaces
// the rest by '_'), unique in the document.
std::string uniqueName(const std::string& wanted, std::set<std::string>& taken) {
    std::string name = wanted.empty() ? "material" : wanted;
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') c = '_';
    if (std::isdigit(static_cast<unsigned char>(name[0]))) name = "_" + name;
    std::string candidate = name;
    for (int i = 2; taken.count(candidate); ++i) candidate = name + "_" + std::to_string(i);
    taken.insert(candidate);
    return candidate;
}

std::string relativePath(const std::string& file, const std::string& folder) {
    if (folder.empty()) return file;
    std::error_code error;
    const auto relative = std::filesystem::relative(file, folder, error);
    return error || relative.empty() ? file : relative.generic_string();
}

struct ShaderText {
    std::string graph;   // the node graph holding its images, empty when none
    std::string inputs;  // the shader's <input> lines
};

// The images of `material` as a node graph named `graphName`, and how each input connects to it.
void writeTextures(const Material& material, const std::string& graphName, const std::string& folder, ShaderText& text,
                   std::map<std::string, std::string>& connections, std::vector<Diagnostic>& warnings) {
    const auto table = paramTable(material);
    std::ostringstream graph;
    for (const MaterialTexture& texture : material.analytic()->textures) {
        const bool normal = texture.parameter == kNormalMapKey;
        const int index = normal ? -1 : findParam(table, texture.parameter);
        if (texture.parameter == kOcclusionMapKey) {
            warnings.push_back(makeError("warning: material '" + material.name +
                                         "': the occlusion map is not written (open_pbr_surface has no ambient-occlusion input)"));
            continue;
        }
        if (texture.parameter == kCoatNormalMapKey) {
            warnings.push_back(makeError("warning: material '" + material.name +
                                         "': the coat normal map is not written (geometry_coat_normal is left to the base's normal)"));
            continue;
        }
        if (texture.kind != TextureKind::Image) {
            warnings.push_back(makeError("warning: material '" + material.name + "': the procedural texture on '" + texture.parameter +
                                         "' is not written (MaterialX would need its own node graph); the constant is"));
            continue;
        }
        if (texture.gltfImage >= 0) {
            warnings.push_back(makeError("warning: material '" + material.name + "': the texture on '" + texture.parameter + "' is image " +
                                         std::to_string(texture.gltfImage) + " inside " + texture.file +
                                         " and is not written (MaterialX names image files); the constant is"));
            continue;
        }
        const bool scalar = !normal && table[index].kind == ParamKind::Scalar;
        const std::string image = texture.parameter + "_image";
        const std::string type = normal ? "vector3" : scalar ? "color4" : "color3";
        graph << "    <tiledimage name=\"" << image << "\" type=\"" << type << "\">\n"
              << "      <input name=\"file\" type=\"filename\" value=\"" << escapeMarkup(relativePath(texture.file, folder)) << "\""
              << (texture.colorSpace == TextureColorSpace::Srgb ? " colorspace=\"srgb_texture\"" : "") << " />\n"
              << "      <input name=\"uvtiling\" type=\"vector2\" value=\"" << shortestDecimal(texture.tiling.x) << ", "
              << shortestDecimal(texture.tiling.y) << "\" />\n"
              << "    </tiledimage>\n";
        std::string last = image;
        std::string outputType = normal ? "vector3" : scalar ? "float" : "color3";
        if (normal) {
            graph << "    <normalmap name=\"normal_map\" type=\"vector3\">\n"
                  << "      <input name=\"in\" type=\"vector3\" nodename=\"" << image << "\" />\n    </normalmap>\n";
            last = "normal_map";
        } else if (scalar) {
            const std::string channel = texture.parameter + "_channel";
            graph << "    <extract name=\"" << channel << "\" type=\"float\">\n"
                  << "      <input name=\"in\" type=\"color4\" nodename=\"" << image << "\" />\n"
                  << "      <input name=\"index\" type=\"integer\" value=\"" << static_cast<int>(texture.channel) << "\" />\n"
                  << "    </extract>\n";
            last = channel;
            if (texture.range != glm::vec2(0.0f, 1.0f)) {
                const std::string range = texture.parameter + "_range";
                graph << "    <remap name=\"" << range << "\" type=\"float\">\n"
                      << "      <input name=\"in\" type=\"float\" nodename=\"" << channel << "\" />\n"
                      << "      <input name=\"outlow\" type=\"float\" value=\"" << shortestDecimal(texture.range.x) << "\" />\n"
                      << "      <input name=\"outhigh\" type=\"float\" value=\"" << shortestDecimal(texture.range.y) << "\" />\n"
                      << "    </remap>\n";
                last = range;
            }
        }
        const std::string parameter = normal ? "geometry_normal" : texture.parameter;
        graph << "    <output name=\"" << parameter << "_out\" type=\"" << outputType << "\" nodename=\"" << last << "\" />\n";
        connections[parameter] = "nodegraph=\"" + graphName + "\" output=\"" + parameter + "_out\"";
    }
    if (!connections.empty()) text.graph = "  <nodegraph name=\"" + graphName + "\">\n" + graph.str() + "  </nodegraph>\n";
}

}  // namespace

Result<ImportedFile> parseMaterialX(std::string_view text, const std::string& file) {
    auto root = parseXml(text, file);
    if (!root) return root.error();
    MaterialXDocument document{&*root, file, {}};
    if (root->name != "materialx")
        return makeError("the root element is <" + root->name + ">, not <materialx>: not a MaterialX document", document.at(*root));
    ImportedFile imported;
    const int version = versionNumber(root->attribute("version"));
    if (version < 138)
        imported.warnings.push_back(makeError("warning: MaterialX version '" + (root->attribute("version") ? *root->attribute("version") : std::string()) +
                                              "' is older than 1.38: inputs are read by their 1.39 names", document.at(*root)));
    for (const XmlElement& child : root->children) {
        if (child.name == "xi:include")
            imported.warnings.push_back(makeError("warning: included documents are not read", document.at(child)));
        const std::string* name = child.attribute("name");
        if (!name) continue;
        if (!document.topLevel.emplace(*name, &child).second)
            return makeError("two elements are named '" + *name + "'", document.at(child));
    }
    // surfacematerials name the shaders; a document without any is read shader by shader.
    std::vector<std::pair<std::string, const XmlElement*>> shaders;
    std::set<std::string> unreadable;
    bool anyMaterial = false;
    for (const XmlElement& child : root->children) {
        if (child.name != "surfacematerial") continue;
        anyMaterial = true;
        const XmlElement* input = nullptr;
        for (const XmlElement& in : child.children)
            if (in.name == "input" && in.attribute("name") && *in.attribute("name") == "surfaceshader") input = &in;
        const std::string name = child.attribute("name") ? *child.attribute("name") : "material";
        if (!input || !input->attribute("nodename")) {
            imported.warnings.push_back(makeError("warning: material '" + name + "' has no surface shader", document.at(child)));
            continue;
        }
        const auto shader = document.topLevel.find(*input->attribute("nodename"));
        if (shader == document.topLevel.end())
            return makeError("material '" + name + "' names shader '" + *input->attribute("nodename") + "', which the document does not hold",
                             document.at(*input));
        if (!isReadableMaterialXShader(shader->second->name)) {
            unreadable.insert(shader->second->name);
            imported.warnings.push_back(makeError("warning: material '" + name + "' uses a " + shader->second->name +
                                                  " shader; Glint reads open_pbr_surface, standard_surface and gltf_pbr", document.at(child)));
            continue;
        }
        shaders.emplace_back(name, shader->second);
    }
    if (!anyMaterial)
        for (const XmlElement& child : root->children)
            if (isReadableMaterialXShader(child.name) && child.attribute("name")) shaders.emplace_back(*child.attribute("name"), &child);
    for (const auto& [name, shader] : shaders) {
        auto material = readMaterial(document, name, *shader);
        if (!material) return material.error();
        imported.materials.push_back(std::move(*material));
    }
    if (imported.materials.empty()) {
        std::string held;
        for (const std::string& category : unreadable) held += (held.empty() ? " (it holds " : ", ") + category;
        return makeError("no open_pbr_surface, standard_surface or gltf_pbr material" + held + (held.empty() ? "" : ")"),
                         document.at(*root));
    }
    return imported;
}

Result<ImportedFile> loadMaterialX(const std::string& path) { return parseTextFile(path, parseMaterialX); }

ExportedText writeMaterialX(std::span<const ImportedMaterial> materials, const std::string& folder) {
    ExportedText out;
    std::ostringstream text;
    text << "<?xml version=\"1.0\"?>\n<materialx version=\"1.39\" colorspace=\"lin_rec709\">\n";
    std::set<std::string> taken;
    for (const ImportedMaterial& source : materials) {
        GLINT_CHECK(source.material.analytic());  // exportMaterials converts the other kinds
        // An open_pbr_surface holds OpenPBR's parameters: another model is switched to it first.
        const ModelSwitch converted = switchModel(source.material, BrdfModel::OpenPbr);
        if (!converted.dropped.empty())
            out.warnings.push_back(makeError("warning: material '" + source.material.name + "' converted from " +
                                             modelInfo(source.material.analytic()->model).label + " to OpenPBR: " +
                                             converted.summary()));
        const Material& material = converted.material;
        const std::string materialName = uniqueName(material.name, taken);
        const std::string shaderName = uniqueName("SR_" + materialName, taken);
        ShaderText shader;
        std::map<std::string, std::string> connections;
        writeTextures(material, uniqueName("NG_" + materialName, taken), folder, shader, connections, out.warnings);
        text << shader.graph << "  <open_pbr_surface name=\"" << shaderName << "\" type=\"surfaceshader\">\n";
        const auto table = paramTable(material);
        for (size_t i = 0; i < table.size(); ++i) {
            const ParamSpec& spec = table[i];
            const glm::vec3 value = paramValue(material, spec.name);
            // Glint's own parameters are no inputs of open_pbr_surface: not written, a warning when set.
            static const std::map<std::string_view, const char*> kGlintOwn = {
                {"geometry_tangent_rotation", "°) is Glint's own; open_pbr_surface turns the tangent through geometry_tangent, which is not written"},
                {"geometry_thickness", " m) is Glint's own; open_pbr_surface's volume is the geometry, and it is not written"}};
            if (const auto own = kGlintOwn.find(spec.name); own != kGlintOwn.end()) {
                if (value.x != 0.0f)
                    out.warnings.push_back(makeError("warning: material '" + material.name + "': " + spec.name + " (" +
                                                     shortestDecimal(value.x) + own->second));
                continue;
            }
            const char* type = spec.kind == ParamKind::Bool ? "boolean" : componentCount(spec.kind) == 3 ? "color3" : "float";
            text << "    <input name=\"" << spec.name << "\" type=\"" << type << "\" ";
            if (const auto connection = connections.find(spec.name); connection != connections.end())
                text << connection->second;
            else if (spec.kind == ParamKind::Bool)
                text << "value=\"" << (value.x > 0.5f ? "true" : "false") << "\"";
            else if (componentCount(spec.kind) == 3)
                text << "value=\"" << shortestDecimal(value.r) << ", " << shortestDecimal(value.g) << ", " << shortestDecimal(value.b) << "\"";
            else
                text << "value=\"" << shortestDecimal(value.x) << "\"";
            text << " />\n";
        }
        if (const auto normal = connections.find("geometry_normal"); normal != connections.end())
            text << "    <input name=\"geometry_normal\" type=\"vector3\" " << normal->second << " />\n";
        text << "  </open_pbr_surface>\n"
             << "  <surfacematerial name=\"" << materialName << "\" type=\"material\">\n"
             << "    <input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"" << shaderName << "\" />\n"
             << "  </surfacematerial>\n";
    }
    text << "</materialx>\n";
    out.text = text.str();
    return out;
}

}  // namespace glint
