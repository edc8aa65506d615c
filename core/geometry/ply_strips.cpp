// PLY triangle strips to faces (see ply_strips.h). PLY: Greg Turk's format description (1994).
#include "geometry/ply_strips.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <utility>
#include <vector>

#include "util/text.h"

namespace glint {
namespace {

enum class Encoding { Ascii, LittleEndian, BigEndian };

struct Property {
    std::string type;       // scalar type, or the list's item type
    std::string countType;  // lists only
    bool list = false;
};

struct Element {
    std::string name;
    long long count = 0;
    std::vector<Property> properties;
    std::string headerLines;  // its element and property lines, as written
};

int typeSize(const std::string& type) {
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
    if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32") return 4;
    if (type == "double" || type == "float64") return 8;
    return 0;
}

// Reads binary data (bounds-checked) and ASCII tokens.
struct Reader {
    std::string_view data;
    size_t position = 0;
    Encoding encoding;

    bool integer(const std::string& type, long long& value) {
        if (encoding == Encoding::Ascii) {
            while (position < data.size() && std::isspace(static_cast<unsigned char>(data[position]))) ++position;
            const size_t start = position;
            while (position < data.size() && !std::isspace(static_cast<unsigned char>(data[position]))) ++position;
            double number = 0;
            const auto [end, error] = std::from_chars(data.data() + start, data.data() + position, number);
            if (error != std::errc() || end != data.data() + position || position == start) return false;
            value = static_cast<long long>(number);
            return true;
        }
        const int size = typeSize(type);
        if (size == 0 || data.size() - position < static_cast<size_t>(size)) return false;
        unsigned char bytes[8];
        std::memcpy(bytes, data.data() + position, size);
        position += size;
        if ((encoding == Encoding::BigEndian) == (std::endian::native == std::endian::little))
            for (int i = 0; i < size / 2; ++i) std::swap(bytes[i], bytes[size - 1 - i]);
        const bool isSigned = type == "char" || type == "int8" || type == "short" || type == "int16" || type == "int" || type == "int32";
        if (type == "float" || type == "float32") { float f; std::memcpy(&f, bytes, 4); value = static_cast<long long>(f); }
        else if (type == "double" || type == "float64") { double d; std::memcpy(&d, bytes, 8); value = static_cast<long long>(d); }
        else if (size == 1) value = isSigned ? static_cast<int8_t>(bytes[0]) : bytes[0];
        else if (size == 2) { uint16_t u; std::memcpy(&u, bytes, 2); value = isSigned ? static_cast<int16_t>(u) : u; }
        else { uint32_t u; std::memcpy(&u, bytes, 4); value = isSigned ? static_cast<int32_t>(u) : u; }
        return true;
    }
};

void appendInt32(std::string& out, int32_t value, Encoding encoding) {
    unsigned char bytes[4];
    std::memcpy(bytes, &value, 4);
    if ((encoding == Encoding::BigEndian) == (std::endian::native == std::endian::little)) std::swap(bytes[0], bytes[3]), std::swap(bytes[1], bytes[2]);
    out.append(reinterpret_cast<const char*>(bytes), 4);
}

// The header: its lines up to the first element, the elements, and where the data starts.
struct PlyHeader {
    std::vector<Element> elements;
    Encoding encoding = Encoding::Ascii;
    std::string start;  // the lines before the first element (ply, format, comments)
    size_t dataStart = 0;
    int lines = 0;
};

// One `property` line's words after the keyword.
Result<Property> readProperty(std::istringstream& words) {
    Property property;
    std::string first;
    words >> first;
    if (first != "list") {
        property.type = first;
        if (!typeSize(property.type)) return makeError("unknown type '" + first + "'");
        return property;
    }
    property.list = true;
    words >> property.countType >> property.type;
    if (!typeSize(property.countType) || !typeSize(property.type)) return makeError("unknown list types");
    return property;
}

Result<PlyHeader> readPlyHeader(std::string_view bytes, const std::string& name) {
    PlyHeader header;
    size_t& position = header.dataStart;
    while (position < bytes.size()) {
        const size_t end = std::min(bytes.find('\n', position), bytes.size());
        const std::string text(trimmed(bytes.substr(position, end - position)));
        const std::string raw(bytes.substr(position, end - position + (end < bytes.size() ? 1 : 0)));
        position = end + 1;
        ++header.lines;
        auto fail = [&](const std::string& message) { return makeError("cannot load mesh: PLY header: " + message, {name, header.lines, 1}); };
        std::istringstream words(text);
        std::string keyword;
        words >> keyword;
        if (keyword == "end_header") return header;
        if (keyword == "format") {
            std::string kind;
            words >> kind;
            if (kind != "ascii" && kind != "binary_little_endian" && kind != "binary_big_endian") return fail("unknown format '" + kind + "'");
            header.encoding = kind == "ascii" ? Encoding::Ascii : kind == "binary_big_endian" ? Encoding::BigEndian : Encoding::LittleEndian;
            header.start += raw;
        } else if (keyword == "element") {
            Element element;
            if (!(words >> element.name >> element.count) || element.count < 0) return fail("'element' needs a name and a count");
            element.headerLines = raw;
            header.elements.push_back(element);
        } else if (keyword == "property") {
            if (header.elements.empty()) return fail("a property before any element");
            auto property = readProperty(words);
            if (!property) return fail(property.error().message);
            header.elements.back().properties.push_back(*property);
            header.elements.back().headerLines += raw;
        } else if (header.elements.empty()) {
            header.start += raw;  // ply, comment, obj_info
        }
    }
    return makeError("cannot load mesh: the PLY header ends without end_header (the file is cut short)", {name, header.lines, 1});
}

// The triangles of one record's strips: indices, −1 between strips; every other triangle is
// wound the other way; degenerate ones are dropped.
void appendStripTriangles(const std::vector<long long>& values, std::vector<int32_t>& triangles) {
    size_t begin = 0;  // the strip's first index in `values`
    for (size_t i = 0; i <= values.size(); ++i) {
        if (i == values.size() || values[i] < 0) {  // -1 (or the end) ends a strip
            begin = i + 1;
            continue;
        }
        if (i - begin < 2) continue;
        long long a = values[i - 2], b = values[i - 1], c = values[i];
        if ((i - begin) % 2 == 1) std::swap(a, b);
        if (a != b && b != c && a != c) triangles.insert(triangles.end(), {int32_t(a), int32_t(b), int32_t(c)});
    }
}

// The face element's records, in the file's encoding.
std::string faceRecords(const std::vector<int32_t>& triangles, Encoding encoding) {
    std::string faces;
    for (size_t t = 0; t < triangles.size(); t += 3) {
        if (encoding == Encoding::Ascii) {
            faces += "3 " + std::to_string(triangles[t]) + " " + std::to_string(triangles[t + 1]) + " " + std::to_string(triangles[t + 2]) + "\n";
        } else {
            faces.push_back(3);
            for (int k = 0; k < 3; ++k) appendInt32(faces, triangles[t + k], encoding);
        }
    }
    return faces;
}

}  // namespace

bool plyHasTristrips(std::string_view start) {
    if (start.substr(0, 3) != "ply") return false;
    const size_t header = start.find("end_header");
    const std::string_view text = start.substr(0, header);
    for (size_t at = text.find("element"); at != std::string_view::npos; at = text.find("element", at + 7))
        if (trimmed(text.substr(at + 7)).substr(0, 10) == "tristrips ") return true;
    return false;
}

Result<std::string> plyStripsToFaces(std::string_view bytes, const std::string& name) {
    auto parsed = readPlyHeader(bytes, name);
    if (!parsed) return parsed.error();
    const PlyHeader& ply = *parsed;
    // The data: other elements copied, strips turned into triangles.
    Reader reader{bytes, ply.dataStart, ply.encoding};
    std::string header = ply.start, body;
    std::vector<int32_t> triangles;
    for (const Element& element : ply.elements) {
        const bool strips = element.name == "tristrips";
        if (!strips) header += element.headerLines;
        for (long long record = 0; record < element.count; ++record) {
            const size_t recordStart = reader.position;
            std::vector<long long> values;
            for (const Property& property : element.properties) {
                long long count = 1;
                bool read = !property.list || (reader.integer(property.countType, count) && count >= 0 && count <= (1 << 28));
                for (long long i = 0; read && i < count; ++i) {
                    long long value = 0;
                    read = reader.integer(property.type, value);
                    if (strips && property.list) values.push_back(value);
                }
                if (!read)
                    return makeError("cannot load mesh: element '" + element.name + "' record " + std::to_string(record) +
                                         " is malformed or cut short",
                                     {name, ply.lines, 1});
            }
            const std::string_view recordBytes = bytes.substr(recordStart, reader.position - recordStart);
            if (strips) appendStripTriangles(values, triangles);
            else if (ply.encoding != Encoding::Ascii) body.append(recordBytes);
            else body.append(trimmed(recordBytes)).push_back('\n');
        }
    }
    header += "element face " + std::to_string(triangles.size() / 3) + "\nproperty list uchar int vertex_indices\nend_header\n";
    // The face element goes last: after every element it replaces or follows.
    return header + body + faceRecords(triangles, ply.encoding);
}

}  // namespace glint
