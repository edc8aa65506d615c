// Wavefront .mtl reader and writer (see mtl.h). Statement reference: Wavefront's "MTL material
// format (Lightwave, OBJ)" specification, Advanced Visualizer manual, Appendix B1.
// Sections: lexing · statements · illum mapping · reader entry points · writer.
#include "interchange/mtl.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>
#include <string_view>

#include "brdf/export_forms.h"
#include "brdf/fresnel.h"
#include "brdf/model_registry.h"
#include "interchange/material_values.h"
#include "interchange/text_checks.h"
#include "util/file_io.h"
#include "util/reference_confinement.h"
#include "util/text.h"

namespace glint {
namespace {

// --- lexing ---------------------------------------------------------------------------------

struct MtlError {
    Diagnostic diagnostic;
};

struct Line {
    const std::string* file;
    int number;
    std::vector<std::string> words;
    std::string rest;  // everything after the statement keyword, trimmed (names and paths keep spaces)

    [[noreturn]] void fail(const std::string& message) const {
        throw MtlError{makeError(message, {*file, number, 0})};
    }
    Diagnostic warning(const std::string& message) const { return makeError("warning: " + message, {*file, number, 0}); }

    float number_(size_t index, const char* what) const {
        if (index >= words.size()) fail("'" + words[0] + "' needs " + what);
        const std::string& word = words[index];
        float value = 0;
        const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
        if (error == std::errc::result_out_of_range) fail("'" + word + "' is out of range for a number");
        if (error != std::errc() || end != word.data() + word.size()) fail("'" + word + "' is not a number");
        if (!std::isfinite(value)) fail("'" + word + "' is not a finite number");
        return value;
    }
    void expectWords(size_t least, size_t most, const char* what) const {
        if (words.size() - 1 < least || words.size() - 1 > most) fail("'" + words[0] + "' takes " + what);
    }
};

std::vector<std::string> splitWords(const std::string& text) {
    std::vector<std::string> words;
    std::istringstream stream(text);
    for (std::string word; stream >> word;) words.push_back(word);
    return words;
}

std::string latin1ToUtf8(const std::string& bytes) {
    std::string text;
    for (const char c : bytes) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x80) {
            text += c;
        } else {
            text += static_cast<char>(0xC0 | (byte >> 6));
            text += static_cast<char>(0x80 | (byte & 0x3F));
        }
    }
    return text;
}

std::string hexByte(char c) {
    char text[3];
    std::snprintf(text, sizeof text, "%02x", static_cast<unsigned char>(c));
    return text;
}

// --- statements -----------------------------------------------------------------------------

// Valid MTL that Glint reads but does not use: a warning each.
const std::set<std::string> kUnusedStatements = {
    "Ke", "Tf", "sharpness", "map_Ka", "map_Ke", "disp", "decal", "refl", "map_aat", "map_refl",
    "Pr", "Pm", "Ps", "Pc", "Pcr", "aniso", "anisor", "map_Pr", "map_Pm", "map_Ps", "norm", "map_Ke"};
// Texture statements kept as references.
const std::set<std::string> kTextureStatements = {"map_Kd", "map_Ks", "map_Ns", "map_d", "map_bump", "bump"};
// Texture options and how many numbers or words follow each (-o, -s, -t take 1 to 3 numbers).
struct TextureOption {
    const char* name;
    int minArguments, maxArguments;
    bool wordArguments;  // on/off, a channel or a type name rather than numbers
};
constexpr TextureOption kTextureOptions[] = {
    {"-blendu", 1, 1, true}, {"-blendv", 1, 1, true}, {"-bm", 1, 1, false}, {"-boost", 1, 1, false},
    {"-cc", 1, 1, true},     {"-clamp", 1, 1, true},  {"-imfchan", 1, 1, true}, {"-mm", 2, 2, false},
    {"-o", 1, 3, false},     {"-s", 1, 3, false},     {"-t", 1, 3, false},     {"-texres", 1, 1, false},
    {"-type", 1, 1, true}};

