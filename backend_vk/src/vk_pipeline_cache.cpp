// The Vulkan backend's pipeline cache and grass_prepare_pipelines: every pipeline goes through
// the host's VkPipelineCache (grass_vk_host_objects_desc.pipeline_cache) or grass's own, which
// grass_get_pipeline_cache_data saves (vkGetPipelineCacheData behind grass's blob header,
// context/pipeline_blob.hpp) and grass_pipeline_desc.cache_data seeds (vkMergePipelineCaches
// from a cache made of the blob, after its headers were checked against this device).
#include "vk_backend.hpp"
#include "vk_labels.hpp"

#include "context/context.hpp"
#include "context/pipeline_blob.hpp"
#include "patch/random.hpp"

#include <cstring>

namespace grass::vk {

namespace {

// The device a cache's data is for: what VkPipelineCacheHeaderVersionOne records.
uint64_t device_identity(const VkPhysicalDeviceProperties& p) {
    uint64_t hash = fnv1a64(&p.vendorID, sizeof p.vendorID, kFnvOffset);
    hash = fnv1a64(&p.deviceID, sizeof p.deviceID, hash);
    hash = fnv1a64(&p.driverVersion, sizeof p.driverVersion, hash);
    return fnv1a64(p.pipelineCacheUUID, VK_UUID_SIZE, hash);
}

} // namespace

bool VkBackend::create_pipeline_cache(VkFailure* failure, const char** what) {
    if (device_.host_pipeline_cache != VK_NULL_HANDLE) {
        cache_ = device_.host_pipeline_cache;
        return true;
    }
    VkPipelineCacheCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
    *what = "grass's pipeline cache";
    if (!vk_ok(fn_.vkCreatePipelineCache(device_.device, &info, fn_.callbacks(), &own_cache_), "vkCreatePipelineCache",
               failure)) {
        return false;
    }
    name_object(fn_, device_.device, VK_OBJECT_TYPE_PIPELINE_CACHE, own_cache_, "grass pipeline cache");
    cache_ = own_cache_;
    return true;
}

void VkBackend::destroy_pipeline_cache() {
    if (own_cache_ != VK_NULL_HANDLE) fn_.vkDestroyPipelineCache(device_.device, own_cache_, fn_.callbacks());
    own_cache_ = cache_ = VK_NULL_HANDLE;
}

grass_result VkBackend::prepare_variants(const char* function, const ShaderVariant* variants, uint32_t count,
                                         bool interaction_pass, bool no_depth_test, const GBufferLayout* gbuffer) {
    VkFailure failure;
    const char* what = "";
    // G-buffer pipelines are made per layout: those of `gbuffer` (a frame selects its view's
    // layout again before it looks any up: record).
    if (gbuffer != nullptr) pipeline_.select_gbuffer(GBufferRoutes::of(*gbuffer));
    for (uint32_t i = 0; i < count; ++i) {
        if ((variants[i].features & kFeatureGBuffer) && gbuffer == nullptr) continue; // no layout to make them for
        if (!pipeline_.create_variant(variants[i], true, &failure, &what)) return fail(function, what, failure);
        // A blade window variant's draws are posed by the window pass of their features.
        if ((variants[i].features & kFeatureBladeWindow) &&
            !window_.ensure_pipeline(pipeline_.set_layout(), variants[i].features, &failure, &what))
            return fail(function, what, failure);
        // GRASS_VIEW_FLAG_NO_DEPTH_TEST draws with pipelines of their own, made only when the
        // host declared the debug views (or by the first frame that sets the flag: record).
        if (no_depth_test && takes_no_depth_test(variants[i]) &&
            !pipeline_.create_variant(variants[i], false, &failure, &what))
            return fail(function, what, failure);
    }
    if (interaction_pass && !interaction_.ensure_pipeline(&failure, &what)) return fail(function, what, failure);
    return GRASS_SUCCESS;
}

grass_result VkBackend::seed_pipeline_cache(const char* function, const void* data, uint64_t size) {
    if (own_cache_ == VK_NULL_HANDLE) {
        return ctx_->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_OUT_OF_RANGE,
                          "%s: desc->cache_data is given but the context uses the host's VkPipelineCache "
                          "(grass_vk_host_objects_desc.pipeline_cache 0x%llx); seed that cache instead",
                          function, static_cast<unsigned long long>(reinterpret_cast<uint64_t>(cache_)));
    }
    const VkPhysicalDeviceProperties& p = device_.properties;
    uint64_t bytes = 0;
    const unsigned char* payload =
        open_pipeline_blob(ctx_, function, GRASS_BACKEND_VULKAN, device_identity(p), data, size, &bytes);
    if (payload == nullptr) return GRASS_SUCCESS;
    // VkPipelineCacheHeaderVersionOne: size, version, vendor, device, UUID (32 bytes).
    uint32_t header[4] = {};
    if (bytes >= 32) std::memcpy(header, payload, sizeof header);
    if (bytes < 32 || header[0] < 32 || header[0] > bytes || header[1] != VK_PIPELINE_CACHE_HEADER_VERSION_ONE ||
        header[2] != p.vendorID || header[3] != p.deviceID ||
        std::memcmp(payload + 16, p.pipelineCacheUUID, VK_UUID_SIZE) != 0) {
        ctx_->warn(GRASS_MSG_PIPELINE_CACHE,
                   "%s: desc->cache_data is ignored: its Vulkan cache header does not match this device; grass "
                   "compiles instead",
                   function);
        return GRASS_SUCCESS;
    }
    VkPipelineCacheCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
    info.initialDataSize = static_cast<size_t>(bytes);
    info.pInitialData = payload;
    VkPipelineCache seeded = VK_NULL_HANDLE;
    VkFailure failure;
    if (!vk_ok(fn_.vkCreatePipelineCache(device_.device, &info, fn_.callbacks(), &seeded), "vkCreatePipelineCache",
               &failure)) {
        return fail(function, "a pipeline cache of desc->cache_data", failure);
    }
    const bool merged =
        vk_ok(fn_.vkMergePipelineCaches(device_.device, own_cache_, 1, &seeded), "vkMergePipelineCaches", &failure);
    fn_.vkDestroyPipelineCache(device_.device, seeded, fn_.callbacks());
    return merged ? GRASS_SUCCESS : fail(function, "grass's pipeline cache", failure);
}

