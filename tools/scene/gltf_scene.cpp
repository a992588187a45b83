#include "gltf_scene.hpp"

#include "file_bytes.hpp"
#include "gltf_accessor.hpp"
#include "json_depth.hpp"
#include "png_chunks.hpp"
#include "png_palette.hpp"
#include "terrain_raster.hpp"

#include <png.h>
#include <sys/stat.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace grass_sample {

namespace {

using Mat4 = std::array<double, 16>; // column-major
using tinygltf::Model;
using tinygltf::Value;

constexpr uint64_t kMaxTriangles = uint64_t(1) << 22;        // of all meshes together
constexpr uint32_t kMaxCellsPerSide = 1u << 20;              // of the terrain's field
constexpr uint32_t kDefaultMaxMapTexels = 1024;              // per side, when texel_size is not given
constexpr uint32_t kMaxMapTexels = 4096;                     // per side, texel_size given
constexpr uint32_t kMaxTextureTexels = 8192;                 // per side of a density texture
constexpr double kMaxTexelTests = double(uint64_t(1) << 28); // texels the rasteriser may visit

[[noreturn]] void refuse(const std::string& why) { throw std::runtime_error(why); }

std::string quoted(const std::string& s) { return "\"" + cut(s) + "\""; }

// ---- Files: size-capped, and only beside the scene -------------------------------------

// The whole file (read_file_bytes: a regular file of at most kMaxFileBytes).
std::vector<unsigned char> read_file(const std::string& path) {
    std::vector<unsigned char> bytes;
    std::string error;
    if (!read_file_bytes(path, kMaxFileBytes, &bytes, &error)) refuse(error);
    return bytes;
}

// tinygltf's file callbacks: a file a scene names (buffers, images) must lie in the scene's
// folder or below it, without "..", and within kMaxFileBytes.
struct SceneFolder {
    std::string dir; // with a trailing '/', or empty for the working directory
};

bool inside_folder(const std::string& path, const SceneFolder& folder) {
    if (path.compare(0, folder.dir.size(), folder.dir) != 0) return false;
    const std::string rest = path.substr(folder.dir.size());
    if (rest.empty() || rest[0] == '/') return false;
    size_t start = 0;
    while (start <= rest.size()) {
        const size_t slash = std::min(rest.find('/', start), rest.size());
        if (rest.compare(start, slash - start, "..") == 0 && slash - start == 2) return false;
        start = slash + 1;
    }
    return true;
}

// A path outside the folder "exists", so that read_whole_file refuses it with the reason.
bool file_exists(const std::string& path, void* user) {
    struct stat st {};
    return !inside_folder(path, *static_cast<SceneFolder*>(user)) || stat(path.c_str(), &st) == 0;
}

std::string expand_path(const std::string& path, void*) { return path; }

bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    if (!inside_folder(path, *static_cast<SceneFolder*>(user))) {
        if (err) *err += "the file " + quoted(cut_path(path)) + " lies outside the scene's folder\n";
        return false;
    }
    try {
        *out = read_file(path);
    } catch (const std::exception& e) {
        if (err) *err += std::string(e.what()) + "\n";
        return false;
    }
    return true;
}

// tinygltf's image callback: images are not decoded at load (only a density texture is,
// later, by libpng). Bytes from a data URI or a file are kept; an image in a buffer view is
// read later through the checked buffer_view_bytes (tinygltf does not check that view's
// range against its buffer before handing its bytes here).
bool keep_image_bytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
    if (image->bufferView < 0 && bytes && size > 0) image->image.assign(bytes, bytes + size);
    image->as_is = true;
    return true;
}

// The GLB header and chunk table, checked before tinygltf reads it.
void check_glb(const std::vector<unsigned char>& bytes) {
    auto word = [&](size_t at) {
        return uint32_t(bytes[at]) | uint32_t(bytes[at + 1]) << 8 | uint32_t(bytes[at + 2]) << 16 |
               uint32_t(bytes[at + 3]) << 24;
    };
    if (bytes.size() < 20) refuse("is " + std::to_string(bytes.size()) + " bytes: too short for a GLB header");
    const uint32_t version = word(4), length = word(8), json_length = word(12);
    if (version != 2) refuse("is GLB version " + std::to_string(version) + "; 2 is read");
    if (length != bytes.size()) {
        refuse("is truncated or padded: its GLB header says " + std::to_string(length) + " bytes, the file has " +
               std::to_string(bytes.size()));
    }
    if (word(16) != 0x4E4F534Au || uint64_t(json_length) + 20 > length) {
        refuse("has a bad JSON chunk (length " + std::to_string(json_length) + " in a file of " +
               std::to_string(length) + " bytes)");
    }
    const uint64_t bin = 20 + uint64_t(json_length);
    if (bin < length) {
        if (bin + 8 > length) refuse("has a truncated BIN chunk header");
        const uint64_t bin_length = word(size_t(bin));
        if (bin + 8 + bin_length > length) {
            refuse("has a BIN chunk of " + std::to_string(bin_length) + " bytes in the " +
                   std::to_string(length - bin - 8) + " left");
        }
    }
}

