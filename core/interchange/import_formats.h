// The interchange formats Glint opens, by file extension: one row per format with the loader
// that turns a file into materials and lights. The editor (File ▸ Open, drag-and-drop) and
// `glint render` route through this table; adding a format is adding a row.
#pragma once

#include <span>
#include <string>

#include "interchange/imported.h"

namespace glint {

struct ImportFormat {
    const char* extension;    // lower case, with the dot: ".mtl"
    const char* description;  // "Wavefront material library"
    Result<ImportedFile> (*load)(const std::string& path);
};

std::span<const ImportFormat> importFormats();
// The row whose extension matches the path's (case-insensitive), or nullptr.
const ImportFormat* findImportFormat(const std::string& path);

}  // namespace glint