grass_result VkBackend::pipeline_cache_data(const char* function, void* data, uint64_t* size) {
    if (own_cache_ == VK_NULL_HANDLE) {
        return ctx_->fail(
            GRASS_ERROR_INVALID_STATE, GRASS_MSG_OUT_OF_RANGE,
            "%s: the context uses the host's VkPipelineCache (grass_vk_host_objects_desc.pipeline_cache 0x%llx); "
            "save it with vkGetPipelineCacheData",
            function, static_cast<unsigned long long>(reinterpret_cast<uint64_t>(cache_)));
    }
    VkFailure failure;
    size_t bytes = 0;
    if (!vk_ok(fn_.vkGetPipelineCacheData(device_.device, own_cache_, &bytes, nullptr), "vkGetPipelineCacheData",
               &failure)) {
        return fail(function, "grass's pipeline cache", failure);
    }
    const uint64_t total = kPipelineBlobHeaderBytes + bytes;
    if (data == nullptr) {
        *size = total;
        return GRASS_SUCCESS;
    }
    if (*size < total) {
        return ctx_->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                          "%s: *size is %llu; the blob needs %llu bytes (call with data NULL to learn the size)",
                          function, static_cast<unsigned long long>(*size), static_cast<unsigned long long>(total));
    }
    unsigned char* payload = static_cast<unsigned char*>(data) + kPipelineBlobHeaderBytes;
    // The cache may only have grown since the size was asked for: VK_INCOMPLETE then.
    size_t written = bytes;
    const VkResult r = fn_.vkGetPipelineCacheData(device_.device, own_cache_, &written, payload);
    if (r != VK_SUCCESS && r != VK_INCOMPLETE) {
        vk_ok(r, "vkGetPipelineCacheData", &failure);
        return fail(function, "grass's pipeline cache", failure);
    }
    write_pipeline_blob_header(GRASS_BACKEND_VULKAN, device_identity(device_.properties), payload, written, data);
    *size = kPipelineBlobHeaderBytes + written;
    return GRASS_SUCCESS;
}

} // namespace grass::vk
