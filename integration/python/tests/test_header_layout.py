"""The binding against the headers: a C program compiled against grass.h, grass_gl.h and
grass_vk.h prints every struct's size, every field's offset and size, every enum value and
every numeric #define; they must equal what grass/_ffi.py declares. Every GRASS_API function
must be bound with the ctypes types its C declaration maps to. A changed struct or signature
fails here instead of corrupting memory."""
import ctypes
import os
import re
import subprocess

import pytest

from conftest import REPO_ROOT
from grass import _ffi

INCLUDE = os.path.join(REPO_ROOT, "api", "include")
HEADERS = ["grass.h", "grass_gl.h", "grass_vk.h"]


def _source():
    text = "\n".join(open(os.path.join(INCLUDE, "grass", h), encoding="utf-8").read() for h in HEADERS)
    # The "0.3 names" and "0.4 names" blocks declare old names for sources only
    # (GRASS_ENABLE_DEPRECATED); the binding binds the current names.
    text, blocks = re.subn(r"/\* ---- 0\.3 names \(begin\).*?/\* ---- 0\.3 names \(end\)[^\n]*", " ", text, flags=re.S)
    assert blocks == len(HEADERS), "each header has one 0.3 names block"
    text, blocks = re.subn(r"/\* ---- 0\.4 names \(begin\).*?/\* ---- 0\.4 names \(end\)[^\n]*", " ", text, flags=re.S)
    assert blocks == 2, "grass.h and grass_vk.h have a 0.4 names block"
    # ... and renamed fields' aliases (an anonymous union under GRASS_FIELD_ALIASES): the
    # binding binds the current field.
    text, blocks = re.subn(r"#if defined\(GRASS_FIELD_ALIASES\)\n.*?#else\n(.*?)#endif\n", r"\1", text, flags=re.S)
    assert blocks == 1, "grass_collider.centre is the one field alias"
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


SOURCE = _source()


def parse_structs():
    structs = {}
    for name, body in re.findall(r"typedef struct (\w+) \{(.*?)\} \1;", SOURCE, flags=re.S):
        fields = []
        for decl in body.split(";"):
            decl = " ".join(decl.split())
            if not decl:
                continue
            # A function pointer, with its calling convention (GRASS_API_PTR) or none.
            fn = re.search(r"\(\s*(?:GRASS_\w*API_PTR)?\s*\*\s*(\w+)\s*\)\s*\(", decl)
            if fn:
                fields.append(fn.group(1))
                continue
            first, *rest = [p.strip() for p in decl.split(",")]
            fields.append(re.search(r"(\w+)\s*(?:\[[^\]]*\])*$", first).group(1))  # [n] or [m][n]
            fields += [re.match(r"\**\s*(\w+)", r).group(1) for r in rest]
        structs[name] = fields
    return structs


def parse_enums():
    enums = {}
    for name, body in re.findall(r"typedef enum (\w+) \{(.*?)\} \1;", SOURCE, flags=re.S):
        enums[name] = [m.split("=")[0].strip() for m in body.split(",") if m.strip()]
    return enums


def parse_defines():
    return re.findall(r"#define (GRASS_\w+)\s+\(?\s*[0-9(]", SOURCE) + ["GRASS_HEADER_VERSION"]


def parse_functions():
    functions = {}
    code = re.sub(r"^\s*#[^\n]*", " ", SOURCE, flags=re.M)  # not the GRASS_API #defines
    for ret, name, params in re.findall(r"GRASS_API\s+([^;{}#]*?)\b(grass_\w+)\s*\(([^;]*?)\)\s*;", code):
        params = [" ".join(p.split()) for p in params.split(",")]
        functions[name] = (" ".join(ret.split()), [] if params == ["void"] else params)
    return functions


@pytest.fixture(scope="module")
def c_values(tmp_path_factory):
    structs, enums = parse_structs(), parse_enums()
    lines = ["#include <grass/grass_gl.h>", "#include <grass/grass_vk.h>", "#include <stddef.h>",
             "#include <stdio.h>", "int main(void) {"]
    for s, fields in structs.items():
        lines.append(f'    printf("S {s} %zu\\n", sizeof({s}));')
        for f in fields:
            lines.append(f'    printf("F {s} {f} %zu %zu\\n", offsetof({s}, {f}), sizeof((({s}*)0)->{f}));')
    for e, members in enums.items():
        lines.append(f'    printf("Z {e} %zu\\n", sizeof({e}));')
        for m in members:
            lines.append(f'    printf("E {e} {m} %lld\\n", (long long){m});')
    for d in parse_defines():
        lines.append(f'    printf("D {d} %lld\\n", (long long)({d}));')
    lines += ["    return 0;", "}"]
    work = tmp_path_factory.mktemp("layout")
    src, exe = work / "layout.c", work / "layout"
    src.write_text("\n".join(lines) + "\n")
    cc = os.environ.get("CC", "cc")
    subprocess.run([cc, "-std=c99", "-Wall", "-Werror", "-I", INCLUDE, str(src), "-o", str(exe)], check=True)
    out = subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout
    values = {"S": {}, "F": {}, "E": {}, "D": {}, "Z": {}}
    for line in out.splitlines():
        kind, *rest = line.split()
        if kind == "S":
            values["S"][rest[0]] = int(rest[1])
        elif kind == "F":
            values["F"].setdefault(rest[0], []).append((rest[1], int(rest[2]), int(rest[3])))
        elif kind == "E":
            values["E"].setdefault(rest[0], {})[rest[1]] = int(rest[2])
        elif kind == "Z":
            values["Z"][rest[0]] = int(rest[1])
        else:
            values["D"][rest[0]] = int(rest[1])
    return values


