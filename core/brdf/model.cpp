// Names by convention (see model.h).
#include "brdf/model.h"

#include <cctype>

namespace glint {

std::string glslModelName(std::string_view id) {
    std::string name;
    bool upper = true;
    for (char c : id) {
        if (c == '_') upper = true;
        else name += upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c, upper = false;
    }
    return name;
}

std::string glslOptionConstant(std::string_view param, std::string_view option) {
    std::string name = std::string(param) + "_" + std::string(option);
    for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return name;
}

}  // namespace glint
