// Drawing ImGui's frame with unchanged windows copied (see ui_layer_cache.h).
#include "editor/ui_layer_cache.h"

#include <imgui_impl_opengl3.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <vector>

namespace glint {
namespace {

// FNV-1a over 8-byte words (and the bytes left over).
void hashBytes(std::uint64_t& hash, const void* data, size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    size_t i = 0;
    for (; i + 8 <= size; i += 8) {
        std::uint64_t word;
        std::memcpy(&word, bytes + i, 8);
        hash = (hash ^ word) * 1099511628211ull;
    }
    for (; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
}

// What the list's pixels follow from but its vertices: the vertex count, indices and commands.
std::uint64_t hashStructure(const ImDrawList& list) {
    std::uint64_t hash = 14695981039346656037ull;
    hashBytes(hash, &list.VtxBuffer.Size, sizeof list.VtxBuffer.Size);
    hashBytes(hash, list.IdxBuffer.Data, static_cast<size_t>(list.IdxBuffer.Size) * sizeof(ImDrawIdx));
    for (const ImDrawCmd& command : list.CmdBuffer) {
        hashBytes(hash, &command.ClipRect, sizeof command.ClipRect);
        hashBytes(hash, &command.TextureId, sizeof command.TextureId);
        const unsigned ranges[3] = {command.VtxOffset, command.IdxOffset, command.ElemCount};
        hashBytes(hash, ranges, sizeof ranges);
    }
    return hash;
}

// The bounding box (x1, y1, x2, y2) of what the list draws: each command's triangles within its
// clip rectangle, within the display. Empty (x2 <= x1) for a list that draws nothing.
ImVec4 listBounds(const ImDrawList& list, const ImDrawData& data) {
    ImVec4 bounds(1e30f, 1e30f, -1e30f, -1e30f);
    for (const ImDrawCmd& command : list.CmdBuffer) {
        if (command.ElemCount == 0 || command.UserCallback) continue;
        ImVec4 drawn(1e30f, 1e30f, -1e30f, -1e30f);
        for (unsigned i = 0; i < command.ElemCount; ++i) {
            const ImVec2 p = list.VtxBuffer[static_cast<int>(command.VtxOffset + list.IdxBuffer[static_cast<int>(command.IdxOffset + i)])].pos;
            drawn.x = std::min(drawn.x, p.x), drawn.y = std::min(drawn.y, p.y);
            drawn.z = std::max(drawn.z, p.x), drawn.w = std::max(drawn.w, p.y);
        }
        bounds.x = std::min(bounds.x, std::max(drawn.x, command.ClipRect.x));
        bounds.y = std::min(bounds.y, std::max(drawn.y, command.ClipRect.y));
        bounds.z = std::max(bounds.z, std::min(drawn.z, command.ClipRect.z));
        bounds.w = std::max(bounds.w, std::min(drawn.w, command.ClipRect.w));
    }
    bounds.x = std::max(bounds.x, data.DisplayPos.x), bounds.y = std::max(bounds.y, data.DisplayPos.y);
    bounds.z = std::min(bounds.z, data.DisplayPos.x + data.DisplaySize.x);
    bounds.w = std::min(bounds.w, data.DisplayPos.y + data.DisplaySize.y);
    // Whole pixels: two lists that share a partly covered pixel overlap.
    return ImVec4(std::floor(bounds.x), std::floor(bounds.y), std::ceil(bounds.z), std::ceil(bounds.w));
}

bool empty(const ImVec4& r) { return r.z <= r.x || r.w <= r.y; }

// The bounds of the triangles with a vertex unlike the same vertex of `before` (a list of the same
// structure), their old and new corners both, a pixel wider: what a change of a slider's value or a
// label of the same length redraws. Empty when no vertex changed.
ImVec4 changedTriangles(const ImDrawList& list, const std::vector<ImDrawVert>& before) {
    ImVec4 bounds(1e30f, 1e30f, -1e30f, -1e30f);
    const auto add = [&bounds](const ImVec2& p) {
        bounds.x = std::min(bounds.x, p.x - 1.0f), bounds.y = std::min(bounds.y, p.y - 1.0f);
        bounds.z = std::max(bounds.z, p.x + 1.0f), bounds.w = std::max(bounds.w, p.y + 1.0f);
    };
    const auto same = [&](unsigned v) { return std::memcmp(&list.VtxBuffer[static_cast<int>(v)], &before[v], sizeof(ImDrawVert)) == 0; };
    for (const ImDrawCmd& command : list.CmdBuffer)
        for (unsigned i = 0; i + 2 < command.ElemCount; i += 3) {
            unsigned v[3];
            for (int k = 0; k < 3; ++k) v[k] = command.VtxOffset + list.IdxBuffer[static_cast<int>(command.IdxOffset + i + k)];
            if (same(v[0]) && same(v[1]) && same(v[2])) continue;
            for (unsigned vertex : v) add(list.VtxBuffer[static_cast<int>(vertex)].pos), add(before[vertex].pos);
        }
    return bounds;
}

ImVec4 intersection(const ImVec4& a, const ImVec4& b) {
    return ImVec4(std::max(a.x, b.x), std::max(a.y, b.y), std::min(a.z, b.z), std::min(a.w, b.w));
}

// The rectangle of the list's own window, when it is a plain window (not a popup, tooltip or child).
std::optional<ImVec4> plainWindowRect(const ImDrawList& list) {
    const ImGuiWindow* window = list._OwnerName ? ImGui::FindWindowByName(list._OwnerName) : nullptr;
    if (!window || window->DrawList != &list) return std::nullopt;
    if (window->Flags & (ImGuiWindowFlags_Popup | ImGuiWindowFlags_Tooltip | ImGuiWindowFlags_ChildWindow)) return std::nullopt;
    return ImVec4(std::floor(window->Pos.x), std::floor(window->Pos.y), std::ceil(window->Pos.x + window->Size.x),
                  std::ceil(window->Pos.y + window->Size.y));
}

bool overlap(const ImVec4& a, const ImVec4& b) { return a.x < b.z && b.x < a.z && a.y < b.w && b.y < a.w; }

// Drawn with the font atlas alone (an image's texture may change without its id), no callbacks.
bool fontOnly(const ImDrawList& list) {
    const ImTextureID font = ImGui::GetIO().Fonts->TexID;
    return std::all_of(list.CmdBuffer.begin(), list.CmdBuffer.end(),
                       [font](const ImDrawCmd& command) { return command.UserCallback == nullptr && command.TextureId == font; });
}

void renderLists(const ImDrawData& data, ImDrawList** lists, int count) {
    ImDrawData part = data;
    part.CmdLists = lists;
    part.CmdListsCount = count;
    part.TotalIdxCount = part.TotalVtxCount = 0;
    for (int i = 0; i < count; ++i) part.TotalIdxCount += lists[i]->IdxBuffer.Size, part.TotalVtxCount += lists[i]->VtxBuffer.Size;
    ImGui_ImplOpenGL3_RenderDrawData(&part);
}

}  // namespace

UiLayerCache::~UiLayerCache() {
    if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
    if (texture_) glDeleteTextures(1, &texture_);
}

void UiLayerCache::ensureTarget(int width, int height) {
    if (framebuffer_ && width == width_ && height == height_) return;
    if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
    if (texture_) glDeleteTextures(1, &texture_);
    width_ = width, height_ = height;
    entries_.clear();
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, width, height);
    glBindTexture(GL_TEXTURE_2D, 0);
    glGenFramebuffers(1, &framebuffer_);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void UiLayerCache::draw(ImDrawData* data, const ImVec4& viewport, const float clearColor[4]) {
    ++frame_;
    listsRedrawn_ = listsCopied_ = 0;
    const ImVec2 scale = data->FramebufferScale;
    const int fbWidth = static_cast<int>(data->DisplaySize.x * scale.x), fbHeight = static_cast<int>(data->DisplaySize.y * scale.y);
    if (fbWidth <= 0 || fbHeight <= 0) return;
    ensureTarget(fbWidth, fbHeight);
    const ImVec4 viewportBounds(viewport.x, viewport.y, viewport.x + viewport.z, viewport.y + viewport.w);
    std::vector<ImDrawList*> direct;  // drawn onto the screen as they come
    std::vector<ImVec4> drawnBefore;
    const auto flushDirect = [&] {
        if (!direct.empty()) renderLists(*data, direct.data(), static_cast<int>(direct.size()));
        direct.clear();
    };
    for (int n = 0; n < data->CmdListsCount; ++n) {
        ImDrawList* list = data->CmdLists[n];
        // A plain window's list is cut to its window's rectangle (its borders' anti-aliased fringe
        // reaches a pixel beyond, over the viewport and the neighbouring windows).
        const std::optional<ImVec4> windowRect = fontOnly(*list) ? plainWindowRect(*list) : std::nullopt;
        const ImVec4 drawn = listBounds(*list, *data);
        const ImVec4 bounds = windowRect ? intersection(drawn, *windowRect) : drawn;
        bool cached = windowRect && !empty(bounds) && !overlap(bounds, viewportBounds);
        for (const ImVec4& before : drawnBefore) cached = cached && !overlap(bounds, before);
        if (cached)
            for (ImDrawCmd& command : list->CmdBuffer) command.ClipRect = intersection(command.ClipRect, *windowRect);
        if (!empty(cached ? bounds : drawn)) drawnBefore.push_back(cached ? bounds : drawn);
        if (!cached) {
            direct.push_back(list);
            continue;
        }
        flushDirect();
        // The list's rectangle in framebuffer pixels, lower-left origin.
        const int x0 = std::max(0, static_cast<int>(std::floor((bounds.x - data->DisplayPos.x) * scale.x)));
        const int x1 = std::min(fbWidth, static_cast<int>(std::ceil((bounds.z - data->DisplayPos.x) * scale.x)));
        const int y0 = std::max(0, fbHeight - static_cast<int>(std::ceil((bounds.w - data->DisplayPos.y) * scale.y)));
        const int y1 = std::min(fbHeight, fbHeight - static_cast<int>(std::floor((bounds.y - data->DisplayPos.y) * scale.y)));
        if (x1 <= x0 || y1 <= y0) continue;
        const std::uint64_t structure = hashStructure(*list);
        Entry& entry = entries_[list];
        // Redrawn where its vertices changed when only they did, whole when more changed or it was
        // not drawn last frame (another list may have drawn there since).
        const bool continued = entry.frame + 1 == frame_ && entry.structure == structure &&
                               entry.vertices.size() == static_cast<size_t>(list->VtxBuffer.Size);
        const ImVec4 redrawn = continued ? intersection(changedTriangles(*list, entry.vertices), bounds) : bounds;
        if (!empty(redrawn)) {
            entry.structure = structure;
            entry.vertices.assign(list->VtxBuffer.begin(), list->VtxBuffer.end());
            const int rx0 = std::max(x0, static_cast<int>(std::floor((redrawn.x - data->DisplayPos.x) * scale.x)));
            const int rx1 = std::min(x1, static_cast<int>(std::ceil((redrawn.z - data->DisplayPos.x) * scale.x)));
            const int ry0 = std::max(y0, fbHeight - static_cast<int>(std::ceil((redrawn.w - data->DisplayPos.y) * scale.y)));
            const int ry1 = std::min(y1, fbHeight - static_cast<int>(std::floor((redrawn.y - data->DisplayPos.y) * scale.y)));
            glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
            glEnable(GL_SCISSOR_TEST);
            glScissor(rx0, ry0, std::max(0, rx1 - rx0), std::max(0, ry1 - ry0));
            glClearColor(clearColor[0], clearColor[1], clearColor[2], clearColor[3]);
            glClear(GL_COLOR_BUFFER_BIT);  // as the screen is under the list
            glDisable(GL_SCISSOR_TEST);
            // The backend scissors each command to its clip rectangle: kept to the redrawn part for the call.
            std::vector<ImVec4> clips;
            for (ImDrawCmd& command : list->CmdBuffer) clips.push_back(command.ClipRect), command.ClipRect = intersection(command.ClipRect, redrawn);
            renderLists(*data, &list, 1);
            for (int i = 0; i < list->CmdBuffer.Size; ++i) list->CmdBuffer[i].ClipRect = clips[static_cast<size_t>(i)];
            ++listsRedrawn_;
        } else {
            ++listsCopied_;
        }
        entry.frame = frame_;
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        glBlitFramebuffer(x0, y0, x1, y1, x0, y0, x1, y1, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    flushDirect();
    // Lists no longer drawn (closed windows) are forgotten.
    for (auto it = entries_.begin(); it != entries_.end();) it = it->second.frame == frame_ ? std::next(it) : entries_.erase(it);
}

}  // namespace glint