bool isNumberWord(const std::string& word) {
    float value = 0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    return error == std::errc() && end == word.data() + word.size();
}

TextureReference readTexture(const Line& line) {
    TextureReference texture{line.words[0], "", ""};
    size_t index = 1;
    while (index < line.words.size() && line.words[index].size() > 1 && line.words[index][0] == '-') {
        const TextureOption* option = nullptr;
        for (const TextureOption& candidate : kTextureOptions)
            if (line.words[index] == candidate.name) option = &candidate;
        if (!option) line.fail("unknown texture option '" + line.words[index] + "'");
        size_t end = index + 1;
        while (end < line.words.size() && static_cast<int>(end - index - 1) < option->maxArguments &&
               (option->wordArguments || isNumberWord(line.words[end])))
            ++end;
        if (static_cast<int>(end - index - 1) < option->minArguments)
            line.fail("texture option '" + std::string(option->name) + "' needs " + std::to_string(option->minArguments) +
                      " value(s)");
        for (size_t i = index; i < end; ++i) texture.options += (texture.options.empty() ? "" : " ") + line.words[i];
        index = end;
    }
    if (index >= line.words.size()) line.fail("'" + line.words[0] + "' needs a file name");
    // The file name is the rest of the line: it may hold spaces.
    std::string path;
    for (size_t i = index; i < line.words.size(); ++i) path += (path.empty() ? "" : " ") + line.words[i];
    texture.path = path;
    return texture;
}

// One newmtl block as read, before it is mapped onto a Glint model.
struct MtlBlock {
    std::string name;
    int line = 0;
    glm::vec3 ambient{0.0f}, diffuse{0.8f}, specular{0.0f};  // the spec's defaults: Kd 0.8, Ks 0
    bool hasAmbient = false;
    float exponent = 0.0f;      // Ns
    float ior = 1.0f;           // Ni
    float dissolve = 1.0f;      // d (Tr = 1 − d)
    int illum = 2;              // the spec's default when absent is undefined; 2 is what exporters mean
    int dissolveLine = 0;
    std::vector<TextureReference> textures;
    std::vector<Diagnostic> warnings;  // what its statements held that Glint does not use
};

glm::vec3 readColor(const Line& line, std::vector<Diagnostic>& warnings, bool* used) {
    *used = true;
    if (line.words.size() >= 2 && (line.words[1] == "spectral" || line.words[1] == "xyz")) {
        warnings.push_back(line.warning("'" + line.words[0] + " " + line.words[1] +
                                        "' is valid MTL but Glint reads only RGB colours; the value is ignored"));
        *used = false;
        return glm::vec3(0.0f);
    }
    line.expectWords(1, 3, "one (grey) or three (r g b) numbers");
    if (line.words.size() == 3) line.fail("'" + line.words[0] + "' takes one (grey) or three (r g b) numbers, not two");
    const float red = line.number_(1, "a colour");
    glm::vec3 color(red);
    if (line.words.size() == 4) color = {red, line.number_(2, "g"), line.number_(3, "b")};
    for (int c = 0; c < 3; ++c)
        if (color[c] < 0.0f || color[c] > 1.0f)
            line.fail("'" + line.words[0] + "' component " + std::to_string(c) + " is " + std::to_string(color[c]) +
                      ": Glint's reflectances must be in [0, 1]");
    return color;
}

