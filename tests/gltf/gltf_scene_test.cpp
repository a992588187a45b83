// glTF scenes (tools/scene/gltf_scene.hpp): the shipped sample scene becomes a field with
// height and density maps, host meshes, a camera and colliders; the terrain rasteriser puts
// heights where the mesh is; hostile files (truncated, wrong indices, huge counts, missing
// buffers, non-triangles, NaN, cycles, paths out of the folder) are refused with an error
// naming what is wrong, and leave the scene as it was. No GPU.
#include "gltf_scene.hpp"
#include "terrain_raster.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <random>
#include <sys/stat.h>
#include <unistd.h>

namespace {

using grass_sample::GltfInfo;
using grass_sample::load_gltf_scene;
using grass_sample::MapRole;
using grass_sample::Scene;
using nlohmann::json;

std::string scratch() {
    const std::string dir = ::testing::TempDir() + "grass_gltf_test/";
    mkdir(dir.c_str(), 0755);
    return dir;
}

void write_bytes(const std::string& path, const std::vector<unsigned char>& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

std::vector<unsigned char> read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), {});
}

// A small valid scene: a 4 m x 4 m terrain quad rising 1 m along +z, its density in COLOR_0.
struct Gltf {
    json doc;
    std::vector<unsigned char> bin;

    template <class T>
    void append(const T* values, size_t count) {
        const auto* p = reinterpret_cast<const unsigned char*>(values);
        bin.insert(bin.end(), p, p + count * sizeof(T));
        while (bin.size() % 4) bin.push_back(0);
    }

    static Gltf quad() {
        Gltf g;
        const float positions[12] = {0, 0, 0, 4, 0, 0, 0, 1, 4, 4, 1, 4};
        const uint16_t indices[6] = {0, 2, 1, 1, 2, 3};
        const float colors[16] = {1, 1, 1, 1, 1, 1, 1, 1, 0, 0, 0, 1, 0, 0, 0, 1}; // dense at z 0, bare at z 4
        g.append(positions, 12);
        g.append(indices, 6);
        g.append(colors, 16);
        g.doc = json::parse(R"({
          "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1]}],
          "nodes": [{"name": "terrain", "mesh": 0, "extras": {"grass": {"cell_size": 0.5}}},
                    {"name": "eye", "camera": 0, "translation": [2, 3, -5]}],
          "cameras": [{"type": "perspective", "perspective": {"yfov": 1.0, "znear": 0.1, "zfar": 300}}],
          "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "COLOR_0": 2}, "indices": 1}]}],
          "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
            {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"},
            {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC4"}],
          "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 48},
            {"buffer": 0, "byteOffset": 48, "byteLength": 12},
            {"buffer": 0, "byteOffset": 60, "byteLength": 64}],
          "buffers": [{"byteLength": 124}]
        })");
        return g;
    }

    std::vector<unsigned char> glb() const {
        std::string text = doc.dump();
        while (text.size() % 4) text += ' ';
        std::vector<unsigned char> out;
        auto word = [&](uint32_t v) {
            for (int k = 0; k < 4; ++k) out.push_back(uint8_t(v >> (8 * k)));
        };
        const bool has_bin = !bin.empty();
        word(0x46546C67); // glTF
        word(2);
        word(uint32_t(12 + 8 + text.size() + (has_bin ? 8 + bin.size() : 0)));
        word(uint32_t(text.size()));
        word(0x4E4F534A); // JSON
        out.insert(out.end(), text.begin(), text.end());
        if (has_bin) {
            word(uint32_t(bin.size()));
            word(0x004E4942); // BIN
            out.insert(out.end(), bin.begin(), bin.end());
        }
        return out;
    }
};

// Loads `bytes` as NAME into a scene; the error when it fails.
struct Loaded {
    bool ok = false;
    std::string error;
    Scene scene;
    GltfInfo info;
};
Loaded load_bytes(const std::string& name, const std::vector<unsigned char>& bytes) {
    const std::string path = scratch() + name;
    write_bytes(path, bytes);
    Loaded l;
    l.scene.field.cells_x = 7; // a marker: a refused file leaves the scene as it was
    l.ok = load_gltf_scene(path, &l.scene, &l.info, &l.error);
    return l;
}

