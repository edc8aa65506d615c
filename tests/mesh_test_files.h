// Mesh files written by the tests and the mesh-load benchmark themselves: any indexed triangle
// mesh (with UVs or without) in OBJ, PLY (ASCII, binary), STL (ASCII, binary; no UVs), glTF 2.0
// with an embedded base64 buffer, and GLB; and a flat n×n grid of quads (two triangles each),
// (n+1)² vertices and 2n² triangles in every format.
#pragma once

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace glint::test {

struct GridMesh {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> indices;
    std::vector<glm::vec2> uvs;  // one per position, or none
};

// In the xy plane, [0, n]², facing +z.
inline GridMesh makeGrid(int n) {
    GridMesh grid;
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x) grid.positions.push_back({float(x), float(y), 0.0f});
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const uint32_t a = y * (n + 1) + x, b = a + 1, c = a + n + 2, d = a + n + 1;
            grid.indices.insert(grid.indices.end(), {a, b, c, a, c, d});
        }
    return grid;
}

inline void writeText(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

inline void writeObj(const std::string& path, const GridMesh& grid) {
    std::ofstream out(path, std::ios::binary);
    out << "# grid written by Glint's tests\n";
    for (const glm::vec3& p : grid.positions) out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
    for (const glm::vec2& uv : grid.uvs) out << "vt " << uv.x << ' ' << uv.y << '\n';
    for (size_t i = 0; i < grid.indices.size(); i += 3) {
        out << 'f';
        for (size_t k = i; k < i + 3; ++k) {
            out << ' ' << grid.indices[k] + 1;
            if (!grid.uvs.empty()) out << '/' << grid.indices[k] + 1;
        }
        out << '\n';
    }
}

inline void writePly(const std::string& path, const GridMesh& grid, bool binary) {
    std::ofstream out(path, std::ios::binary);
    out << "ply\nformat " << (binary ? "binary_little_endian" : "ascii") << " 1.0\n"
        << "element vertex " << grid.positions.size() << "\nproperty float x\nproperty float y\nproperty float z\n"
        << (grid.uvs.empty() ? "" : "property float s\nproperty float t\n") << "element face " << grid.indices.size() / 3
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    if (!binary) {
        for (size_t i = 0; i < grid.positions.size(); ++i) {
            const glm::vec3& p = grid.positions[i];
            out << p.x << ' ' << p.y << ' ' << p.z;
            if (!grid.uvs.empty()) out << ' ' << grid.uvs[i].x << ' ' << grid.uvs[i].y;
            out << '\n';
        }
        for (size_t i = 0; i < grid.indices.size(); i += 3)
            out << "3 " << grid.indices[i] << ' ' << grid.indices[i + 1] << ' ' << grid.indices[i + 2] << '\n';
        return;
    }
    if (grid.uvs.empty()) {
        out.write(reinterpret_cast<const char*>(grid.positions.data()), grid.positions.size() * sizeof(glm::vec3));
    } else {
        for (size_t i = 0; i < grid.positions.size(); ++i) {
            out.write(reinterpret_cast<const char*>(&grid.positions[i]), sizeof(glm::vec3));
            out.write(reinterpret_cast<const char*>(&grid.uvs[i]), sizeof(glm::vec2));
        }
    }
    std::vector<char> faces(grid.indices.size() / 3 * 13);
    for (size_t t = 0; t < grid.indices.size() / 3; ++t) {
        faces[t * 13] = 3;
        const int32_t corners[3] = {int32_t(grid.indices[3 * t]), int32_t(grid.indices[3 * t + 1]), int32_t(grid.indices[3 * t + 2])};
        std::memcpy(&faces[t * 13 + 1], corners, 12);
    }
    out.write(faces.data(), faces.size());
}

inline void writeStl(const std::string& path, const GridMesh& grid, bool binary) {
    std::ofstream out(path, std::ios::binary);
    const size_t triangles = grid.indices.size() / 3;
    if (!binary) {
        out << "solid grid\n";
        for (size_t t = 0; t < triangles; ++t) {
            out << "facet normal 0 0 1\nouter loop\n";
            for (int k = 0; k < 3; ++k) {
                const glm::vec3& p = grid.positions[grid.indices[3 * t + k]];
                out << "vertex " << p.x << ' ' << p.y << ' ' << p.z << '\n';
            }
            out << "endloop\nendfacet\n";
        }
        out << "endsolid grid\n";
        return;
    }
    char header[80] = "binary STL written by Glint's tests";
    out.write(header, 80);
    const auto count = static_cast<uint32_t>(triangles);
    out.write(reinterpret_cast<const char*>(&count), 4);
    for (size_t t = 0; t < triangles; ++t) {
        const float normal[3] = {0, 0, 1};
        out.write(reinterpret_cast<const char*>(normal), 12);
        for (int k = 0; k < 3; ++k) out.write(reinterpret_cast<const char*>(&grid.positions[grid.indices[3 * t + k]]), 12);
        const uint16_t attributes = 0;
        out.write(reinterpret_cast<const char*>(&attributes), 2);
    }
}

inline std::string base64(const std::string& bytes) {
    static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        uint32_t chunk = uint8_t(bytes[i]) << 16;
        if (i + 1 < bytes.size()) chunk |= uint8_t(bytes[i + 1]) << 8;
        if (i + 2 < bytes.size()) chunk |= uint8_t(bytes[i + 2]);
        out += alphabet[(chunk >> 18) & 63];
        out += alphabet[(chunk >> 12) & 63];
        out += i + 1 < bytes.size() ? alphabet[(chunk >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? alphabet[chunk & 63] : '=';
    }
    return out;
}

// The glTF JSON for a grid whose buffer (positions, uint32 indices, then UVs if any) is `uri`
// (omitted in a GLB).
inline std::string gltfJson(const GridMesh& grid, size_t bufferBytes, const std::string& uri) {
    glm::vec3 low(1e30f), high(-1e30f);
    for (const glm::vec3& p : grid.positions) low = glm::min(low, p), high = glm::max(high, p);
    const size_t positionBytes = grid.positions.size() * 12, indexBytes = grid.indices.size() * 4;
    std::string json = R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)";
    json += std::string(R"("meshes":[{"primitives":[{"attributes":{"POSITION":0)") +
            (grid.uvs.empty() ? "" : R"(,"TEXCOORD_0":2)") + R"(},"indices":1}]}],)";
    json += R"("buffers":[{"byteLength":)" + std::to_string(bufferBytes) + (uri.empty() ? "" : R"(,"uri":")" + uri + "\"") + "}],";
    json += R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":)" + std::to_string(positionBytes) + R"(,"target":34962},)";
    json += R"({"buffer":0,"byteOffset":)" + std::to_string(positionBytes) + R"(,"byteLength":)" +
            std::to_string(indexBytes) + R"(,"target":34963})";
    if (!grid.uvs.empty())
        json += R"(,{"buffer":0,"byteOffset":)" + std::to_string(positionBytes + indexBytes) + R"(,"byteLength":)" +
                std::to_string(grid.uvs.size() * 8) + R"(,"target":34962})";
    json += "],";
    json += R"("accessors":[{"bufferView":0,"componentType":5126,"count":)" + std::to_string(grid.positions.size()) +
            R"(,"type":"VEC3","min":[)" + std::to_string(low.x) + "," + std::to_string(low.y) + "," + std::to_string(low.z) +
            R"(],"max":[)" + std::to_string(high.x) + "," + std::to_string(high.y) + "," + std::to_string(high.z) + "]},";
    json += R"({"bufferView":1,"componentType":5125,"count":)" + std::to_string(grid.indices.size()) + R"(,"type":"SCALAR"})";
    if (!grid.uvs.empty())
        json += R"(,{"bufferView":2,"componentType":5126,"count":)" + std::to_string(grid.uvs.size()) + R"(,"type":"VEC2"})";
    json += "]}";
    return json;
}

