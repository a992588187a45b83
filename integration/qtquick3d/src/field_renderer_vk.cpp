// Vulkan: grass records into the command buffer Qt Quick renders the window with, inside
// its main render pass, with the device, render pass and sample count of the window.
#include "field_renderer_vk.hpp"

#include <grass/grass_vk.h>

#include <QQuickWindow>
#include <QSGRendererInterface>
#include <QVulkanFunctions>
#include <QVulkanInstance>

#include <algorithm>
#include <vector>

namespace grass_qt {

namespace {

template <typename T>
T resource(QQuickWindow* window, QSGRendererInterface::Resource which) {
    void* r = window->rendererInterface()->getResource(window, which);
    return r ? *static_cast<T*>(r) : T{};
}

// The sample count Qt Quick gives the window's swapchain (QSGRhiSupport: the larger of the
// default and the window's requested format, QSG_SAMPLES overriding).
uint32_t window_samples(const QQuickWindow* window) {
    int samples = std::max(QSurfaceFormat::defaultFormat().samples(), window->requestedFormat().samples());
    if (qEnvironmentVariableIsSet("QSG_SAMPLES")) samples = qEnvironmentVariableIntValue("QSG_SAMPLES");
    return samples > 1 ? static_cast<uint32_t>(samples) : 1u;
}

// QRhi's choice of depth-stencil format for a swapchain, in its order of preference.
VkFormat window_depth_format(QVulkanFunctions* f, VkPhysicalDevice physical_device) {
    for (VkFormat format : {VK_FORMAT_D24_UNORM_S8_UINT, VK_FORMAT_D32_SFLOAT_S8_UINT, VK_FORMAT_D16_UNORM_S8_UINT}) {
        VkFormatProperties p{};
        f->vkGetPhysicalDeviceFormatProperties(physical_device, format, &p);
        if (p.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT) return format;
    }
    return VK_FORMAT_D32_SFLOAT_S8_UINT;
}

// The first family with graphics, as QRhi picks for the window's queue.
uint32_t graphics_family(QVulkanFunctions* f, VkPhysicalDevice physical_device) {
    uint32_t count = 0;
    f->vkGetPhysicalDeviceQueueFamilyProperties(physical_device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    f->vkGetPhysicalDeviceQueueFamilyProperties(physical_device, &count, families.data());
    for (uint32_t i = 0; i < count; ++i)
        if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) return i;
    return 0;
}

} // namespace

VkFieldRenderer::~VkFieldRenderer() { destroy_context(); }

VkCommandBuffer VkFieldRenderer::command_buffer() const {
    return resource<VkCommandBuffer>(window_, QSGRendererInterface::CommandListResource);
}

bool VkFieldRenderer::create_context(const grass_context_desc& desc, QString* error) {
    instance_ = static_cast<QVulkanInstance*>(
        window_->rendererInterface()->getResource(window_, QSGRendererInterface::VulkanInstanceResource));
    const auto physical_device = resource<VkPhysicalDevice>(window_, QSGRendererInterface::PhysicalDeviceResource);
    device_ = resource<VkDevice>(window_, QSGRendererInterface::DeviceResource);
    const auto render_pass = resource<VkRenderPass>(window_, QSGRendererInterface::RenderPassResource);
    if (!instance_ || !physical_device || !device_ || !render_pass) {
        *error = QStringLiteral("the window's renderer interface handed out no Vulkan instance, device or render pass");
        return false;
    }
    // Qt's instances ask for Vulkan 1.0 unless told otherwise; grass's SPIR-V is for 1.1.
    const QVersionNumber api = instance_->apiVersion();
    if (api < QVersionNumber(1, 1)) {
        *error =
            QStringLiteral("the window's QVulkanInstance was made for Vulkan %1, grass needs 1.1: create one "
                           "with setApiVersion(QVersionNumber(1, 1)) and give it to QQuickWindow::setVulkanInstance")
                .arg(api.isNull() ? QStringLiteral("1.0") : api.toString());
        return false;
    }
    QVulkanFunctions* f = instance_->functions();
    grass_vk_desc vk = grass_default_vk_desc();
    vk.get_instance_proc_addr =
        reinterpret_cast<grass_vk_get_instance_proc_addr_fn>(instance_->getInstanceProcAddr("vkGetInstanceProcAddr"));
    vk.instance = instance_->vkInstance();
    vk.physical_device = physical_device;
    vk.device = device_;
    vk.queue_family = graphics_family(f, physical_device);
    vk.render_pass = reinterpret_cast<uint64_t>(render_pass);
    vk.subpass = 0;
    vk.depth_format = window_depth_format(f, physical_device);
    vk.sample_count = window_samples(window_);
    vk.frames_in_flight = static_cast<uint32_t>(std::max(1, window_->graphicsStateInfo().framesInFlight));
    if (grass_vk_create_context(GRASS_HEADER_VERSION, &desc, &vk, &context_) != GRASS_SUCCESS) {
        *error = QStringLiteral("grass_vk_create_context failed (%1 samples)").arg(vk.sample_count);
        return false;
    }
    return true;
}

grass_result VkFieldRenderer::prepare(QString* error) {
    grass_vk_prepare_desc prepare = grass_default_vk_prepare_desc();
    prepare.command_buffer = command_buffer();
    const grass_result r = grass_vk_prepare(context_, &prepare);
    if (r != GRASS_SUCCESS) *error = QString::fromUtf8(grass_get_last_error(context_));
    return r;
}

grass_result VkFieldRenderer::draw(QString* error) {
    grass_vk_record_desc record = grass_default_vk_record_desc();
    record.command_buffer = command_buffer(); // after beginExternalCommands: maybe a secondary buffer
    const grass_result r = grass_vk_record(context_, &record);
    if (r != GRASS_SUCCESS) *error = QString::fromUtf8(grass_get_last_error(context_));
    return r;
}

void VkFieldRenderer::wait_idle() {
    if (instance_ && device_) instance_->deviceFunctions(device_)->vkDeviceWaitIdle(device_);
}

} // namespace grass_qt
