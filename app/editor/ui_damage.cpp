// Where ImGui's frame changed, and drawing it there only (see ui_damage.h).
#include "editor/ui_damage.h"

#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <cstring>

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

// What the list's pixels follow from but its vertices: the vertex count, indices and commands;
// 0 for a list drawn with another texture than the font atlas, or with a callback (never the same).
std::uint64_t hashStructure(const ImDrawList& list) {
    const ImTextureID font = ImGui::GetIO().Fonts->TexID;
    std::uint64_t hash = 14695981039346656037ull;
    hashBytes(hash, &list.VtxBuffer.Size, sizeof list.VtxBuffer.Size);
    hashBytes(hash, list.IdxBuffer.Data, static_cast<size_t>(list.IdxBuffer.Size) * sizeof(ImDrawIdx));
    for (const ImDrawCmd& command : list.CmdBuffer) {
        if (command.UserCallback || command.TextureId != font) return 0;
        hashBytes(hash, &command.ClipRect, sizeof command.ClipRect);
        const unsigned ranges[3] = {command.VtxOffset, command.IdxOffset, command.ElemCount};
        hashBytes(hash, ranges, sizeof ranges);
    }
    return hash == 0 ? 1 : hash;
}

// An ImGui rectangle (x1, y1, x2, y2) in framebuffer pixels, lower-left origin: the whole pixels it
// touches, within the framebuffer. Clamped before the conversion to int: an empty rectangle is
// (1e30, 1e30, -1e30, -1e30), far outside int's range.
PixelRegion toPixels(const ImVec4& r, const ImDrawData& data) {
    const ImVec2 scale = data.FramebufferScale;
    const int width = static_cast<int>(data.DisplaySize.x * scale.x), height = static_cast<int>(data.DisplaySize.y * scale.y);
    const auto within = [](float value, int limit) { return static_cast<int>(std::clamp(value, 0.0f, static_cast<float>(limit))); };
    const int x0 = within(std::floor((r.x - data.DisplayPos.x) * scale.x), width);
    const int x1 = within(std::ceil((r.z - data.DisplayPos.x) * scale.x), width);
    const int top = within(std::floor((r.y - data.DisplayPos.y) * scale.y), height);
    const int bottom = within(std::ceil((r.w - data.DisplayPos.y) * scale.y), height);
    if (x1 <= x0 || bottom <= top) return {};
    return {x0, height - bottom, x1 - x0, bottom - top};
}

// What the list draws: each command's triangles within its clip rectangle.
PixelRegion listBounds(const ImDrawList& list, const ImDrawData& data) {
    PixelRegion bounds;
    for (const ImDrawCmd& command : list.CmdBuffer) {
        if (command.ElemCount == 0) continue;
        ImVec4 drawn(1e30f, 1e30f, -1e30f, -1e30f);
        for (unsigned i = 0; i < command.ElemCount; ++i) {
            const ImVec2 p = list.VtxBuffer[static_cast<int>(command.VtxOffset + list.IdxBuffer[static_cast<int>(command.IdxOffset + i)])].pos;
            drawn.x = std::min(drawn.x, p.x), drawn.y = std::min(drawn.y, p.y);
            drawn.z = std::max(drawn.z, p.x), drawn.w = std::max(drawn.w, p.y);
        }
        const ImVec4& clip = command.ClipRect;
        const ImVec4 within(std::max(drawn.x, clip.x), std::max(drawn.y, clip.y), std::min(drawn.z, clip.z), std::min(drawn.w, clip.w));
        bounds = boundsOf(bounds, toPixels(within, data));
    }
    return bounds;
}

// The bounds of the triangles with a vertex unlike the same vertex of `before` (a list of the same
// structure), their old and new corners both, a pixel wider: what a change of a slider's value or
// a label of the same length redraws.
PixelRegion changedTriangles(const ImDrawList& list, const std::vector<ImDrawVert>& before, const ImDrawData& data) {
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
    return toPixels(bounds, data);
}

bool overlap(const PixelRegion& a, const PixelRegion& b) {
    return a.width > 0 && a.height > 0 && b.width > 0 && b.height > 0 && a.x < b.x + b.width && b.x < a.x + a.width &&
           a.y < b.y + b.height && b.y < a.y + a.height;
}

}  // namespace