// Expects the file refused with an error holding every one of `parts`, the scene untouched.
void expect_refused(const Loaded& l, std::initializer_list<const char*> parts) {
    ASSERT_FALSE(l.ok) << "accepted";
    for (const char* part : parts) EXPECT_NE(l.error.find(part), std::string::npos) << l.error;
    EXPECT_EQ(l.scene.field.cells_x, 7u) << "a refused file changed the scene";
    EXPECT_TRUE(l.scene.meshes.empty());
}

float height_at(const Scene::MapImage& m, uint32_t x, uint32_t z) {
    uint16_t v;
    std::memcpy(&v, &m.pixels[(size_t(z) * m.width + x) * 2], 2);
    return v / 65535.0f;
}

TEST(GltfScene, AQuadBecomesAFieldWithHeightAndDensityMapsACameraAndAHostMesh) {
    const Loaded l = load_bytes("quad.glb", Gltf::quad().glb());
    ASSERT_TRUE(l.ok) << l.error;
    const Scene& s = l.scene;
    EXPECT_EQ(s.field.cells_x, 8u); // 4 m of 0.5 m cells
    EXPECT_EQ(s.field.cells_z, 8u);
    EXPECT_DOUBLE_EQ(s.field.cell_size, 0.5);
    EXPECT_DOUBLE_EQ(s.field.base_transform[13], 0.0);
    EXPECT_FALSE(s.ground);
    const Scene::MapImage& h = s.map(MapRole::height);
    ASSERT_EQ(h.format, GRASS_MAP_FORMAT_R16_UNORM);
    ASSERT_EQ(h.width, 8u);
    EXPECT_FLOAT_EQ(s.height_scale, 1.0f);
    // Heights rise linearly with z: texel row j samples z = (j + 0.5) * 0.5 m of 4 m.
    for (uint32_t j = 0; j < 8; ++j) EXPECT_NEAR(height_at(h, 3, j), (j + 0.5) / 8.0, 1e-4) << "row " << j;
    // Density follows COLOR_0's red: 1 at z 0, 0 at z 4.
    const Scene::MapImage& d = s.map(MapRole::density);
    ASSERT_EQ(d.width, 8u);
    EXPECT_NEAR(d.pixels[0 * 8 + 4], 255 * (1 - 0.5 / 8), 1.0);
    EXPECT_NEAR(d.pixels[7 * 8 + 4], 255 * (0.5 / 8), 1.0);
    // The camera node: its position, looking down its -z (+z of the world here: identity).
    EXPECT_EQ(l.info.camera, "eye");
    EXPECT_DOUBLE_EQ(s.eye[1], 3.0);
    EXPECT_DOUBLE_EQ(s.target[2], -6.0);
    EXPECT_NEAR(s.fov_degrees, 57.2958f, 1e-3f);
    EXPECT_FLOAT_EQ(s.near_m, 0.1f);
    EXPECT_FLOAT_EQ(s.far_m, 300.0f);
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.meshes[0].indices.size(), 6u);
    EXPECT_DOUBLE_EQ(s.meshes[0].origin[0], 2.0);
}

TEST(GltfScene, TheSampleSceneHasItsTerrainRocksCameraAndColliders) {
    Scene s;
    GltfInfo info;
    std::string error;
    ASSERT_TRUE(load_gltf_scene(GRASS_GLTF_SAMPLE, &s, &info, &error)) << error;
    EXPECT_EQ(s.field.cells_x, 128u); // 32 m of 0.25 m cells
    EXPECT_EQ(s.field.cells_z, 128u);
    EXPECT_EQ(s.meshes.size(), 5u); // terrain, three rocks, the shed
    EXPECT_EQ(info.terrain_triangles, 48u * 48u * 2u);
    EXPECT_EQ(info.camera, "camera");
    ASSERT_EQ(info.colliders.size(), 2u);
    EXPECT_EQ(info.colliders[0].node, "ball");
    EXPECT_EQ(info.colliders[0].shape, grass_sample::GltfCollider::Shape::sphere);
    EXPECT_DOUBLE_EQ(info.colliders[0].radius, 0.3);
    EXPECT_EQ(info.colliders[1].shape, grass_sample::GltfCollider::Shape::capsule);
    EXPECT_NEAR(info.colliders[1].b[1] - info.colliders[1].a[1], 1.3, 1e-9);
    // The path: thin grass where the script's density is low (x = -2 at z = 0), full beside it.
    const Scene::MapImage& d = s.map(MapRole::density);
    auto density = [&](double x, double z) {
        const uint32_t i = uint32_t((x + 16.0) / 32.0 * d.width), j = uint32_t((z + 16.0) / 32.0 * d.height);
        return d.pixels[size_t(j) * d.width + i] / 255.0;
    };
    EXPECT_LT(density(-2.0, 0.0), 0.3);
    EXPECT_GT(density(4.0, 0.0), 0.9);
    // The hill's top (2.4 m above its surroundings, near (5, 6)) is the highest texel.
    EXPECT_GT(s.height_scale, 2.4f);
}