Model load_model(const std::string& path, std::vector<std::string>* notes) {
    std::vector<unsigned char> bytes = read_file(path);
    const bool binary = bytes.size() >= 4 && bytes[0] == 'g' && bytes[1] == 'l' && bytes[2] == 'T' && bytes[3] == 'F';
    if (binary) check_glb(bytes);
    // The JSON (the whole .gltf, a GLB's JSON chunk) nested at most kMaxJsonDepth deep before
    // tinygltf, whose conversion of a parsed value recurses a level at a time, reads it.
    const size_t json_at = binary ? 20 : 0;
    const size_t json_size =
        binary ? size_t(bytes[12] | bytes[13] << 8 | bytes[14] << 16 | uint32_t(bytes[15]) << 24) : bytes.size();
    const std::string deep =
        json_depth_problem(reinterpret_cast<const char*>(bytes.data()) + json_at, json_size, kMaxJsonDepth, false);
    if (!deep.empty()) refuse("has JSON that " + deep);
    SceneFolder folder;
    const size_t slash = path.find_last_of('/');
    if (slash != std::string::npos) folder.dir = path.substr(0, slash + 1);
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&keep_image_bytes, nullptr);
    loader.SetFsCallbacks(tinygltf::FsCallbacks{&file_exists, &expand_path, &read_whole_file, nullptr, &folder});
    Model model;
    std::string err, warn;
    bool ok = false;
    const std::string base = folder.dir.empty() ? "." : folder.dir.substr(0, folder.dir.size() - 1);
    try {
        ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), base)
                    : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                                 unsigned(bytes.size()), base);
    } catch (const std::exception& e) { // tinygltf throws on some bad files (a GLB buffer of 0 bytes)
        refuse(std::string("cannot be read by tinygltf: ") + e.what());
    }
    while (!err.empty() && err.back() == '\n') err.pop_back();
    err = cut(err, 400); // tinygltf quotes what it stopped at
    if (!ok) refuse("is not a glTF 2.0 file tinygltf reads: " + (err.empty() ? std::string("no reason given") : err));
    if (!warn.empty()) notes->push_back("tinygltf: " + warn);
    for (const std::string& e : model.extensionsRequired) refuse("requires the extension " + e + ", not supported");
    return model;
}

// ---- Transforms ----------------------------------------------------------------------

Mat4 identity() {
    Mat4 m{};
    m[0] = m[5] = m[10] = m[15] = 1.0;
    return m;
}

Mat4 multiply(const Mat4& a, const Mat4& b) {
    Mat4 m{};
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            for (int k = 0; k < 4; ++k) m[4 * c + r] += a[4 * k + r] * b[4 * c + k];
    return m;
}

template <class T>
void point(const Mat4& m, const T p[3], double out[3]) {
    for (int r = 0; r < 3; ++r) out[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r];
}

std::string node_label(const Model& model, int n) {
    const std::string& name = model.nodes[size_t(n)].name;
    return "node " + std::to_string(n) + (name.empty() ? "" : " " + quoted(name));
}

void check_finite(const std::vector<double>& v, size_t size, const std::string& what) {
    if (!v.empty() && v.size() != size)
        refuse(what + " has " + std::to_string(v.size()) + " numbers, not " + std::to_string(size));
    for (double x : v)
        if (!std::isfinite(x)) refuse(what + " holds a number that is not finite");
}

Mat4 local_transform(const Model& model, int n) {
    const tinygltf::Node& node = model.nodes[size_t(n)];
    const std::string label = node_label(model, n);
    check_finite(node.matrix, 16, label + "'s matrix");
    check_finite(node.translation, 3, label + "'s translation");
    check_finite(node.rotation, 4, label + "'s rotation");
    check_finite(node.scale, 3, label + "'s scale");
    if (node.matrix.size() == 16) {
        Mat4 m;
        std::copy(node.matrix.begin(), node.matrix.end(), m.begin());
        return m;
    }
    double q[4] = {0, 0, 0, 1}, s[3] = {1, 1, 1}, t[3] = {0, 0, 0};
    if (node.rotation.size() == 4) {
        const double len = std::sqrt(node.rotation[0] * node.rotation[0] + node.rotation[1] * node.rotation[1] +
                                     node.rotation[2] * node.rotation[2] + node.rotation[3] * node.rotation[3]);
        if (len < 1e-6) refuse(label + "'s rotation is not a unit quaternion (length " + std::to_string(len) + ")");
        for (int k = 0; k < 4; ++k) q[k] = node.rotation[size_t(k)] / len;
    }
    for (size_t k = 0; k < node.scale.size(); ++k) s[k] = node.scale[k];
    for (size_t k = 0; k < node.translation.size(); ++k) t[k] = node.translation[k];
    const double x = q[0], y = q[1], z = q[2], w = q[3];
    const double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w),     2 * (x * z - y * w),
                         2 * (x * y - z * w),     1 - 2 * (x * x + z * z), 2 * (y * z + x * w),
                         2 * (x * z + y * w),     2 * (y * z - x * w),     1 - 2 * (x * x + y * y)};
    Mat4 m = identity();
    for (int c = 0; c < 3; ++c)
        for (int row = 0; row < 3; ++row) m[4 * c + row] = r[3 * c + row] * s[c];
    for (int row = 0; row < 3; ++row) m[12 + row] = t[row];
    return m;
}

