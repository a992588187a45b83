/* doc-test prelude (tests/docs/run_doc_examples.py): a fragment of the docs in which a Vulkan
 * host hands grass its cascaded shadow map (grass_shadow_receive_desc `receive`), with the
 * host's command buffer, depth image and its 2D array view as stand-ins (no Vulkan device
 * here: vkCmdPipelineBarrier below keeps the barrier to check it). Run: the barrier must
 * leave the map in the layout `receive` names, visible to fragment-shader reads. */
#define VK_NO_PROTOTYPES
#include <grass/grass.h>
#include <vulkan/vulkan.h>

#include <stdint.h>
#include <stdio.h>

static VkImageMemoryBarrier recorded;
static VkPipelineStageFlags recorded_stage;

static void vkCmdPipelineBarrier(VkCommandBuffer cmd, VkPipelineStageFlags src, VkPipelineStageFlags dst,
                                 VkDependencyFlags flags, uint32_t memory_count, const VkMemoryBarrier* memory,
                                 uint32_t buffer_count, const VkBufferMemoryBarrier* buffers, uint32_t image_count,
                                 const VkImageMemoryBarrier* images) {
    (void)cmd, (void)src, (void)flags, (void)memory_count, (void)memory, (void)buffer_count, (void)buffers;
    if (image_count == 1) recorded = images[0];
    recorded_stage = dst;
}

int main(void) {
    VkCommandBuffer cmd = NULL;
    const VkImage engine_shadow_image = (VkImage)(uintptr_t)0x5a5a;
    const VkImageView engine_shadow_array_view = (VkImageView)(uintptr_t)0x6b6b;
    grass_shadow_receive_desc receive = grass_default_shadow_receive_desc();
    /* clang-format off */
    /* doc-test block */
    /* clang-format on */
    if (receive.shadow_map != (uint64_t)(uintptr_t)engine_shadow_array_view ||
        receive.vk_image_layout != (uint32_t)recorded.newLayout || recorded.image != engine_shadow_image ||
        !(recorded.dstAccessMask & VK_ACCESS_SHADER_READ_BIT) ||
        !(recorded_stage & VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT)) {
        fprintf(stderr, "doc-test: the map's barrier and grass_shadow_receive_desc disagree\n");
        return 1;
    }
    printf("doc-test: the map is read-only for fragment shaders in the layout grass is told\n");
    return 0;
}