void readStatement(const Line& line, MtlBlock& block, std::vector<Diagnostic>& warnings) {
    const std::string& keyword = line.words[0];
    bool used = true;
    if (keyword == "Ka") {
        block.ambient = readColor(line, warnings, &used);
        block.hasAmbient = used;
    } else if (keyword == "Kd") {
        const glm::vec3 color = readColor(line, warnings, &used);
        if (used) block.diffuse = color;
    } else if (keyword == "Ks") {
        const glm::vec3 color = readColor(line, warnings, &used);
        if (used) block.specular = color;
    } else if (keyword == "Ns") {
        line.expectWords(1, 1, "one number");
        block.exponent = line.number_(1, "an exponent");
        if (block.exponent < 0) line.fail("'Ns' must be at least 0");
    } else if (keyword == "Ni") {
        line.expectWords(1, 1, "one number");
        const float ior = line.number_(1, "an index of refraction");
        if (ior > 0) block.ior = ior;
        else  // Blender and others write `Ni 0` (or less) for "no index": the default 1 stands
            warnings.push_back(line.warning("'Ni " + line.words[1] + "' is no index of refraction; read as 1"));
    } else if (keyword == "d" || keyword == "Tr") {
        // "d -halo 0.5" is valid MTL; Glint reads the factor and warns about the halo.
        size_t index = 1;
        if (keyword == "d" && line.words.size() > 1 && line.words[1] == "-halo") {
            warnings.push_back(line.warning("'d -halo' is valid MTL but Glint has no halo dissolve; read as plain d"));
            index = 2;
        }
        if (line.words.size() != index + 1) line.fail("'" + keyword + "' takes one number");
        const float value = line.number_(index, "a number");
        if (value < 0 || value > 1) line.fail("'" + keyword + "' must be in [0, 1]");
        block.dissolve = keyword == "d" ? value : 1.0f - value;
        block.dissolveLine = line.number;
    } else if (keyword == "illum") {
        line.expectWords(1, 1, "one integer 0-10");
        const float value = line.number_(1, "an integer");
        if (value != std::floor(value) || value < 0 || value > 10) line.fail("'illum' must be an integer 0-10");
        block.illum = static_cast<int>(value);
    } else if (kTextureStatements.count(keyword)) {
        TextureReference texture = readTexture(line);
        // Kept as a reference only, never read; an outside one is not kept (util/reference_confinement.h).
        if (auto confined = confinedReference(texture.path, {*line.file, line.number, 0}); confined)
            block.textures.push_back(std::move(texture));
        else
            warnings.push_back(line.warning(confined.error().message + "; the texture map is left out"));
    } else if (kUnusedStatements.count(keyword)) {
        warnings.push_back(line.warning("'" + keyword + "' is valid MTL but Glint does not use it; ignored"));
    } else {  // Wavefront readers skip what they do not know (3ds Max's Km, vendors' own)
        warnings.push_back(line.warning("unknown statement '" + keyword + "'; ignored"));
    }
}

// --- illum mapping --------------------------------------------------------------------------

