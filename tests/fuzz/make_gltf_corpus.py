#!/usr/bin/env python3
"""Writes the seed corpus of fuzz_gltf (tests/fuzz/corpus/gltf): the sample scene of
scripts/make-gltf-scene.py with an 8 x 8 terrain (hill-8x8.glb: rocks, shed, camera, a sphere
and a capsule collider, small enough for the fuzzer's 64 KiB inputs), and the quad of
tests/gltf/gltf_scene_test.cpp as a GLB, as .gltf with its buffer beside it (buffer.bin,
which fuzz_gltf writes) or in a data URI, and with a PNG density texture (density.png); and
the quad with a node whose "extras" nest arrays 100 deep in all (read), 101 (refused by the
loader's depth limit, as .gltf and .glb) and 20,000 (the 41 KB file that crashed tinygltf's
recursive parser, issue 37).

  python3 tests/fuzz/make_gltf_corpus.py
"""
import base64
import importlib.util
import json
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "corpus", "gltf")

spec = importlib.util.spec_from_file_location("make_gltf_scene", os.path.join(HERE, "..", "..", "scripts",
                                                                              "make-gltf-scene.py"))
hill = importlib.util.module_from_spec(spec)
spec.loader.exec_module(hill)

QUAD_BIN = (struct.pack("<12f", 0, 0, 0, 4, 0, 0, 0, 1, 4, 4, 1, 4) + struct.pack("<6H", 0, 2, 1, 1, 2, 3) +
            struct.pack("<16f", 1, 1, 1, 1, 1, 1, 1, 1, 0, 0, 0, 1, 0, 0, 0, 1))
assert len(QUAD_BIN) == 124


def quad(buffer, extras=None, more_nodes=()):
    terrain_extras = {"grass": {"cell_size": 0.5}}
    if extras:
        terrain_extras["grass"].update(extras)
    nodes = [{"name": "terrain", "mesh": 0, "extras": terrain_extras},
             {"name": "eye", "camera": 0, "translation": [2, 3, -5]}] + list(more_nodes)
    prim = {"attributes": {"POSITION": 0, "COLOR_0": 2}, "indices": 1}
    return {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "cameras": [{"type": "perspective", "perspective": {"yfov": 1.0, "znear": 0.1, "zfar": 300}}],
        "meshes": [{"primitives": [prim]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
            {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"},
            {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC4"}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 48},
            {"buffer": 0, "byteOffset": 48, "byteLength": 12},
            {"buffer": 0, "byteOffset": 60, "byteLength": 64}],
        "buffers": [buffer],
    }


def glb(doc, binary):
    return glb_text(json.dumps(doc, sort_keys=True, separators=(",", ":")).encode(), binary)


def glb_text(text, binary):
    text += b" " * (-len(text) % 4)
    total = 12 + 8 + len(text) + 8 + len(binary)
    return (struct.pack("<4sII", b"glTF", 2, total) + struct.pack("<I4s", len(text), b"JSON") + text +
            struct.pack("<I4s", len(binary), b"BIN\0") + binary)


def deep_extras(depth):
    """The quad with a node "deep" whose extras hold arrays nesting the JSON `depth` levels deep in
    all (the document, "nodes", the node and its "extras" are the first four)."""
    doc = quad({"byteLength": 124, "uri": "buffer.bin"}, more_nodes=[{"name": "deep", "extras": {"note": "DEEP"}}])
    text = json.dumps(doc, sort_keys=True, separators=(",", ":"))
    arrays = depth - 4
    return text.replace('"DEEP"', "[" * arrays + "0" + "]" * arrays)


def write(name, data):
    if isinstance(data, dict):
        data = json.dumps(data, indent=1, sort_keys=True).encode()
    with open(os.path.join(OUT, name), "wb") as f:
        f.write(data)


def main():
    os.makedirs(OUT, exist_ok=True)
    hill.terrain.__defaults__ = (8, 32.0)  # an 8 x 8 terrain instead of 48 x 48
    write("hill-8x8.glb", hill.scene())
    write("quad.glb", glb(quad({"byteLength": 124}), QUAD_BIN))
    write("quad-file.gltf", quad({"byteLength": 124, "uri": "buffer.bin"}))
    data_uri = "data:application/octet-stream;base64," + base64.b64encode(QUAD_BIN).decode()
    colliders = [
        {"name": "ball", "translation": [1, 0.3, 1],
         "extras": {"grass": {"role": "collider", "shape": "sphere", "radius": 0.3}}},
        {"name": "walker", "translation": [2, 0.9, 2], "scale": [1, 2, 1],
         "extras": {"grass": {"role": "collider", "shape": "capsule", "radius": 0.25, "height": 1.3}}}]
    write("quad-data-uri-colliders.gltf", quad({"byteLength": 124, "uri": data_uri}, more_nodes=colliders))
    textured = quad({"byteLength": 124, "uri": "buffer.bin"},
                    extras={"density": "texture", "density_texture": "grass", "density_channel": "g"})
    textured["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 0  # positions' xy as uv
    textured["images"] = [{"uri": "density.png", "name": "grass"}]
    textured["textures"] = [{"source": 0}]
    write("quad-texture.gltf", textured)
    for depth in (100, 101, 20000):
        write("quad-extras-deep-%d.gltf" % depth, deep_extras(depth).encode())
    deep_glb = json.loads(deep_extras(100).replace("[" * 96 + "0" + "]" * 96, "0"))  # the same without the arrays
    deep_glb["buffers"][0].pop("uri")
    text = json.dumps(deep_glb, sort_keys=True, separators=(",", ":")).replace('"note":0', '"note":' + "[" * 97 + "0" + "]" * 97)
    write("quad-extras-deep-101.glb", glb_text(text.encode(), QUAD_BIN))


if __name__ == "__main__":
    main()