// ---- extras: {"grass": {...}} ----------------------------------------------------------

struct GrassExtras {
    std::string role; // "", "terrain", "collider"
    double cell_size = 0.0, texel_size = 0.0;
    std::string density;     // "", "vertex_color", "texture", "uniform"
    int density_channel = 0; // r, g, b, a
    const Value* density_texture = nullptr;
    std::string shape; // colliders: "sphere", "capsule"
    double radius = -1.0, height = -1.0;
};

double positive_number(const Value& v, const std::string& what) {
    if (!v.IsNumber()) refuse(what + " is not a number");
    const double x = v.GetNumberAsDouble();
    if (!std::isfinite(x) || x <= 0.0) refuse(what + " is " + std::to_string(x) + "; a positive number is needed");
    return x;
}

std::string string_of(const Value& v, const std::string& what) {
    if (!v.IsString()) refuse(what + " is not a string");
    return v.Get<std::string>();
}

GrassExtras read_extras(const Value& extras, const std::string& label) {
    GrassExtras g;
    if (!extras.IsObject() || !extras.Has("grass")) return g;
    const Value& grass = extras.Get("grass");
    const std::string where = label + "'s extras.grass";
    if (!grass.IsObject()) refuse(where + " is not an object");
    for (const std::string& key : grass.Keys()) {
        const Value& v = grass.Get(key);
        const std::string what = where + "." + key;
        if (key == "role") {
            g.role = string_of(v, what);
            if (g.role != "terrain" && g.role != "collider") {
                refuse(what + " is " + quoted(g.role) + "; \"terrain\" or \"collider\" expected");
            }
        } else if (key == "cell_size") {
            g.cell_size = positive_number(v, what);
        } else if (key == "texel_size") {
            g.texel_size = positive_number(v, what);
        } else if (key == "density") {
            g.density = string_of(v, what);
            if (g.density != "vertex_color" && g.density != "texture" && g.density != "uniform") {
                refuse(what + " is " + quoted(g.density) + "; \"vertex_color\", \"texture\" or \"uniform\" expected");
            }
        } else if (key == "density_channel") {
            const std::string c = string_of(v, what);
            const size_t at = std::string("rgba").find(c);
            if (c.size() != 1 || at == std::string::npos) refuse(what + " is " + quoted(c) + "; r, g, b or a expected");
            g.density_channel = int(at);
        } else if (key == "density_texture") {
            if (!v.IsString() && !v.IsInt()) refuse(what + " is neither a texture's name nor its index");
            g.density_texture = &v;
        } else if (key == "shape") {
            g.shape = string_of(v, what);
            if (g.shape != "sphere" && g.shape != "capsule") {
                refuse(what + " is " + quoted(g.shape) + "; \"sphere\" or \"capsule\" expected");
            }
        } else if (key == "radius") {
            g.radius = positive_number(v, what);
        } else if (key == "height") {
            g.height = positive_number(v, what);
        } else {
            refuse(where + " has the unknown key " + quoted(key));
        }
    }
    if (g.density_texture && g.density.empty()) g.density = "texture";
    return g;
}

bool named_terrain(const std::string& name) {
    std::string lower = name;
    for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
    return lower == "terrain";
}

// ---- The walk over the scene's nodes ----------------------------------------------------

struct Terrain {
    std::vector<TerrainVertex> triangles;
    GrassExtras extras;  // of the first terrain node
    std::string density; // the density source used
    int texture = -1;    // the density texture's index
    bool any = false;
};

struct Walk {
    const Model& model;
    Scene scene;
    GltfInfo info;
    Terrain terrain;
    bool camera_found = false;
    uint64_t triangles = 0;
};

int find_texture(const Model& model, const Value& v, const std::string& label) {
    if (v.IsInt()) {
        const int t = v.Get<int>();
        if (t < 0 || size_t(t) >= model.textures.size()) {
            refuse(label + "'s extras.grass.density_texture is " + std::to_string(t) + "; the file has " +
                   std::to_string(model.textures.size()) + " textures");
        }
        return t;
    }
    const std::string name = v.Get<std::string>();
    for (size_t t = 0; t < model.textures.size(); ++t) {
        const int source = model.textures[t].source;
        const bool image_named =
            source >= 0 && size_t(source) < model.images.size() && model.images[size_t(source)].name == name;
        if (model.textures[t].name == name || image_named) return int(t);
    }
    refuse(label + "'s extras.grass.density_texture names " + quoted(name) + ", which no texture or image is called");
}

