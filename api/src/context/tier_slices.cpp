#include "context/tier_slices.hpp"

#include "bake/bake_cache.hpp"
#include "bake/slice_baker.hpp"
#include "context/invariants.hpp"
#include "foundation/validate.hpp"
#include "patch/random.hpp"

namespace grass {

namespace {

grass_result ensure_slices(grass_context* ctx, const char* fn, uint32_t patch_slot, uint32_t slices_per_axis) {
    Patch* patch = ctx->patches.get(patch_slot);
    if (patch->slices(slices_per_axis)) return GRASS_SUCCESS; // baked and uploaded before
    SliceSet* set = ctx->host.create<SliceSet>(&ctx->host);
    try {
        const char* dir = ctx->desc.cache_directory;
        // The desc and the generated patch itself: a change of the generator never serves
        // stale slices from the cache.
        const uint64_t key =
            fnv1a64(&patch->data.content_hash, sizeof(uint64_t), bake_key(patch->desc, slices_per_axis, 0, 0));
        char path[kCachePathCapacity] = "";
        const CacheMiss miss = dir ? load_baked(dir, key, &ctx->host, set, path) : CacheMiss::missing;
        if (miss != CacheMiss::none) {
            if (miss != CacheMiss::missing) {
                ctx->warn(GRASS_MSG_BAKE_CACHE, "%s: the bake cache file %s %s; its slices are baked again", fn, path,
                          cache_miss_phrase(miss));
            }
            bake_slices(patch->data, slices_per_axis, 0, 0, &ctx->host, set);
            // A directory or FIFO under the name stays: it was named in the warning above,
            // and a store would only fail and warn again about the directory.
            const bool store = dir && miss != CacheMiss::not_regular;
            if (store && !store_baked(dir, key, *set) && !ctx->cache_write_warned) {
                ctx->cache_write_warned = true;
                ctx->warn(GRASS_MSG_BAKE_CACHE,
                          "%s: cannot write to the cache directory %s (missing, not a directory, read-only or full); "
                          "the slices this context bakes are not kept",
                          fn, dir);
            }
        }
        grass_result r = check_slice_set(ctx, fn, patch_slot, *set);
        if (r == GRASS_SUCCESS) r = ctx->backend->upload_slices(patch_slot, *set);
        if (r != GRASS_SUCCESS) {
            ctx->host.destroy(set);
            return r;
        }
        patch->slice_sets.push_back(set);
    } catch (...) {
        ctx->host.destroy(set);
        throw;
    }
    return GRASS_SUCCESS;
}

} // namespace

grass_result prepare_tier_slices(grass_context* ctx, const char* fn, uint32_t patch_slot, const LodSetup& lod) {
    if (ctx->backend->kind() == GRASS_BACKEND_NONE) return GRASS_SUCCESS; // nothing draws: nothing to bake
    for (uint32_t t = 0; t < lod.tier_count; ++t) {
        const grass_tier_desc& tier = lod.tiers[t];
        if (tier.kind == GRASS_TIER_VOLUME) GRASS_TRY(ensure_slices(ctx, fn, patch_slot, tier.slices));
        if (tier.kind == GRASS_TIER_IMAGE) GRASS_TRY(ensure_slices(ctx, fn, patch_slot, 0));
    }
    return GRASS_SUCCESS;
}

} // namespace grass