ImportedMaterial mapBlock(const MtlBlock& block, const std::string& file) {
    const SourceLocation where{file, block.line, 0};
    ImportedMaterial imported;
    imported.warnings = block.warnings;
    auto warn = [&](const std::string& message) { imported.warnings.push_back(makeError("warning: " + message, where)); };
    imported.textures = block.textures;
    if (!block.textures.empty())
        warn("'" + block.name + "': texture maps are kept as file references but not rendered (Glint renders a glTF's textures, not an MTL's)");
    const bool reflective = block.illum == 3 || block.illum == 5 || block.illum == 8;
    const bool refractive = block.illum == 4 || block.illum == 6 || block.illum == 7 || block.illum == 9;
    if (block.dissolve < 1.0f && !refractive)
        warn("'" + block.name + "': dissolve d = " + std::to_string(block.dissolve) +
             " is ignored: Glint draws opaque surfaces (use illum 4-7 for glass)");
    if (block.hasAmbient && block.ambient != block.diffuse && block.ambient != glm::vec3(0.0f))
        warn("'" + block.name + "': Ka is ignored: Glint's ambient reflectance is the diffuse albedo Kd");
    Material& material = imported.material;
    if (refractive) {
        material = Material::withDefaults(block.name, BrdfModel::Glass);
        if (block.ior < 1.0f || block.ior > 4.0f)
            throw MtlError{makeError("'" + block.name + "': Ni = " + std::to_string(block.ior) +
                                         " is outside glass's range [1, 4]", where)};
        setParam(material, "ior", block.ior);
        if (block.illum != 7) warn("'" + block.name + "': illum " + std::to_string(block.illum) + " imported as Glint glass with exact Fresnel transparency");
    } else if (reflective) {
        material = Material::withDefaults(block.name, BrdfModel::Mirror);
        glm::vec3 extinction;
        for (int c = 0; c < 3; ++c) {
            float reflectance = block.specular[c];
            if (reflectance > 0.999f) {
                warn("'" + block.name + "': Ks = 1 (a perfect mirror) is imported as reflectance 0.999");
                reflectance = 0.999f;
            }
            extinction[c] = conductorExtinctionFromF0(reflectance);  // a conductor with n = 1
        }
        setParam(material, "ior", 1.0f);
        setParam(material, "extinction", extinction);
        setParam(material, "diffuse_albedo", block.diffuse);
        if (block.illum != 3)
            warn("'" + block.name + "': illum " + std::to_string(block.illum) + " imported as a Glint mirror (as illum 3)");
    } else if (block.illum == 2 && block.exponent == 0.0f && block.specular != glm::vec3(0.0f)) {
        // (N·H)^0 = 1 would add Ks everywhere: no tool draws that. Blender 4.x writes Ns 0 for
        // roughness 1 (Ns = 1000·(1 − roughness)²) and MeshLab for "no shininess set": both mean
        // no highlight.
        material = Material::withDefaults(block.name, BrdfModel::Lambert);
        setParam(material, "albedo", block.diffuse);
        warn("'" + block.name + "': 'Ns 0' (written by Blender for roughness 1, by MeshLab for no shininess) read as no highlight: "
             "imported as Lambert with albedo Kd");
    } else if (block.illum == 2) {
        material = Material::withDefaults(block.name, BrdfModel::BlinnPhong);
        setParam(material, "diffuse_albedo", block.diffuse);
        setParam(material, "specular", block.specular);
        setParam(material, "exponent", block.exponent);
        setParam(material, "form", 0.0f);  // MTL's Ks·(N·H)^Ns is the lecture form
    } else {
        material = Material::withDefaults(block.name, BrdfModel::Lambert);
        setParam(material, "albedo", block.diffuse);
        if (block.illum == 0)
            warn("'" + block.name + "': illum 0 (constant colour, unlit) has no Glint model; imported as Lambert with albedo Kd");
        if (block.illum == 10)
            warn("'" + block.name + "': illum 10 (shadow matte) has no Glint model; imported as Lambert");
    }
    if (auto problem = findOutOfRange(material)) throw MtlError{makeError("'" + block.name + "': " + *problem, where)};
    return imported;
}

}  // namespace

// --- reader entry points --------------------------------------------------------------------