// Smooth normals from the triangles when the primitive has none.
std::vector<float> face_normals(const std::vector<double>& world, const std::vector<uint32_t>& indices) {
    std::vector<double> sum(world.size(), 0.0);
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        const double* p[3] = {&world[3 * indices[t]], &world[3 * indices[t + 1]], &world[3 * indices[t + 2]]};
        const double e1[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
        const double e2[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
        const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                             e1[0] * e2[1] - e1[1] * e2[0]};
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c) sum[3 * indices[t + size_t(k)] + size_t(c)] += n[c];
    }
    return std::vector<float>(sum.begin(), sum.end());
}

void add_primitive(Walk* w, int node, const Mat4& m, const tinygltf::Primitive& prim, const std::string& what,
                   bool terrain) {
    const Model& model = w->model;
    const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES) {
        refuse(what + " has mode " + std::to_string(mode) + "; only triangles (mode 4) are drawn");
    }
    const auto position = prim.attributes.find("POSITION");
    if (position == prim.attributes.end()) refuse(what + " has no POSITION");
    const std::vector<float> p = read_float_accessor(model, position->second, 3, false, "POSITION of " + what);
    const uint64_t vertices = p.size() / 3;
    std::vector<uint32_t> indices;
    if (prim.indices >= 0) {
        indices = read_index_accessor(model, prim.indices, vertices, "indices of " + what);
    } else {
        indices.resize(size_t(vertices));
        for (uint32_t i = 0; i < vertices; ++i) indices[i] = i;
    }
    if (indices.size() % 3 != 0) {
        refuse(what + " has " + std::to_string(indices.size()) + " indices, not a whole number of triangles");
    }
    w->triangles += indices.size() / 3;
    if (w->triangles > kMaxTriangles) {
        refuse("the meshes hold more than " + std::to_string(kMaxTriangles) + " triangles (at " + what + ")");
    }

    std::vector<double> world(size_t(vertices) * 3);
    double lo[3], hi[3];
    for (int c = 0; c < 3; ++c) lo[c] = std::numeric_limits<double>::infinity(), hi[c] = -lo[c];
    for (size_t v = 0; v < vertices; ++v) {
        point(m, &p[3 * v], &world[3 * v]);
        for (int c = 0; c < 3; ++c)
            lo[c] = std::min(lo[c], world[3 * v + c]), hi[c] = std::max(hi[c], world[3 * v + c]);
    }
    std::vector<float> normals;
    const auto normal = prim.attributes.find("NORMAL");
    if (normal != prim.attributes.end()) {
        normals = read_float_accessor(model, normal->second, 3, false, "NORMAL of " + what);
        if (normals.size() != p.size()) refuse("NORMAL of " + what + " has a count other than POSITION's");
        // The inverse transpose of the upper 3x3, up to a scale (normalised in the shader):
        // its cofactor matrix.
        const double a[9] = {m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10]};
        const double cof[9] = {a[4] * a[8] - a[5] * a[7], a[5] * a[6] - a[3] * a[8], a[3] * a[7] - a[4] * a[6],
                               a[2] * a[7] - a[1] * a[8], a[0] * a[8] - a[2] * a[6], a[1] * a[6] - a[0] * a[7],
                               a[1] * a[5] - a[2] * a[4], a[2] * a[3] - a[0] * a[5], a[0] * a[4] - a[1] * a[3]};
        for (size_t v = 0; v < vertices; ++v) {
            const float* n = &normals[3 * v];
            double out[3];
            for (int r = 0; r < 3; ++r) out[r] = cof[r] * n[0] + cof[3 + r] * n[1] + cof[6 + r] * n[2];
            for (int r = 0; r < 3; ++r) normals[3 * v + size_t(r)] = float(out[r]);
        }
    } else {
        normals = face_normals(world, indices);
    }

    grass_host::HostMesh mesh;
    mesh.name = what;
    for (int c = 0; c < 3; ++c) mesh.origin[c] = 0.5 * (lo[c] + hi[c]);
    mesh.vertices.resize(size_t(vertices) * grass_host::HostMesh::kFloatsPerVertex);
    for (size_t v = 0; v < vertices; ++v) {
        float* out = &mesh.vertices[v * grass_host::HostMesh::kFloatsPerVertex];
        for (int c = 0; c < 3; ++c) out[c] = float(world[3 * v + c] - mesh.origin[c]), out[3 + c] = normals[3 * v + c];
    }
    mesh.indices = indices;
    if (terrain) std::copy(w->scene.ground_color, w->scene.ground_color + 3, mesh.color);
    if (prim.material >= 0) {
        if (size_t(prim.material) >= model.materials.size()) {
            refuse(what + " names material " + std::to_string(prim.material) + "; the file has " +
                   std::to_string(model.materials.size()));
        }
        const std::vector<double>& f = model.materials[size_t(prim.material)].pbrMetallicRoughness.baseColorFactor;
        check_finite(f, 4, "material " + std::to_string(prim.material) + "'s baseColorFactor");
        for (size_t c = 0; c < 3 && c < f.size(); ++c) mesh.color[c] = float(std::min(std::max(f[c], 0.0), 1.0));
    }
    w->info.mesh_triangles += indices.size() / 3;
    w->scene.meshes.push_back(std::move(mesh));
    if (!terrain) return;

    // The terrain's triangles with their density attributes.
    Terrain& t = w->terrain;
    const GrassExtras& ex = t.extras;
    const auto color = prim.attributes.find("COLOR_0");
    const auto uv = prim.attributes.find("TEXCOORD_0");
    std::string density = ex.density;
    if (density.empty()) density = color != prim.attributes.end() ? "vertex_color" : "uniform";
    if (!t.density.empty() && density != t.density) {
        refuse(what + " gives the terrain's density by " + density + ", another terrain part by " + t.density);
    }
    t.density = density;
    std::vector<float> a;
    int stride = 0;
    if (density == "vertex_color") {
        if (color == prim.attributes.end()) refuse(what + " has no COLOR_0 for the terrain's density");
        a = read_float_accessor(model, color->second, 4, true, "COLOR_0 of " + what);
        stride = 4;
    } else if (density == "texture") {
        if (!ex.density_texture) refuse(node_label(model, node) + " has no extras.grass.density_texture");
        if (uv == prim.attributes.end()) refuse(what + " has no TEXCOORD_0 for the density texture");
        a = read_float_accessor(model, uv->second, 2, true, "TEXCOORD_0 of " + what);
        stride = 2;
        t.texture = find_texture(model, *ex.density_texture, node_label(model, node));
    }
    if (!a.empty() && a.size() / size_t(stride) != vertices) {
        refuse("the density attribute of " + what + " has a count other than POSITION's");
    }
    for (uint32_t i : indices) {
        TerrainVertex tv;
        tv.x = world[3 * i], tv.y = world[3 * i + 1], tv.z = world[3 * i + 2];
        if (stride == 4) tv.a[0] = a[4 * i + size_t(ex.density_channel)];
        if (stride == 2) tv.a[0] = a[2 * i], tv.a[1] = a[2 * i + 1];
        if (stride == 0) tv.a[0] = 1.0f;
        t.triangles.push_back(tv);
    }
}