void UiDamage::collect(const ImDrawData& data, std::vector<PixelRegion>& damage) {
    ++frame_;
    for (int n = 0; n < data.CmdListsCount; ++n) {
        const ImDrawList& list = *data.CmdLists[n];
        const std::uint64_t structure = hashStructure(list);
        const PixelRegion bounds = listBounds(list, data);
        Entry& entry = entries_[&list];
        const bool continued = entry.frame + 1 == frame_;
        PixelRegion changed = continued ? entry.bounds : PixelRegion{};  // where it drew, and draws
        if (!continued || structure == 0 || structure != entry.structure || bounds.width == 0)
            changed = boundsOf(changed, bounds);
        else
            changed = intersectionOf(changedTriangles(list, entry.vertices, data), boundsOf(changed, bounds));
        damage.push_back(changed);  // (mergeOverlapping drops it when empty)
        entry.structure = structure;
        entry.vertices.assign(list.VtxBuffer.begin(), list.VtxBuffer.end());
        entry.bounds = bounds;
        entry.frame = frame_;
    }
    // Lists no longer drawn (closed windows, a popup gone) leave their pixels to the rest.
    for (auto it = entries_.begin(); it != entries_.end();) {
        if (it->second.frame == frame_) {
            ++it;
            continue;
        }
        damage.push_back(it->second.bounds);
        it = entries_.erase(it);
    }
}

void UiDamage::drawWithin(ImDrawData& data, const PixelRegion& rect) {
    // ImGui_ImplOpenGL3_RenderDrawData scissors each command to its clip rectangle in whole pixels
    // (truncated): those pixels, cut to `rect`, given back as a clip rectangle that truncates to them.
    const ImVec2 offset = data.DisplayPos, scale = data.FramebufferScale;
    const float fbHeight = static_cast<float>(static_cast<int>(data.DisplaySize.y * scale.y));
    std::vector<ImDrawList*> lists;
    std::vector<ImVec4> clips;
    for (int n = 0; n < data.CmdListsCount; ++n) {
        ImDrawList* list = data.CmdLists[n];
        bool reaches = false;
        for (ImDrawCmd& command : list->CmdBuffer) {
            clips.push_back(command.ClipRect);
            const ImVec2 low((command.ClipRect.x - offset.x) * scale.x, (command.ClipRect.y - offset.y) * scale.y);
            const ImVec2 high((command.ClipRect.z - offset.x) * scale.x, (command.ClipRect.w - offset.y) * scale.y);
            if (high.x <= low.x || high.y <= low.y) continue;
            const int x = static_cast<int>(low.x), y = static_cast<int>(fbHeight - high.y);
            const PixelRegion box{x, y, static_cast<int>(high.x - low.x), static_cast<int>(high.y - low.y)};
            const PixelRegion cut = intersectionOf(box, rect);
            const bool empty = cut.width == 0 || cut.height == 0;
            reaches = reaches || !empty;
            command.ClipRect = empty ? ImVec4(0.0f, 0.0f, 0.0f, 0.0f)
                                     : ImVec4(static_cast<float>(cut.x) / scale.x + offset.x,
                                              (fbHeight - static_cast<float>(cut.y + cut.height)) / scale.y + offset.y,
                                              static_cast<float>(cut.x + cut.width) / scale.x + offset.x,
                                              (fbHeight - static_cast<float>(cut.y)) / scale.y + offset.y);
        }
        if (reaches) lists.push_back(list);
    }
    if (!lists.empty()) {
        ImDrawData part = data;
        part.CmdLists = lists.data();
        part.CmdListsCount = static_cast<int>(lists.size());
        part.TotalIdxCount = part.TotalVtxCount = 0;
        for (const ImDrawList* list : lists) part.TotalIdxCount += list->IdxBuffer.Size, part.TotalVtxCount += list->VtxBuffer.Size;
        ImGui_ImplOpenGL3_RenderDrawData(&part);
    }
    size_t next = 0;
    for (int n = 0; n < data.CmdListsCount; ++n)
        for (ImDrawCmd& command : data.CmdLists[n]->CmdBuffer) command.ClipRect = clips[next++];
}

void mergeOverlapping(std::vector<PixelRegion>& rects) {
    rects.erase(std::remove_if(rects.begin(), rects.end(), [](const PixelRegion& r) { return r.width <= 0 || r.height <= 0; }),
                rects.end());
    for (bool merged = true; merged;) {
        merged = false;
        for (size_t i = 0; i < rects.size() && !merged; ++i)
            for (size_t j = i + 1; j < rects.size() && !merged; ++j)
                if (overlap(rects[i], rects[j])) {
                    rects[i] = boundsOf(rects[i], rects[j]);
                    rects.erase(rects.begin() + static_cast<std::ptrdiff_t>(j));
                    merged = true;
                }
    }
}

}  // namespace glint
