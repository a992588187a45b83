// libFuzzer target: the tools' glTF scene loader (tools/scene/gltf_scene.cpp, over
// tinygltf compiled into the fuzz build) on .gltf JSON and .glb bytes, then the scene on a
// CPU-only context (fuzz_scene_use.hpp) with the file's colliders. The input is the file;
// the loader takes a GLB by its magic ("glTF"), anything else as JSON. Beside it lie a
// buffer (buffer.bin: the corpus quad's 124 bytes) and a PNG (density.png) for a .gltf to
// name by URI, and the loader must keep any other URI (an absolute path, "..") unread.
// A refused file says why, and a loaded one has a field the library takes or refuses cleanly.
#include "fuzz_scene_use.hpp"

#include "gltf_scene.hpp"

#include <png.h>

#include <cstdio>
#include <cstring>
#include <vector>

namespace {

// The corpus quad's buffer (tests/fuzz/corpus/gltf/quad-*.gltf): positions, indices, colours.
std::vector<unsigned char> quad_buffer() {
    const float positions[12] = {0, 0, 0, 4, 0, 0, 0, 1, 4, 4, 1, 4};
    const uint16_t indices[6] = {0, 2, 1, 1, 2, 3};
    const float colors[16] = {1, 1, 1, 1, 1, 1, 1, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    std::vector<unsigned char> bin(124, 0);
    std::memcpy(bin.data(), positions, 48);
    std::memcpy(bin.data() + 48, indices, 12);
    std::memcpy(bin.data() + 60, colors, 64);
    return bin;
}

void write_density_png(const std::string& path) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = png.height = 4;
    png.format = PNG_FORMAT_RGBA;
    std::vector<uint8_t> pixels(64);
    for (size_t k = 0; k < pixels.size(); ++k) pixels[k] = static_cast<uint8_t>(k * 4);
    if (!png_image_write_to_file(&png, path.c_str(), 0, pixels.data(), 0, nullptr)) std::abort();
}

grass_collider to_collider(const grass_sample::GltfCollider& g) {
    grass_collider c{};
    c.shape = g.shape == grass_sample::GltfCollider::Shape::sphere ? GRASS_COLLIDER_SPHERE : GRASS_COLLIDER_CAPSULE;
    c.radius = static_cast<float>(g.radius);
    std::memcpy(c.center, g.a, sizeof(c.center));
    std::memcpy(c.end, g.b, sizeof(c.end));
    return c;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string dir = [] {
        const std::string d = grass_fuzz::scratch_dir();
        const std::vector<unsigned char> bin = quad_buffer();
        if (!grass_fuzz::write_bytes(d + "/buffer.bin", bin.data(), bin.size())) std::abort();
        write_density_png(d + "/density.png");
        return d;
    }();
    const bool glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    const std::string path = dir + (glb ? "/scene.glb" : "/scene.gltf");
    if (!grass_fuzz::write_bytes(path, data, size)) std::abort();
    grass_sample::Scene scene = grass_sample::demo_scene();
    const uint32_t marker = scene.field.cells_x;
    grass_sample::GltfInfo info;
    std::string error;
    if (grass_sample::load_gltf_scene(path, &scene, &info, &error)) {
        std::vector<grass_collider> colliders;
        for (const grass_sample::GltfCollider& c : info.colliders) colliders.push_back(to_collider(c));
        grass_fuzz::use_scene(scene, colliders);
    } else if (error.empty() || error.compare(0, path.size(), path) != 0) {
        std::fprintf(stderr, "a refused file gave the error \"%s\", which does not start with its path\n",
                     error.c_str());
        std::abort();
    } else if (error.size() > path.size() + 1000) { // values and names are cut (issue 37)
        std::fprintf(stderr, "a refused file gave a message of %zu bytes\n", error.size());
        std::abort();
    } else if (scene.field.cells_x != marker || !scene.meshes.empty()) {
        std::fprintf(stderr, "a refused file changed the scene\n");
        std::abort();
    }
    return 0;
}