void add_collider(Walk* w, int n, const Mat4& m, const GrassExtras& ex) {
    const std::string label = node_label(w->model, n);
    if (ex.shape.empty()) refuse(label + " is a collider without extras.grass.shape (sphere or capsule)");
    if (ex.radius < 0.0) refuse(label + " is a collider without extras.grass.radius");
    if (ex.shape == "capsule" && ex.height < 0.0) refuse(label + " is a capsule without extras.grass.height");
    GltfCollider c;
    c.node = w->model.nodes[size_t(n)].name.empty() ? "node " + std::to_string(n) : w->model.nodes[size_t(n)].name;
    c.shape = ex.shape == "sphere" ? GltfCollider::Shape::sphere : GltfCollider::Shape::capsule;
    double scale = 0.0;
    for (int col = 0; col < 3; ++col) {
        scale = std::max(scale, std::sqrt(m[4 * col] * m[4 * col] + m[4 * col + 1] * m[4 * col + 1] +
                                          m[4 * col + 2] * m[4 * col + 2]));
    }
    c.radius = ex.radius * scale;
    const double half = c.shape == GltfCollider::Shape::capsule ? 0.5 * ex.height : 0.0;
    const double a[3] = {0.0, -half, 0.0}, b[3] = {0.0, half, 0.0};
    point(m, a, c.a);
    point(m, b, c.b);
    if (w->info.colliders.size() == GRASS_MAX_COLLIDERS) {
        refuse("has more than " + std::to_string(GRASS_MAX_COLLIDERS) + " colliders (GRASS_MAX_COLLIDERS) at " + label);
    }
    w->info.colliders.push_back(c);
}

