// Mesh-file checks before assimp reads them (see mesh_file_checks.h).
// Sections: words and numbers · PLY · OBJ · glTF.
#include "geometry/mesh_file_checks.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <map>
#include <vector>

#include <nlohmann/json.hpp>

#include "interchange/base64.h"
#include "interchange/glb.h"
#include "interchange/gltf.h"
#include "scene/json_document.h"
#include "util/file_io.h"
#include "util/reference_confinement.h"
#include "util/text.h"

namespace glint {

// --- words and numbers ---------------------------------------------------------------------

namespace {

// The line's words (split at white space).
std::vector<std::string_view> wordsOf(std::string_view text) {
    std::vector<std::string_view> words;
    size_t position = 0;
    while (position < text.size()) {
        while (position < text.size() && std::isspace(static_cast<unsigned char>(text[position]))) ++position;
        const size_t start = position;
        while (position < text.size() && !std::isspace(static_cast<unsigned char>(text[position]))) ++position;
        if (position > start) words.push_back(text.substr(start, position - start));
    }
    return words;
}

bool parseIndex(std::string_view text, long long& value) {
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    return error == std::errc() && end == text.data() + text.size();
}

}  // namespace

// --- PLY ------------------------------------------------------------------------------------

// Assimp 5.2.5's PLY reader never returns on some malformed headers (an unknown keyword,
// "end_header" running on into the data, found by fuzz_mesh_import; a file that ends inside its
// header), so the header's lines are checked before assimp sees them: each must start with a PLY
// keyword, and a file whose first bytes (`start`) are all of it (`whole`) must hold end_header.
std::optional<Diagnostic> checkPlyHeader(std::string_view start, bool whole, const std::string& name) {
    if (start.substr(0, 3) != "ply") return std::nullopt;
    static const std::string_view keywords[] = {"ply", "format", "comment", "obj_info", "element", "property"};
    int line = 0;
    size_t position = 0;
    while (position < start.size()) {
        ++line;
        const size_t end = std::min(start.find('\n', position), start.size());
        if (end == start.size() && !whole) return std::nullopt;  // runs on past the first bytes: assimp's turn
        std::string_view text = start.substr(position, end - position);
        if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
        position = end + 1;
        if (text == "end_header") return std::nullopt;
        const std::string_view word = text.substr(0, text.find(' '));
        if (std::find(std::begin(keywords), std::end(keywords), word) == std::end(keywords))
            return makeError("cannot load mesh: malformed PLY header: '" + std::string(text.substr(0, 40)) +
                                 "' is not a PLY header line (format, comment, element, property, end_header)",
                             {name, line, 1});
        if (word == "element") {
            const std::vector<std::string_view> words = wordsOf(text);
            long long count = 0;
            if (words.size() == 3 && parseIndex(words[2], count) && count > kMaxMeshElements)
                return makeError("cannot load mesh: the PLY header declares " + std::to_string(count) + " " + std::string(words[1]) +
                                     " elements; Glint loads at most " + std::to_string(kMaxMeshElements) +
                                     " (a larger mesh would not fit in memory): simplify the mesh or split it",
                                 {name, line, 1});
        }
    }
    if (!whole) return std::nullopt;
    return makeError("cannot load mesh: the PLY header ends without end_header (the file is cut short)", {name, line, 1});
}

// --- OBJ ------------------------------------------------------------------------------------

namespace {

// Calls `visit(statement, line)` for each logical line (a trailing backslash joins the next).
template <class Visit>
void forEachObjLine(std::string_view text, const Visit& visit) {
    size_t position = 0;
    int number = 0;
    std::string joined;
    int joinedStart = 0;
    while (position < text.size()) {
        const size_t end = std::min(text.find('\n', position), text.size());
        std::string_view line = text.substr(position, end - position);
        position = end + 1;
        ++number;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (!line.empty() && line.back() == '\\') {
            if (joined.empty()) joinedStart = number;
            joined.append(line.substr(0, line.size() - 1)).push_back(' ');
            continue;
        }
        if (!joined.empty()) {
            joined.append(line);
            visit(std::string_view(joined), joinedStart);
            joined.clear();
        } else {
            visit(line, number);
        }
    }
    if (!joined.empty()) visit(std::string_view(joined), joinedStart);
}

}  // namespace

std::optional<Diagnostic> checkObjText(std::string_view text, const std::string& name) {
    long long vertexTotal = 0;
    forEachObjLine(text, [&](std::string_view line, int) {
        line = trimmed(line);
        if (line.size() > 2 && line[0] == 'v' && std::isspace(static_cast<unsigned char>(line[1]))) ++vertexTotal;
    });
    std::optional<Diagnostic> problem;
    long long verticesSoFar = 0;
    forEachObjLine(text, [&](std::string_view line, int number) {
        if (problem) return;
        const std::vector<std::string_view> words = wordsOf(line.substr(0, line.find('#')));
        if (words.empty()) return;
        auto fail = [&](const std::string& message) { problem = makeError("cannot load mesh: " + message, {name, number, 1}); };
        if (words[0] == "v") {
            ++verticesSoFar;
            if (words.size() < 4)
                return fail("a vertex needs x y z (" + std::to_string(words.size() - 1) + " number(s) given: is the file cut short?)");
            for (size_t i = 1; i < 4; ++i) {
                float value = 0;
                const auto [end, error] = std::from_chars(words[i].data(), words[i].data() + words[i].size(), value);
                if (error == std::errc::invalid_argument || end != words[i].data() + words[i].size())
                    return fail("'" + std::string(words[i]) + "' is not a number");
            }
            return;
        }
        if (words[0] != "f" && words[0] != "fo") return;
        if (words.size() < 4)
            return fail("a face with " + std::to_string(words.size() - 1) +
                        " corner(s): a face needs three or more (is the file cut short?)");
        for (size_t i = 1; i < words.size(); ++i) {
            const std::string_view corner = words[i];
            const size_t slash = corner.find('/');
            long long index = 0;
            if (!parseIndex(corner.substr(0, slash), index))
                return fail("face corner '" + std::string(corner) + "' does not start with a vertex index");
            if (slash != std::string_view::npos) {  // v/vt, v//vn, v/vt/vn: a part after a slash may be empty, not the last
                const std::string_view rest = corner.substr(slash + 1);
                const size_t second = rest.find('/');
                const std::string_view last = second == std::string_view::npos ? rest : rest.substr(second + 1);
                long long ignored = 0;
                if (last.empty() || !parseIndex(last, ignored) ||
                    (second != std::string_view::npos && second > 0 && !parseIndex(rest.substr(0, second), ignored)))
                    return fail("face corner '" + std::string(corner) + "' is incomplete or malformed (is the file cut short?)");
            }
            if (index == 0) return fail("face corner '" + std::string(corner) + "': vertex index 0 (OBJ counts from 1)");
            if (index > vertexTotal)
                return fail("face corner '" + std::string(corner) + "' uses vertex " + std::to_string(index) +
                            ", but the file has only " + std::to_string(vertexTotal) + " vertices");
            if (index < 0 && -index > verticesSoFar)
                return fail("face corner '" + std::string(corner) + "' counts back " + std::to_string(-index) +
                            " vertices, but only " + std::to_string(verticesSoFar) + " come before it");
        }
    });
    return problem;
}

// --- glTF -----------------------------------------------------------------------------------

namespace {

using Json = nlohmann::json;

const Json* member(const Json& object, const char* key) {
    return object.is_object() && object.contains(key) ? &object[key] : nullptr;
}

long long integerOr(const Json* value, long long fallback) {
    return value && value->is_number_integer() ? value->get<long long>() : fallback;
}

// The bytes of buffer `index`: a data URI, a file in the .gltf's folder or below, or a .glb's BIN
// chunk; nothing when they cannot be had here (assimp then says why) or the file is refused
// (`refusal` then says why: util/reference_confinement.h).
std::optional<std::string> bufferBytes(const Json& buffer, std::string_view bin, const std::string& meshFile,
                                       std::optional<Diagnostic>& refusal) {
    const Json* uri = member(buffer, "uri");
    if (!uri) return std::string(bin);
    if (!uri->is_string()) return std::nullopt;
    const std::string text = uri->get<std::string>();
    if (text.rfind("data:", 0) == 0) {
        const size_t comma = text.find(";base64,");
        if (comma == std::string::npos) return std::nullopt;
        auto decoded = decodeBase64(std::string_view(text).substr(comma + 8));
        if (!decoded) return std::nullopt;
        return std::string(decoded->begin(), decoded->end());
    }
    if (meshFile.empty()) return std::nullopt;
    auto confined = confinedReference(text, {meshFile});
    if (!confined) {
        refusal = confined.error();
        return std::nullopt;
    }
    auto read = readTextFile(confined->string());
    if (!read) return std::nullopt;
    return std::move(*read);
}

}  // namespace

std::optional<Diagnostic> checkGltfIndices(std::string_view bytes, bool binary, const std::string& meshFile,
                                           const std::string& name) {
    std::string jsonText;
    std::string_view bin;
    if (binary) {
        auto chunks = glbChunks(bytes, name);
        if (!chunks) return chunks.error();
        jsonText = std::move(chunks->json);
        bin = chunks->bin;
    } else {
        jsonText = std::string(bytes);
    }
    auto document = JsonDocument::parse(jsonText, binary ? name + " (JSON chunk)" : name);
    if (!document) return document.error();
    if (auto refusal = unsupportedRequiredExtension(*document)) return *refusal;
    const Json& root = document->root();
    const Json* meshes = member(root, "meshes");
    const Json* accessors = member(root, "accessors");
    const Json* views = member(root, "bufferViews");
    const Json* buffers = member(root, "buffers");
    if (!meshes || !meshes->is_array() || !accessors || !accessors->is_array() || !views || !views->is_array() || !buffers ||
        !buffers->is_array())
        return std::nullopt;
    std::map<long long, std::optional<std::string>> loaded;
    for (size_t m = 0; m < meshes->size(); ++m) {
        const Json* primitives = member((*meshes)[m], "primitives");
        for (size_t p = 0; primitives && primitives->is_array() && p < primitives->size(); ++p) {
            const Json& primitive = (*primitives)[p];
            const long long indices = integerOr(member(primitive, "indices"), -1);
            const Json* attributes = member(primitive, "attributes");
            const long long position = attributes ? integerOr(member(*attributes, "POSITION"), -1) : -1;
            const auto accessorCount = static_cast<long long>(accessors->size());
            if (indices < 0 || position < 0 || indices >= accessorCount || position >= accessorCount) continue;
            const Json& accessor = (*accessors)[indices];
            const long long vertexCount = integerOr(member((*accessors)[position], "count"), -1);
            const long long count = integerOr(member(accessor, "count"), -1);
            const long long type = integerOr(member(accessor, "componentType"), -1);
            const long long viewIndex = integerOr(member(accessor, "bufferView"), -1);
            const int size = type == 5121 ? 1 : type == 5123 ? 2 : type == 5125 ? 4 : 0;
            if (vertexCount < 0 || count < 0 || size == 0 || viewIndex < 0 || viewIndex >= static_cast<long long>(views->size()))
                continue;
            const Json& view = (*views)[viewIndex];
            const long long bufferIndex = integerOr(member(view, "buffer"), -1);
            if (bufferIndex < 0 || bufferIndex >= static_cast<long long>(buffers->size())) continue;
            auto& data = loaded.try_emplace(bufferIndex, std::nullopt).first->second;
            std::optional<Diagnostic> refusal;
            if (!data) data = bufferBytes((*buffers)[bufferIndex], bin, meshFile, refusal);
            if (refusal) {
                const std::string uri = "/buffers/" + std::to_string(bufferIndex) + "/uri";
                return makeError("cannot load mesh: " + uri + ": " + refusal->message, document->locate(uri));
            }
            if (!data) continue;
            const long long start = integerOr(member(view, "byteOffset"), 0) + integerOr(member(accessor, "byteOffset"), 0);
            const long long stride = std::max<long long>(size, integerOr(member(view, "byteStride"), size));
            const std::string pointer = "/accessors/" + std::to_string(indices);
            if (start < 0 || (count > 0 && start + (count - 1) * stride + size > static_cast<long long>(data->size())))
                return makeError("cannot load mesh: " + pointer + ": the indices run past the end of buffer " +
                                     std::to_string(bufferIndex) + " (" + std::to_string(data->size()) + " bytes)",
                                 document->locate(pointer));
            for (long long k = 0; k < count; ++k) {
                const auto* at = reinterpret_cast<const unsigned char*>(data->data() + start + k * stride);
                uint32_t value = 0;
                for (int b = 0; b < size; ++b) value |= uint32_t(at[b]) << (8 * b);  // little-endian
                if (value >= vertexCount)
                    return makeError("cannot load mesh: " + pointer + ": index " + std::to_string(k) + " is " +
                                         std::to_string(value) + ", but mesh " + std::to_string(m) + " primitive " +
                                         std::to_string(p) + " has only " + std::to_string(vertexCount) + " vertices",
                                     document->locate(pointer));
            }
        }
    }
    return std::nullopt;
}

}  // namespace glint