Result<ImportedFile> parseMtl(const std::string& text, const std::string& file) {
    ImportedFile result;
    std::vector<MtlBlock> blocks;
    try {
        std::istringstream stream(text);
        int number = 0;
        for (std::string raw; std::getline(stream, raw);) {
            ++number;
            for (const char c : raw)  // text, not binary: a NUL or an escape cannot be part of a name or path
                if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\r' && c != '\f' && c != '\v')
                    throw MtlError{makeError("control character 0x" + hexByte(c) + " in the line: not a text .mtl file",
                                             {file, number, 0})};
            // Older tools write names and comments in Latin-1 (ISO 8859-1); a line that is not
            // UTF-8 is read as Latin-1, with a warning, as Wavefront readers take bytes as they come.
            if (findInvalidUtf8(raw)) {
                raw = latin1ToUtf8(raw);
                result.warnings.push_back(makeError("warning: the line is not UTF-8; read as Latin-1 (ISO 8859-1)", {file, number, 0}));
            }
            const size_t comment = raw.find('#');
            const std::string content(trimmed(std::string_view(raw).substr(0, comment)));
            if (content.empty()) continue;
            Line line{&file, number, splitWords(content), ""};
            if (line.words.empty()) continue;
            line.rest = trimmed(std::string_view(content).substr(line.words[0].size()));
            if (line.words[0] == "newmtl") {
                MtlBlock block{.name = line.rest, .line = number};
                if (block.name.empty()) {  // Blender writes `newmtl` with no name for a slot without a material
                    block.name = "unnamed (line " + std::to_string(number) + ")";
                    block.warnings.push_back(line.warning("'newmtl' without a name; named '" + block.name + "'"));
                }
                blocks.push_back(std::move(block));
                continue;
            }
            if (blocks.empty()) line.fail("'" + line.words[0] + "' before the first 'newmtl'");
            readStatement(line, blocks.back(), blocks.back().warnings);
        }
        if (blocks.empty()) throw MtlError{makeError("no material in the file (no 'newmtl' line)", {file, 0, 0})};
        for (const MtlBlock& block : blocks) result.materials.push_back(mapBlock(block, file));
    } catch (const MtlError& error) {
        return error.diagnostic;
    }
    return result;
}

Result<ImportedFile> loadMtl(const std::string& path) { return parseTextFile(path, parseMtl); }

// --- writer ---------------------------------------------------------------------------------

namespace {

std::string number(float value) { return formatNumber(value, "%.9g"); }
std::string numbers(glm::vec3 value) { return number(value.r) + " " + number(value.g) + " " + number(value.b); }

// Names go on one line: control characters become spaces.
std::string oneLine(std::string name) {
    for (char& c : name)
        if (static_cast<unsigned char>(c) < 0x20) c = ' ';
    const std::string_view kept = trimmed(name);
    return kept.empty() ? "material" : std::string(kept);
}

}  // namespace

ExportedText writeMtl(std::span<const ImportedMaterial> materials) {
    ExportedText out;
    std::string& text = out.text;
    text += "# Wavefront material library written by Glint\n";
    for (const ImportedMaterial& imported : materials) {
        GLINT_CHECK(imported.material.analytic());  // exportMaterials converts the other kinds
        const AnalyticMaterial& material = *imported.material.analytic();
        const std::string name = oneLine(imported.material.name);
        auto lost = [&](const std::string& what) {
            out.warnings.push_back(makeError("warning: '" + name + "' (" + modelInfo(material.model).id + "): " + what));
        };
        const MtlForm form = dispatch(material.model, [&](auto model) {
            using M = decltype(model);
            if constexpr (HasMtlForm<M>) return M::mtlForm(unpack<M>(material.values.data()));
            else return MtlForm{.lost = {"the model has no MTL form; written as a black Lambert"}};
        });
        for (const std::string& what : form.lost) lost(what);
        text += "\nnewmtl " + name + "\n";
        text += "# Glint model: " + std::string(modelInfo(material.model).id) + "\n";
        text += "Ka " + numbers(form.diffuse) + "\n";
        text += "Kd " + numbers(form.diffuse) + "\n";
        text += "Ks " + numbers(form.specular) + "\n";
        text += "Ns " + number(form.exponent) + "\n";
        text += "Ni " + number(form.ior) + "\n";
        text += "d 1\n";
        text += "illum " + std::to_string(form.illum) + "\n";
        for (const TextureReference& texture : imported.textures) {
            if (!kTextureStatements.count(texture.slot)) {
                lost("texture '" + texture.slot + "' has no MTL statement; not written");
                continue;
            }
            text += texture.slot + (texture.options.empty() ? "" : " " + texture.options) + " " + oneLine(texture.path) + "\n";
        }
    }
    return out;
}

}  // namespace glint