void take_camera(Walk* w, int n, const Mat4& m) {
    const Model& model = w->model;
    const int index = model.nodes[size_t(n)].camera;
    const std::string label = node_label(model, n);
    if (size_t(index) >= model.cameras.size()) {
        refuse(label + " names camera " + std::to_string(index) + "; the file has " +
               std::to_string(model.cameras.size()));
    }
    const tinygltf::Camera& camera = model.cameras[size_t(index)];
    if (camera.type != "perspective") {
        w->info.notes.push_back("camera " + std::to_string(index) + " (" + label + ") is " + camera.type +
                                "; only a perspective camera is used");
        return;
    }
    if (w->camera_found) {
        w->info.notes.push_back(label + "'s camera is not used: the first perspective camera is");
        return;
    }
    const tinygltf::PerspectiveCamera& p = camera.perspective;
    const std::string what = "camera " + std::to_string(index);
    if (!(p.yfov > 0.0 && p.yfov < 3.1)) refuse(what + " has yfov " + std::to_string(p.yfov) + "; 0..3.1 rad expected");
    if (!(p.znear > 0.0 && p.znear < 1e6)) refuse(what + " has znear " + std::to_string(p.znear));
    if (!(p.zfar == 0.0 || (p.zfar > p.znear && p.zfar < 1e8))) refuse(what + " has zfar " + std::to_string(p.zfar));
    double forward[3] = {-m[8], -m[9], -m[10]};
    const double len = std::sqrt(forward[0] * forward[0] + forward[1] * forward[1] + forward[2] * forward[2]);
    if (!(len > 1e-9)) refuse(label + "'s transform has no forward direction");
    for (int c = 0; c < 3; ++c) {
        w->scene.eye[c] = m[12 + c];
        w->scene.target[c] = m[12 + c] + forward[c] / len;
    }
    w->scene.fov_degrees = float(p.yfov * 180.0 / 3.14159265358979);
    w->scene.near_m = float(p.znear);
    if (p.zfar > 0.0) w->scene.far_m = float(p.zfar);
    w->info.camera = model.nodes[size_t(n)].name.empty() ? label : model.nodes[size_t(n)].name;
    w->camera_found = true;
}

void visit_node(Walk* w, int n, const Mat4& m) {
    const Model& model = w->model;
    const tinygltf::Node& node = model.nodes[size_t(n)];
    const std::string label = node_label(model, n);
    const GrassExtras ex = read_extras(node.extras, label);
    const bool terrain = ex.role == "terrain" || (ex.role.empty() && named_terrain(node.name));
    if (terrain && !w->terrain.any) w->terrain.extras = ex;
    if (terrain && node.mesh < 0) refuse(label + " is the terrain but has no mesh");
    w->terrain.any = w->terrain.any || terrain;
    if (terrain) w->info.terrain += (w->info.terrain.empty() ? "" : ", ") + label;
    if (ex.role == "collider") add_collider(w, n, m, ex);
    if (node.camera >= 0) take_camera(w, n, m);
    if (node.mesh < 0) return;
    if (size_t(node.mesh) >= model.meshes.size()) {
        refuse(label + " names mesh " + std::to_string(node.mesh) + "; the file has " +
               std::to_string(model.meshes.size()));
    }
    const tinygltf::Mesh& mesh = model.meshes[size_t(node.mesh)];
    for (size_t k = 0; k < mesh.primitives.size(); ++k) {
        const std::string what = "mesh " + std::to_string(node.mesh) +
                                 (mesh.name.empty() ? "" : " " + quoted(mesh.name)) + " primitive " +
                                 std::to_string(k) + " (" + label + ")";
        add_primitive(w, n, m, mesh.primitives[k], what, terrain);
    }
}

// Every node of the scene once, parents before children, without recursion (a hostile
// hierarchy may be deep); a node met twice (a cycle, a shared child) is refused.
void walk_scene(Walk* w) {
    const Model& model = w->model;
    if (model.scenes.empty()) refuse("has no scene");
    const int s = model.defaultScene < 0 ? 0 : model.defaultScene;
    if (size_t(s) >= model.scenes.size()) {
        refuse("has scene " + std::to_string(s) + " as its default; it has " + std::to_string(model.scenes.size()));
    }
    std::vector<char> seen(model.nodes.size(), 0);
    std::vector<std::pair<int, Mat4>> stack;
    const std::vector<int>& roots = model.scenes[size_t(s)].nodes;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.emplace_back(*it, identity());
    while (!stack.empty()) {
        const auto [n, parent] = stack.back();
        stack.pop_back();
        if (n < 0 || size_t(n) >= model.nodes.size()) {
            refuse("names node " + std::to_string(n) + "; it has " + std::to_string(model.nodes.size()));
        }
        if (seen[size_t(n)])
            refuse("has " + node_label(model, n) + " twice in its hierarchy (a cycle or a shared child)");
        seen[size_t(n)] = 1;
        const Mat4 m = multiply(parent, local_transform(model, n));
        visit_node(w, n, m);
        const std::vector<int>& children = model.nodes[size_t(n)].children;
        for (auto it = children.rbegin(); it != children.rend(); ++it) stack.emplace_back(*it, m);
    }
}

// ---- The terrain's field and maps ---------------------------------------------------

