// The on-disk cache of computed tables (see disk_cache.h).
#include "util/disk_cache.h"

#include <link.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "util/file_io.h"

namespace glint {
namespace {

constexpr char kMagic[8] = {'G', 'L', 'I', 'N', 'T', 'C', 'A', '1'};
constexpr size_t kHeaderSize = sizeof kMagic + 2 * sizeof(std::uint64_t);  // magic, size, checksum

// The hexadecimal GNU build ID of the executable (the first object dl_iterate_phdr reports);
// empty without one.
std::string executableBuildId() {
    std::string id;
    dl_iterate_phdr(
        [](dl_phdr_info* info, size_t, void* out) {
            for (int i = 0; i < info->dlpi_phnum; ++i) {
                const ElfW(Phdr)& header = info->dlpi_phdr[i];
                if (header.p_type != PT_NOTE) continue;
                const char* note = reinterpret_cast<const char*>(info->dlpi_addr + header.p_vaddr);
                const char* end = note + header.p_memsz;
                while (note + sizeof(ElfW(Nhdr)) <= end) {
                    const auto* entry = reinterpret_cast<const ElfW(Nhdr)*>(note);
                    const char* name = note + sizeof(ElfW(Nhdr));
                    const char* desc = name + ((entry->n_namesz + 3) & ~3u);
                    if (entry->n_type == NT_GNU_BUILD_ID && entry->n_namesz == 4 && std::memcmp(name, "GNU", 4) == 0) {
                        static const char kHex[] = "0123456789abcdef";
                        auto& text = *static_cast<std::string*>(out);
                        for (unsigned k = 0; k < entry->n_descsz; ++k) {
                            const auto byte = static_cast<unsigned char>(desc[k]);
                            text += kHex[byte >> 4], text += kHex[byte & 15];
                        }
                        return 1;
                    }
                    note = desc + ((entry->n_descsz + 3) & ~3u);
                }
            }
            return 1;  // only the executable itself
        },
        &id);
    return id;
}

std::string entryPath(const std::string& folder, const std::string& name) {
    static const std::string build = executableBuildId();
    return folder + "/" + name + "-" + build + ".bin";
}

}  // namespace

std::uint64_t cacheChecksum(const void* data, size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    std::uint64_t hash = 14695981039346656037ull;
    for (size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
    return hash;
}

std::string cacheFolder() {
    static const std::string folder = [] {
        if (executableBuildId().empty()) return std::string();
        if (const char* glint = std::getenv("GLINT_CACHE_DIR")) return std::string(glint);
        if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::string(xdg) + "/glint";
        if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.cache/glint";
        return std::string();
    }();
    return folder;
}

std::optional<std::string> readCacheEntry(const std::string& name) {
    const std::string folder = cacheFolder();
    if (folder.empty()) return std::nullopt;
    auto contents = readTextFile(entryPath(folder, name));  // an error for a missing file or a folder
    if (!contents || contents->size() < kHeaderSize || std::memcmp(contents->data(), kMagic, sizeof kMagic) != 0)
        return std::nullopt;
    std::uint64_t size = 0, sum = 0;
    std::memcpy(&size, contents->data() + sizeof kMagic, sizeof size);
    std::memcpy(&sum, contents->data() + sizeof kMagic + sizeof size, sizeof sum);
    if (size != contents->size() - kHeaderSize || sum != cacheChecksum(contents->data() + kHeaderSize, size)) return std::nullopt;
    return contents->substr(kHeaderSize);
}

void writeCacheEntry(const std::string& name, const std::string& bytes) {
    const std::string folder = cacheFolder();
    if (folder.empty()) return;
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    const std::string path = entryPath(folder, name);
    for (const auto& other : std::filesystem::directory_iterator(folder, error)) {
        const std::string file = other.path().filename().string();
        const bool sameName = file.size() > name.size() + 1 && file.compare(0, name.size() + 1, name + "-") == 0 &&
                              file.find('-', name.size() + 1) == std::string::npos && other.path().extension() == ".bin";
        if (sameName && other.path().string() != path) std::filesystem::remove(other.path(), error);  // another build's
    }
    const std::uint64_t size = bytes.size(), sum = cacheChecksum(bytes.data(), bytes.size());
    std::string contents(kMagic, sizeof kMagic);
    contents.append(reinterpret_cast<const char*>(&size), sizeof size);
    contents.append(reinterpret_cast<const char*>(&sum), sizeof sum);
    contents += bytes;
    (void)writeFileAtomically(path, contents);  // a cache: a failed write only costs the next start
}

}  // namespace glint