inline std::string gridBuffer(const GridMesh& grid) {
    std::string bytes(reinterpret_cast<const char*>(grid.positions.data()), grid.positions.size() * 12);
    bytes.append(reinterpret_cast<const char*>(grid.indices.data()), grid.indices.size() * 4);
    bytes.append(reinterpret_cast<const char*>(grid.uvs.data()), grid.uvs.size() * 8);
    return bytes;
}

inline void writeGltf(const std::string& path, const GridMesh& grid) {
    const std::string buffer = gridBuffer(grid);
    writeText(path, gltfJson(grid, buffer.size(), "data:application/octet-stream;base64," + base64(buffer)));
}

inline void writeGlb(const std::string& path, const GridMesh& grid) {
    std::string buffer = gridBuffer(grid);
    std::string json = gltfJson(grid, buffer.size(), "");
    while (json.size() % 4) json += ' ';
    while (buffer.size() % 4) buffer += '\0';
    const uint32_t total = 12 + 8 + uint32_t(json.size()) + 8 + uint32_t(buffer.size());
    std::ofstream out(path, std::ios::binary);
    const uint32_t header[3] = {0x46546C67u, 2u, total};  // "glTF", version 2
    out.write(reinterpret_cast<const char*>(header), 12);
    const uint32_t jsonChunk[2] = {uint32_t(json.size()), 0x4E4F534Au};  // "JSON"
    out.write(reinterpret_cast<const char*>(jsonChunk), 8);
    out << json;
    const uint32_t binChunk[2] = {uint32_t(buffer.size()), 0x004E4942u};  // "BIN\0"
    out.write(reinterpret_cast<const char*>(binChunk), 8);
    out << buffer;
}

}  // namespace glint::test
