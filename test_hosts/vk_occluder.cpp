#include "vk_occluder.hpp"

#include <algorithm>

namespace grass_host {

// The host's own scene: a camera-facing box face, drawn as a cleared rectangle of colour
// and depth (its window depth is that of view-space z = -distance).
void record_occluder(VkCommandBuffer cmd, const TargetDesc& target, const grass_view_desc& view,
                     const Occluder& occluder) {
    const int32_t w = int32_t(target.width), h = int32_t(target.height);
    const int32_t x0 = std::max(occluder.x0, 0), x1 = std::min(occluder.x1, w);
    const int32_t y0 = std::max(occluder.y0, 0), y1 = std::min(occluder.y1, h);
    if (x1 <= x0 || y1 <= y0) return;
    const float* p = view.projection;
    const float z = -occluder.distance;
    const float clip_z = p[10] * z + p[14];
    const float clip_w = p[11] * z + p[15];
    const float depth = std::min(std::max(clip_z / clip_w, 0.0f), 1.0f);

    VkClearAttachment clears[2] = {};
    clears[0].aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
    clears[0].colorAttachment = 0;
    for (int c = 0; c < 3; ++c) {
        const float linear = occluder.color[c];
        clears[0].clearValue.color.float32[c] = target.unorm_color ? linear_to_srgb(linear) : linear;
    }
    clears[0].clearValue.color.float32[3] = 1.0f;
    clears[1].aspectMask = VK_IMAGE_ASPECT_DEPTH_BIT;
    clears[1].clearValue.depthStencil = {depth, 0};
    VkClearRect rect{};
    rect.rect = {{x0, y0}, {uint32_t(x1 - x0), uint32_t(y1 - y0)}}; // top-left origin, as the occluder's
    rect.layerCount = 1;
    vkCmdClearAttachments(cmd, 2, clears, 1, &rect);
}

} // namespace grass_host
