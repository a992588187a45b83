/* doc-test prelude (tests/docs/run_doc_examples.py): a fragment of the docs that chains an
 * extension on a Vulkan host's grass_vk_desc `vk` (grass_vk_create_context's argument), with
 * the host's shadow render pass and depth format as stand-ins (no Vulkan device here: the
 * context is not made). Run: the chain must then hold a grass_vk_depth_pass_desc with the
 * fields set. */
#include <grass/grass_vk.h>

#include <stdint.h>
#include <stdio.h>

int main(void) {
    grass_vk_desc vk = grass_default_vk_desc();
    const uint64_t shadow_render_pass = 0x5a5a; /* the host's VkRenderPass of its shadow maps */
    const uint32_t shadow_depth_format = 126;   /* VK_FORMAT_D32_SFLOAT */
    const grass_vk_depth_pass_desc* chained;
    /* clang-format off */
    /* doc-test block */
    /* clang-format on */
    chained = (const grass_vk_depth_pass_desc*)vk.next;
    if (!chained || chained->type != GRASS_STRUCT_TYPE_VK_DEPTH_PASS_DESC ||
        chained->render_pass != shadow_render_pass || chained->depth_format != shadow_depth_format ||
        chained->sample_count != 1) {
        fprintf(stderr, "doc-test: vk.next holds no grass_vk_depth_pass_desc of the shadow pass\n");
        return 1;
    }
    printf("doc-test: vk.next chains the shadow pass's grass_vk_depth_pass_desc\n");
    return 0;
}