struct DensityTexture {
    std::vector<uint8_t> rgba;
    uint32_t width = 0, height = 0;
    float sample(float u, float v, int channel) const { // bilinear, repeating (glTF's default sampler)
        const double x = double(u) * width - 0.5, y = double(v) * height - 0.5;
        const double fx = std::floor(x), fy = std::floor(y);
        auto at = [&](double i, double j) {
            const long xi = long(((long(i) % long(width)) + long(width)) % long(width));
            const long yi = long(((long(j) % long(height)) + long(height)) % long(height));
            return rgba[(size_t(yi) * width + size_t(xi)) * 4 + size_t(channel)] / 255.0;
        };
        const double tx = x - fx, ty = y - fy;
        return float((at(fx, fy) * (1 - tx) + at(fx + 1, fy) * tx) * (1 - ty) +
                     (at(fx, fy + 1) * (1 - tx) + at(fx + 1, fy + 1) * tx) * ty);
    }
};

DensityTexture decode_density_texture(const Model& model, int texture) {
    const int source = model.textures[size_t(texture)].source;
    const std::string what = "texture " + std::to_string(texture);
    if (source < 0 || size_t(source) >= model.images.size()) {
        refuse(what + " names image " + std::to_string(source) + "; the file has " +
               std::to_string(model.images.size()));
    }
    const tinygltf::Image& image = model.images[size_t(source)];
    const unsigned char* bytes = image.image.data();
    size_t size = image.image.size();
    if (image.bufferView >= 0) {
        bytes = buffer_view_bytes(model, image.bufferView, &size, "image " + std::to_string(source));
    }
    const std::string problem = size > 0 ? png_chunk_problem(bytes, size) : std::string();
    if (!problem.empty()) refuse("image " + std::to_string(source) + " (the density texture) is refused: " + problem);
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    if (size == 0 || !png_image_begin_read_from_memory(&png, bytes, size)) {
        refuse("image " + std::to_string(source) + " (the density texture) is not a PNG libpng reads" +
               (png.message[0] ? std::string(": ") + png.message : std::string()));
    }
    if (png.width > kMaxTextureTexels || png.height > kMaxTextureTexels) {
        png_image_free(&png);
        refuse("image " + std::to_string(source) + " is " + std::to_string(png.width) + "x" +
               std::to_string(png.height) + "; at most " + std::to_string(kMaxTextureTexels) + " a side is read");
    }
    const std::string palette = png_palette_problem(bytes, size);
    if (!palette.empty()) {
        png_image_free(&png);
        refuse("image " + std::to_string(source) + " (the density texture) is refused: " + palette);
    }
    DensityTexture t;
    png.format = PNG_FORMAT_RGBA;
    t.width = png.width;
    t.height = png.height;
    t.rgba.resize(PNG_IMAGE_SIZE(png));
    if (!png_image_finish_read(&png, nullptr, t.rgba.data(), 0, nullptr)) {
        refuse("image " + std::to_string(source) + " cannot be decoded: " + png.message);
    }
    return t;
}

