#include "vk_spirv.hpp"

namespace grass::vk {

Spirv spirv(Shader shader, SpirvVariant variant) {
    const uint32_t index = static_cast<uint32_t>(shader);
    const uint32_t features = variant.features() & kSpirvShaderFeatures[index];
    for (uint32_t i = 0; i < kSpirvModuleCount; ++i) {
        const SpirvModule& m = kSpirvModules[i];
        if (m.shader == index && m.features == features) return Spirv{m.code, *m.size};
    }
    return Spirv{nullptr, 0};
}

} // namespace grass::vk