def test_the_parser_sees_the_headers():
    structs, functions = parse_structs(), parse_functions()
    assert len(structs) >= 20 and "grass_frame_stats" in structs and "grass_vk_desc" in structs
    assert structs["grass_patch_desc"][4:6] == ["length_min", "length_max"]
    assert structs["grass_allocator"] == ["alloc_fn", "free_fn", "user_data"]
    assert len(functions) >= 40 and "grass_gl_render" in functions and "grass_vk_record" in functions


def test_every_struct_has_the_headers_layout(c_values):
    assert set(_ffi.STRUCTS) == set(c_values["S"]), "structs in the headers and in _ffi.py differ"
    for name, size in c_values["S"].items():
        cls = _ffi.STRUCTS[name]
        c_fields = c_values["F"][name]
        py_fields = [(f[0], getattr(cls, f[0]).offset, getattr(cls, f[0]).size) for f in cls._fields_]
        assert py_fields == c_fields, f"{name}: fields (name, offset, size) differ from the header"
        assert ctypes.sizeof(cls) == size, f"sizeof({name})"
        assert ctypes.alignment(cls) <= size


def test_every_enum_value_matches(c_values):
    assert set(_ffi.ENUMS) == set(c_values["E"]), "enums in the headers and in _ffi.py differ"
    for name, members in c_values["E"].items():
        assert _ffi.ENUMS[name] == members, name
        assert c_values["Z"][name] == ctypes.sizeof(_ffi.grass_enum), f"sizeof({name})"


def test_every_define_matches(c_values):
    for name, value in c_values["D"].items():
        assert _ffi.DEFINES.get(name) == value, name


def _ctype(c):
    """The ctypes type a C parameter or return type maps to."""
    c = re.sub(r"\bconst\b", "", c)
    array = re.search(r"\[[^\]]*\]\s*$", c)
    c = re.sub(r"\[[^\]]*\]\s*$", "", c)
    c = c.replace("*", " * ")
    tokens = c.split()
    if array:
        tokens.append("*")
    # drop the parameter's name: the last identifier after a type
    if len([t for t in tokens if t != "*"]) > 1 and tokens[-1] != "*":
        tokens = tokens[:-1]
    base, stars = tokens[0], tokens.count("*")
    scalars = {"void": None, "uint32_t": ctypes.c_uint32, "int32_t": ctypes.c_int32, "uint64_t": ctypes.c_uint64,
               "uint16_t": ctypes.c_uint16, "double": ctypes.c_double, "float": ctypes.c_float,
               "size_t": ctypes.c_size_t, "grass_bool": _ffi.grass_bool}
    if base in _ffi.ENUMS:
        t = _ffi.grass_enum
    elif base in _ffi.STRUCTS:
        t = _ffi.STRUCTS[base]
    elif base == "grass_context":  # opaque
        assert stars >= 1
        t, stars = ctypes.c_void_p, stars - 1
    elif base == "char" and stars == 1:
        return ctypes.c_char_p
    elif base == "void" and stars == 1:
        return ctypes.c_void_p
    else:
        t = scalars[base]
    for _ in range(stars):
        t = ctypes.POINTER(t)
    return t


def test_every_function_is_bound_with_its_signature():
    functions = parse_functions()
    assert set(_ffi.FUNCTIONS) == set(functions), "GRASS_API functions in the headers and in _ffi.py differ"
    for name, (ret, params) in functions.items():
        restype, argtypes = _ffi.FUNCTIONS[name]
        assert restype is _ctype(ret), f"{name}: return type {ret}"
        assert len(argtypes) == len(params), f"{name}: parameter count"
        for i, (declared, param) in enumerate(zip(argtypes, params)):
            assert declared is _ctype(param), f"{name}: parameter {i} ({param})"


def test_the_library_exports_every_function():
    import grass
    for name in _ffi.FUNCTIONS:
        assert hasattr(grass.lib, name)
    assert grass.lib.grass_get_library_version() >> 12 == _ffi.GRASS_HEADER_VERSION >> 12
