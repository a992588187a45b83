#pragma once

#include "field_renderer.hpp"

#include <vulkan/vulkan.h>

class QVulkanInstance;

namespace grass_qt {

class VkFieldRenderer final : public FieldRenderer {
public:
    using FieldRenderer::FieldRenderer;
    ~VkFieldRenderer() override;

protected:
    bool create_context(const grass_context_desc& desc, QString* error) override;
    grass_result prepare(QString* error) override;
    grass_result draw(QString* error) override;
    void wait_idle() override;

private:
    VkCommandBuffer command_buffer() const;

    QVulkanInstance* instance_ = nullptr;
    VkDevice device_ = VK_NULL_HANDLE;
};

} // namespace grass_qt