TEST(GltfScene, TheRasteriserPutsEachTexelOnTheHighestTriangleOverItsCentre) {
    // Two overlapping triangles over [0, 2] x [0, 2]: a floor at y 0 and, over the x < z
    // half, a roof at y 1. Texels above the diagonal take the roof.
    using grass_sample::TerrainVertex;
    std::vector<TerrainVertex> t(6);
    const double floor[3][3] = {{0, 0, 0}, {2, 0, 0}, {0, 0, 2}};
    const double roof[3][3] = {{0, 1, 0}, {2, 1, 2}, {0, 1, 2}};
    for (int k = 0; k < 3; ++k) {
        t[size_t(k)].x = floor[k][0], t[size_t(k)].y = floor[k][1], t[size_t(k)].z = floor[k][2];
        t[size_t(k + 3)].x = roof[k][0], t[size_t(k + 3)].y = roof[k][1], t[size_t(k + 3)].z = roof[k][2];
        t[size_t(k + 3)].a[0] = 0.5f;
    }
    const grass_sample::TerrainRaster r = grass_sample::rasterise_terrain(t, 0.0, 0.0, 2.0, 2.0, 4, 4);
    int covered = 0;
    for (uint32_t j = 0; j < 4; ++j) {
        for (uint32_t i = 0; i < 4; ++i) {
            const size_t texel = j * 4 + i;
            const bool under_floor = i + j <= 3; // centre x + z <= 2
            const bool under_roof = i <= j;      // centre x <= z
            EXPECT_EQ(r.covered(texel), under_floor || under_roof) << i << "," << j;
            if (!r.covered(texel)) continue;
            ++covered;
            EXPECT_DOUBLE_EQ(r.y[texel], under_roof ? 1.0 : 0.0) << i << "," << j;
            EXPECT_FLOAT_EQ(r.a[0][texel], under_roof ? 0.5f : 0.0f);
        }
    }
    EXPECT_EQ(covered, 14);
}

TEST(GltfScene, ATruncatedGlbIsRefused) {
    std::vector<unsigned char> bytes = Gltf::quad().glb();
    bytes.resize(bytes.size() - 40);
    expect_refused(load_bytes("truncated.glb", bytes), {"truncated.glb", "truncated", "header says"});
    expect_refused(load_bytes("short.glb", {'g', 'l', 'T', 'F', 2, 0}), {"too short for a GLB header"});
}

TEST(GltfScene, WrongAccessorIndicesAreRefused) {
    Gltf g = Gltf::quad();
    g.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 99;
    expect_refused(load_bytes("accessor.glb", g.glb()), {"names accessor 99", "POSITION of mesh 0 primitive 0"});
    g = Gltf::quad();
    g.doc["accessors"][0]["bufferView"] = 42;
    expect_refused(load_bytes("view.glb", g.glb()), {"buffer view 42"});
    g = Gltf::quad();
    g.doc["nodes"][0]["mesh"] = 5;
    expect_refused(load_bytes("mesh.glb", g.glb()), {"node 0 \"terrain\" names mesh 5"});
}

TEST(GltfScene, IndicesBeyondTheVertexCountAreRefused) {
    Gltf g = Gltf::quad();
    const uint16_t bad = 7;
    std::memcpy(&g.bin[48 + 2 * 4], &bad, 2); // index 4 of 6
    expect_refused(load_bytes("indices.glb", g.glb()), {"index 4 is 7", "4 vertices", "accessor 1"});
}