void make_field(Walk* w) {
    Terrain& t = w->terrain;
    if (!t.any) {
        refuse("has no terrain: name a node \"terrain\" or give it \"extras\": {\"grass\": {\"role\": \"terrain\"}}");
    }
    double lo[3], hi[3];
    for (int c = 0; c < 3; ++c) lo[c] = std::numeric_limits<double>::infinity(), hi[c] = -lo[c];
    for (const TerrainVertex& v : t.triangles) {
        const double p[3] = {v.x, v.y, v.z};
        for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], p[c]), hi[c] = std::max(hi[c], p[c]);
    }
    if (t.triangles.empty() || !(hi[0] - lo[0] > 0.0) || !(hi[2] - lo[2] > 0.0)) {
        refuse("has a terrain that covers no area seen from above");
    }
    const double cell = t.extras.cell_size > 0.0 ? t.extras.cell_size : 0.25;
    const double cells_x = std::ceil((hi[0] - lo[0]) / cell), cells_z = std::ceil((hi[2] - lo[2]) / cell);
    if (cells_x > kMaxCellsPerSide || cells_z > kMaxCellsPerSide) {
        refuse("has a terrain of " + std::to_string(cells_x) + " x " + std::to_string(cells_z) + " cells of " +
               std::to_string(cell) + " m; at most " + std::to_string(kMaxCellsPerSide) + " a side");
    }
    const double size_x = cells_x * cell, size_z = cells_z * cell;
    const double texel = t.extras.texel_size > 0.0 ? t.extras.texel_size : cell;
    double map_x = std::ceil(size_x / texel), map_z = std::ceil(size_z / texel);
    if (t.extras.texel_size > 0.0 && (map_x > kMaxMapTexels || map_z > kMaxMapTexels)) {
        refuse("asks for terrain maps of " + std::to_string(map_x) + " x " + std::to_string(map_z) +
               " texels (texel_size " + std::to_string(texel) + "); at most " + std::to_string(kMaxMapTexels) +
               " a side");
    }
    // The default texel (a cell) grows for large terrains: at most kDefaultMaxMapTexels a side.
    const double longest = std::max(map_x, map_z);
    if (t.extras.texel_size <= 0.0 && longest > kDefaultMaxMapTexels) {
        map_x = std::max(1.0, std::ceil(map_x * kDefaultMaxMapTexels / longest));
        map_z = std::max(1.0, std::ceil(map_z * kDefaultMaxMapTexels / longest));
    }
    const uint32_t mw = uint32_t(map_x), mh = uint32_t(map_z);
    // The rasteriser visits each triangle's bounding box of texels: many large overlapping
    // triangles would take hours, so their sum is bounded.
    double tests = 0.0;
    for (size_t k = 0; k + 2 < t.triangles.size(); k += 3) {
        double x0 = t.triangles[k].x, x1 = x0, z0 = t.triangles[k].z, z1 = z0;
        for (size_t v = k + 1; v < k + 3; ++v) {
            x0 = std::min(x0, t.triangles[v].x), x1 = std::max(x1, t.triangles[v].x);
            z0 = std::min(z0, t.triangles[v].z), z1 = std::max(z1, t.triangles[v].z);
        }
        tests += ((x1 - x0) / size_x * mw + 1.0) * ((z1 - z0) / size_z * mh + 1.0);
    }
    if (tests > kMaxTexelTests) {
        refuse("has terrain triangles that cover the maps' texels " + std::to_string(tests / (double(mw) * mh)) +
               " times over; at most " + std::to_string(kMaxTexelTests / (double(mw) * mh)) + " are rasterised");
    }
    TerrainRaster raster = rasterise_terrain(t.triangles, lo[0], lo[2], size_x, size_z, mw, mh);

    Scene& s = w->scene;
    s.field.cells_x = uint32_t(cells_x);
    s.field.cells_z = uint32_t(cells_z);
    s.field.cell_size = cell;
    s.field.base_transform[12] = lo[0];
    s.field.base_transform[13] = lo[1];
    s.field.base_transform[14] = lo[2];
    std::vector<double> heights;
    fill_uncovered_heights(raster, &heights);
    const double range = hi[1] - lo[1];
    s.maps[int(MapRole::height)] = Scene::MapImage{};
    if (range > 1e-6) {
        Scene::MapImage& h = s.maps[int(MapRole::height)];
        h.width = mw;
        h.height = mh;
        h.format = GRASS_MAP_FORMAT_R16_UNORM;
        h.pixels.resize(size_t(mw) * mh * 2);
        for (size_t k = 0; k < heights.size(); ++k) {
            const double y = heights[k] == heights[k] ? heights[k] : lo[1];
            const double unit = std::min(std::max((y - lo[1]) / range, 0.0), 1.0);
            const uint16_t v = uint16_t(std::lround(unit * 65535.0));
            std::memcpy(&h.pixels[2 * k], &v, 2);
        }
        s.height_scale = float(range);
    }
    DensityTexture texture;
    if (t.density == "texture") texture = decode_density_texture(w->model, t.texture);
    Scene::MapImage& d = s.maps[int(MapRole::density)];
    d = Scene::MapImage{};
    d.width = mw;
    d.height = mh;
    d.format = GRASS_MAP_FORMAT_R8_UNORM;
    d.pixels.assign(size_t(mw) * mh, 0);
    for (size_t k = 0; k < d.pixels.size(); ++k) {
        if (!raster.covered(k)) continue; // no terrain, no grass
        float density = raster.a[0][k];
        if (t.density == "texture") density = texture.sample(raster.a[0][k], raster.a[1][k], t.extras.density_channel);
        d.pixels[k] = uint8_t(std::lround(std::min(std::max(density, 0.0f), 1.0f) * 255.0f));
    }
    s.density_texels.clear();
    s.density_width = s.density_height = 0;
    w->info.map_width = mw;
    w->info.map_height = mh;
    w->info.terrain_triangles = t.triangles.size() / 3;
}

} // namespace

bool is_gltf_path(const std::string& path) {
    std::string lower = path;
    for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
    auto ends = [&](const std::string& tail) {
        return lower.size() >= tail.size() && lower.compare(lower.size() - tail.size(), tail.size(), tail) == 0;
    };
    return ends(".gltf") || ends(".glb");
}

bool load_gltf_scene(const std::string& path, Scene* scene, GltfInfo* info, std::string* error) {
    try {
        std::vector<std::string> notes;
        const Model model = load_model(path, &notes);
        Walk w{model, *scene, GltfInfo{}, Terrain{}};
        w.info.notes = notes;
        w.scene.meshes.clear();
        w.scene.tiers.clear(); // the library's default lod setup, as for a scene file
        w.scene.lod_tests.clear();
        for (Scene::MapImage& m : w.scene.maps) m = Scene::MapImage{};
        walk_scene(&w);
        make_field(&w);
        w.scene.ground = false; // the terrain mesh is the ground
        *scene = std::move(w.scene);
        if (info) *info = std::move(w.info);
    } catch (const std::exception& e) {
        if (error) *error = path + ": " + e.what();
        return false;
    }
    return true;
}

} // namespace grass_sample
