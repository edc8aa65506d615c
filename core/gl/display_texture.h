// An 8-bit display image as a GL texture, top row first (as ImGui's UVs run), for the
// editor's pictures drawn with ImGui::Image. The caller owns the texture.
#pragma once

#include <glad/gl.h>

#include "image/image.h"

namespace glint {

// `filter`: GL_NEAREST to show pixels as they are, GL_LINEAR where the picture is scaled. Into
// `texture` when one is given (its old image replaced), else into a new one.
inline GLuint uploadDisplayTexture(const DisplayImage& image, GLint filter, GLuint texture = 0) {
    if (!texture) glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, image.width, image.height, 0, GL_RGB, GL_UNSIGNED_BYTE, image.pixels.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glBindTexture(GL_TEXTURE_2D, 0);
    return texture;
}

}  // namespace glint