TEST(GltfScene, HugeCountsAreRefusedBeforeAnythingIsAllocated) {
    Gltf g = Gltf::quad();
    g.doc["accessors"][0]["count"] = 2147483648u;
    expect_refused(load_bytes("count.glb", g.glb()), {"count 2147483648", "accessor 0"});
    g = Gltf::quad();
    g.doc["accessors"][0]["count"] = 100000; // within the cap, beyond the view
    expect_refused(load_bytes("range.glb", g.glb()), {"needs bytes up to", "buffer view of 48"});
    g = Gltf::quad();
    g.doc["buffers"][0]["byteLength"] = 4000000000u;
    expect_refused(load_bytes("bytelength.glb", g.glb()), {"byteLength"});
    g = Gltf::quad();
    g.doc["bufferViews"][0]["byteLength"] = 4000000000u;
    expect_refused(load_bytes("viewlength.glb", g.glb()), {"lies outside buffer 0"});
}

TEST(GltfScene, MissingOrEmptyBuffersAreRefused) {
    Gltf g = Gltf::quad();
    g.doc.erase("buffers");
    expect_refused(load_bytes("nobuffers.glb", g.glb()), {"nobuffers.glb"});
    g = Gltf::quad();
    g.bin.clear();
    expect_refused(load_bytes("nobin.glb", g.glb()), {"nobin.glb"});
    // tinygltf 2.7 throws std::out_of_range on a GLB buffer of 0 bytes: caught and named.
    g = Gltf::quad();
    g.doc["buffers"][0]["byteLength"] = 0;
    expect_refused(load_bytes("zero.glb", g.glb()), {"zero.glb"});
}

TEST(GltfScene, TerrainsThatWouldTakeHoursToRasteriseAreRefused) {
    // 20,000 copies of the quad's two triangles (all over the whole map) through one index list.
    Gltf g = Gltf::quad();
    std::vector<uint16_t> indices;
    for (int k = 0; k < 20000; ++k) indices.insert(indices.end(), {0, 2, 1, 1, 2, 3});
    const size_t offset = g.bin.size();
    g.append(indices.data(), indices.size());
    g.doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", indices.size() * 2}});
    g.doc["buffers"][0]["byteLength"] = g.bin.size();
    g.doc["accessors"][1] = {{"bufferView", 3}, {"componentType", 5123}, {"count", indices.size()}, {"type", "SCALAR"}};
    g.doc["nodes"][0]["extras"]["grass"]["texel_size"] = 0.002; // 2000 x 2000 texels
    expect_refused(load_bytes("overlap.glb", g.glb()), {"times over"});
}

TEST(GltfScene, NonTrianglePrimitivesAreRefused) {
    Gltf g = Gltf::quad();
    g.doc["meshes"][0]["primitives"][0]["mode"] = 1; // lines
    expect_refused(load_bytes("lines.glb", g.glb()), {"mode 1", "only triangles"});
}

TEST(GltfScene, NaNPositionsAreRefused) {
    Gltf g = Gltf::quad();
    const float nan = std::nanf("");
    std::memcpy(&g.bin[3 * 4 + 4], &nan, 4); // vertex 1, y
    expect_refused(load_bytes("nan.glb", g.glb()), {"element 1 component 1 is NaN", "POSITION"});
}

TEST(GltfScene, CyclesMissingTerrainsAndBadExtrasAreRefused) {
    Gltf g = Gltf::quad();
    g.doc["nodes"][1]["children"] = {1};
    expect_refused(load_bytes("cycle.glb", g.glb()), {"node 1 \"eye\" twice"});
    g = Gltf::quad();
    g.doc["nodes"][0]["name"] = "lawn";
    g.doc["nodes"][0].erase("extras");
    expect_refused(load_bytes("noterrain.glb", g.glb()), {"has no terrain"});
    g = Gltf::quad();
    g.doc["nodes"][0]["extras"]["grass"]["cel_size"] = 1;
    expect_refused(load_bytes("extras.glb", g.glb()), {"unknown key \"cel_size\""});
    g = Gltf::quad();
    g.doc["nodes"][0]["extras"]["grass"]["cell_size"] = -1;
    expect_refused(load_bytes("cellsize.glb", g.glb()), {"extras.grass.cell_size is -1"});
}

TEST(GltfScene, FilesOutsideTheScenesFolderAreNotRead) {
    Gltf g = Gltf::quad();
    g.doc["buffers"][0]["uri"] = "../outside.bin";
    write_bytes(scratch() + "../outside.bin", g.bin);
    std::string dump = g.doc.dump();
    expect_refused(load_bytes("escape.gltf", std::vector<unsigned char>(dump.begin(), dump.end())),
                   {"outside the scene's folder"});
    // The same buffer beside the scene is read.
    g.doc["buffers"][0]["uri"] = "beside.bin";
    write_bytes(scratch() + "beside.bin", g.bin);
    dump = g.doc.dump();
    const Loaded l = load_bytes("beside.gltf", std::vector<unsigned char>(dump.begin(), dump.end()));
    EXPECT_TRUE(l.ok) << l.error;
}

TEST(GltfScene, ADensityTextureOutsideItsBufferIsRefused) {
    // tinygltf hands an image's buffer view to the image callback without checking it
    // against its buffer; the loader reads it only through its own checked range.
    Gltf g = Gltf::quad();
    g.doc["nodes"][0]["extras"]["grass"]["density_texture"] = 0;
    g.doc["textures"] = json::parse(R"([{"source": 0}])");
    g.doc["images"] = json::parse(R"([{"bufferView": 3, "mimeType": "image/png"}])");
    g.doc["bufferViews"].push_back(json::parse(R"({"buffer": 0, "byteOffset": 100, "byteLength": 100000})"));
    g.doc["accessors"].push_back(
        json::parse(R"({"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC2"})"));
    g.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 3;
    expect_refused(load_bytes("texture.glb", g.glb()), {"buffer view 3", "lies outside buffer 0"});
    g.doc["meshes"][0]["primitives"][0]["attributes"].erase("TEXCOORD_0");
    expect_refused(load_bytes("texture2.glb", g.glb()), {"no TEXCOORD_0"});
}

TEST(GltfScene, RandomlyCorruptedSampleScenesNeverCrash) {
    // Under the sanitizer build this is where a read out of bounds would show.
    const std::vector<unsigned char> good = read_bytes(GRASS_GLTF_SAMPLE);
    ASSERT_GT(good.size(), 1000u);
    std::mt19937 random(15);
    int refused = 0;
    for (int round = 0; round < 60; ++round) {
        std::vector<unsigned char> bytes = good;
        const int flips = 1 + int(random() % 8);
        for (int k = 0; k < flips; ++k) {
            // Mostly in the JSON chunk (its numbers and names), sometimes in the binary data.
            const size_t at = random() % 4 ? 20 + random() % 3000 : random() % bytes.size();
            bytes[at] = uint8_t(random());
        }
        const Loaded l = load_bytes("corrupt.glb", bytes);
        refused += l.ok ? 0 : 1;
        if (!l.ok) {
            EXPECT_NE(l.error.find("corrupt.glb: "), std::string::npos) << l.error;
        }
    }
    EXPECT_GT(refused, 10); // the corruption is not vacuous
}

} // namespace

namespace {

// The quad with a node whose "extras" nest arrays `depth` levels deep in the whole document
// (the document, "nodes", the node and its "extras" are the first four).
std::string deep_extras(size_t depth) {
    Gltf g = Gltf::quad();
    g.doc["nodes"].push_back(json::parse(R"({"name": "deep", "extras": {"note": "DEEP"}})"));
    std::string text = g.doc.dump();
    const size_t at = text.find("\"DEEP\"");
    return text.replace(at, 6, std::string(depth - 4, '[') + "0" + std::string(depth - 4, ']'));
}

std::vector<unsigned char> bytes_of(const std::string& text) {
    return std::vector<unsigned char>(text.begin(), text.end());
}

} // namespace

// A glTF whose extras nested 20,000 deep (41 KB) crashed grass-render in tinygltf's recursive
// conversion of the parsed JSON; 5,000 deep crashed the ASan build and fuzz_gltf. The JSON of
// a .gltf and of a GLB's JSON chunk is measured before tinygltf sees it.
TEST(GltfScene, DeepExtrasAreRefusedBeforeTinygltfReadsThem) {
    Gltf g = Gltf::quad();
    g.doc["buffers"][0]["uri"] = "deep.bin";
    write_bytes(scratch() + "deep.bin", g.bin);
    for (size_t depth : {size_t(101), size_t(5000), size_t(20000), size_t(200000)}) {
        std::string text = deep_extras(depth);
        text.replace(text.find("\"byteLength\":124}"), 17, "\"byteLength\":124,\"uri\":\"deep.bin\"}");
        expect_refused(load_bytes("deep.gltf", bytes_of(text)),
                       {"deep.gltf: has JSON that nests arrays and objects deeper than 100 levels"});
        // The same JSON as a GLB's JSON chunk, the buffer in its BIN chunk.
        Gltf b = Gltf::quad();
        b.doc = json::parse(deep_extras(std::min<size_t>(depth, 100)));
        std::vector<unsigned char> glb = b.glb();
        const std::string plain = b.doc.dump(), deep = deep_extras(depth);
        // Put the deep text in place of the plain one, keeping the GLB's lengths right.
        std::string padded = deep;
        while (padded.size() % 4) padded += ' ';
        std::vector<unsigned char> out(glb.begin(), glb.begin() + 12);
        auto word = [&](uint32_t v) {
            for (int k = 0; k < 4; ++k) out.push_back(uint8_t(v >> (8 * k)));
        };
        word(uint32_t(padded.size()));
        word(0x4E4F534A);
        out.insert(out.end(), padded.begin(), padded.end());
        std::string plain_padded = plain;
        while (plain_padded.size() % 4) plain_padded += ' ';
        out.insert(out.end(), glb.begin() + 20 + std::ptrdiff_t(plain_padded.size()), glb.end());
        const uint32_t total = uint32_t(out.size());
        for (int k = 0; k < 4; ++k) out[8 + size_t(k)] = uint8_t(total >> (8 * k));
        expect_refused(load_bytes("deep.glb", out),
                       {"deep.glb: has JSON that nests arrays and objects deeper than 100"});
    }
    std::string text = deep_extras(100);
    text.replace(text.find("\"byteLength\":124}"), 17, "\"byteLength\":124,\"uri\":\"deep.bin\"}");
    const Loaded l = load_bytes("deep100.gltf", bytes_of(text));
    EXPECT_TRUE(l.ok) << "100 levels are read: " << l.error;
}

// Every file a glTF names is read as a regular file of bounded size: a FIFO or a directory
// in a buffer's or an image's place is refused by name, not waited on.
TEST(GltfScene, BuffersAndImagesThatAreNotRegularFilesAreRefused) {
    const std::string fifo = scratch() + "fifo.bin";
    unlink(fifo.c_str());
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    mkdir((scratch() + "folder.bin").c_str(), 0755);
    for (const char* uri : {"fifo.bin", "folder.bin"}) {
        Gltf g = Gltf::quad();
        g.doc["buffers"][0]["uri"] = uri;
        expect_refused(load_bytes("special.gltf", bytes_of(g.doc.dump())),
                       {uri, std::string(uri) == "fifo.bin" ? "is a FIFO, not a regular file"
                                                            : "is a directory, not a regular file"});
    }
    unlink(fifo.c_str());
}

// A palette PNG as the density texture whose indices run past its palette is refused, naming
// the pixel and the index (libpng read such an index as black: zero density).
TEST(GltfScene, ADensityTextureWithIndicesPastItsPaletteIsRefused) {
    Gltf g = Gltf::quad();
    g.doc["buffers"][0]["uri"] = "palette.bin";
    write_bytes(scratch() + "palette.bin", g.bin);
    g.doc["nodes"][0]["extras"]["grass"]["density_texture"] = 0;
    g.doc["textures"] = json::parse(R"([{"source": 0}])");
    g.doc["images"] = json::parse(R"([{"uri": "palette.png"}])");
    g.doc["accessors"].push_back(
        json::parse(R"({"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC2"})"));
    g.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 3;
    write_bytes(scratch() + "palette.png", read_bytes(GRASS_FUZZ_CORPUS_DIR "/png_map/palette-index-past-palette.png"));
    expect_refused(load_bytes("palette.gltf", bytes_of(g.doc.dump())),
                   {"image 0 (the density texture) is refused: pixel (0, 1) has palette index 5; the palette has 2"});
    write_bytes(scratch() + "palette.png", read_bytes(GRASS_FUZZ_CORPUS_DIR "/png_map/palette-2x2.png"));
    const Loaded l = load_bytes("palette.gltf", bytes_of(g.doc.dump()));
    EXPECT_TRUE(l.ok) << "a palette PNG whose indices fit: " << l.error;
}
