"""The raw binding: every struct, enum, constant and function of grass.h, grass_gl.h and
grass_vk.h, as ctypes declares them. Names are the C names. tests/test_header_layout.py
checks this file against the headers (sizes, offsets, enum values, signatures)."""
import ctypes
import os
import sys
import warnings
from ctypes import (CFUNCTYPE, POINTER, Structure, c_char_p, c_double, c_float, c_int, c_int32, c_size_t,
                    c_uint16, c_uint32, c_uint64, c_void_p)

# ---- Constants (#define) -------------------------------------------------------------

DEFINES = {
    "GRASS_VERSION_MAJOR": 0,
    "GRASS_VERSION_MINOR": 5,
    "GRASS_VERSION_PATCH": 0,
    "GRASS_TIER_KIND_COUNT": 3,
    "GRASS_MAX_TIERS": 8,
    "GRASS_MAX_LOD_TESTS": 32,
    "GRASS_DEFAULT_TIER_COUNT": 5,
    "GRASS_DEFAULT_LOD_TEST_COUNT": 9,
    "GRASS_QUALITY_LEVEL_COUNT": 5,
    "GRASS_MAX_GRASS_TYPES": 8,
    "GRASS_MAX_WIND_SOURCES": 16,
    "GRASS_MAX_VIEWS_PER_FRAME": 16,
    "GRASS_MAX_SHADOW_CASCADES": 4,
    "GRASS_MAX_VIEW_LIGHTS": 8,
    "GRASS_MAX_GBUFFER_ATTACHMENTS": 8,
    "GRASS_MAX_COLLIDERS": 65536, "GRASS_MAX_COLLIDERS_PER_TILE": 1024,
    "GRASS_MAX_MEMORY_HEAPS": 16,
}
DEFINES["GRASS_HEADER_VERSION"] = ((DEFINES["GRASS_VERSION_MAJOR"] << 22) | (DEFINES["GRASS_VERSION_MINOR"] << 12)
                                   | DEFINES["GRASS_VERSION_PATCH"])
globals().update(DEFINES)
# The package's version is the header's (tests/test_header_layout.py checks DEFINES against
# grass.h); pyproject.toml reads it from here.
__version__ = f"{DEFINES['GRASS_VERSION_MAJOR']}.{DEFINES['GRASS_VERSION_MINOR']}.{DEFINES['GRASS_VERSION_PATCH']}"

# ---- Enums (C enums are ints) ---------------------------------------------------------

ENUMS = {
    "grass_result": {
        "GRASS_SUCCESS": 0, "GRASS_ERROR_INVALID_ARGUMENT": -1, "GRASS_ERROR_INVALID_HANDLE": -2,
        "GRASS_ERROR_WRONG_STRUCT_TYPE": -3, "GRASS_ERROR_INVALID_STATE": -4, "GRASS_ERROR_OUT_OF_MEMORY": -5,
        "GRASS_ERROR_VERSION_MISMATCH": -6, "GRASS_ERROR_BACKEND": -7, "GRASS_ERROR_UNSUPPORTED": -8,
        "GRASS_ERROR_IN_USE": -9,
    },
    "grass_struct_type": {
        "GRASS_STRUCT_TYPE_CONTEXT_DESC": 0x67720001, "GRASS_STRUCT_TYPE_PATCH_DESC": 0x67720002,
        "GRASS_STRUCT_TYPE_FIELD_DESC": 0x67720003, "GRASS_STRUCT_TYPE_MAP_DESC": 0x67720004,
        "GRASS_STRUCT_TYPE_VIEW_DESC": 0x67720005, "GRASS_STRUCT_TYPE_GRASS_TYPE_DESC": 0x67720006,
        "GRASS_STRUCT_TYPE_QUALITY_DESC": 0x67720007, "GRASS_STRUCT_TYPE_GL_DESC": 0x67720101,
        "GRASS_STRUCT_TYPE_VK_DESC": 0x67720201, "GRASS_STRUCT_TYPE_VK_RECORD_DESC": 0x67720202,
        "GRASS_STRUCT_TYPE_VK_PREPARE_DESC": 0x67720203, "GRASS_STRUCT_TYPE_VK_HOST_OBJECTS_DESC": 0x67720204,
        "GRASS_STRUCT_TYPE_VK_MULTIVIEW_DESC": 0x67720205,
        "GRASS_STRUCT_TYPE_VK_DEPTH_PASS_DESC": 0x67720206,
        "GRASS_STRUCT_TYPE_VK_VELOCITY_TARGET_DESC": 0x67720207,
        "GRASS_STRUCT_TYPE_VK_GBUFFER_TARGET_DESC": 0x67720208,
        "GRASS_STRUCT_TYPE_BLADE_MECHANICS": 0x67720008, "GRASS_STRUCT_TYPE_WIND_DESC": 0x67720009,
        "GRASS_STRUCT_TYPE_INTERACTION_DESC": 0x6772000A, "GRASS_STRUCT_TYPE_WIND_MAP_DESC": 0x6772000B,
        "GRASS_STRUCT_TYPE_BLADE_CULLING_DESC": 0x6772000C, "GRASS_STRUCT_TYPE_PIPELINE_DESC": 0x6772000D,
        "GRASS_STRUCT_TYPE_DEBUG_LABELS_DESC": 0x6772000E,
        "GRASS_STRUCT_TYPE_STEREO_VIEW_DESC": 0x6772000F, "GRASS_STRUCT_TYPE_LOD_ORIGIN_DESC": 0x67720010,
        "GRASS_STRUCT_TYPE_FRAME_DESC": 0x67720011, "GRASS_STRUCT_TYPE_VIEW_PASS_DESC": 0x67720012,
        "GRASS_STRUCT_TYPE_SHADOW_RECEIVE_DESC": 0x67720013,
        "GRASS_STRUCT_TYPE_VIEW_MOTION_DESC": 0x67720014,
        "GRASS_STRUCT_TYPE_VIEW_LIGHTS_DESC": 0x67720015,
        "GRASS_STRUCT_TYPE_VIEW_GBUFFER_DESC": 0x67720016,
        "GRASS_STRUCT_TYPE_BLADE_TESSELLATION_DESC": 0x67720017,
        "GRASS_STRUCT_TYPE_MESH_FIELD_DESC": 0x67720018,
    },
    "grass_log_level": {"GRASS_LOG_ERROR": 0, "GRASS_LOG_WARNING": 1, "GRASS_LOG_INFO": 2},
    "grass_message_id": {
        "GRASS_MSG_NONE": 0,
        "GRASS_MSG_NULL_ARGUMENT": 100, "GRASS_MSG_WRONG_STRUCT_TYPE": 101, "GRASS_MSG_NEXT_NOT_NULL": 102,
        "GRASS_MSG_NOT_FINITE": 103, "GRASS_MSG_OUT_OF_RANGE": 104, "GRASS_MSG_RANGE_INVERTED": 105,
        "GRASS_MSG_ZERO_CELLS": 106, "GRASS_MSG_BAD_TRANSFORM": 107, "GRASS_MSG_BAD_MAP": 108,
        "GRASS_MSG_BAD_ENUM": 109, "GRASS_MSG_ZERO_VECTOR": 110, "GRASS_MSG_MAP_ROLE": 111,
        "GRASS_MSG_MAP_REGION": 112, "GRASS_MSG_IN_GRASS_TYPE": 113,
        "GRASS_MSG_STALE_HANDLE": 200, "GRASS_MSG_FOREIGN_HANDLE": 201, "GRASS_MSG_NULL_HANDLE": 202,
        "GRASS_MSG_PATCH_IN_USE": 203, "GRASS_MSG_TOO_MANY_OBJECTS": 204, "GRASS_MSG_MAP_IN_USE": 205,
        "GRASS_MSG_FRAME_NOT_BEGUN": 300, "GRASS_MSG_FRAME_ALREADY_BEGUN": 301, "GRASS_MSG_WRONG_BACKEND": 302,
        "GRASS_MSG_UPLOAD_NOT_RECORDED": 303, "GRASS_MSG_REENTRANT_CALL": 304,
        "GRASS_MSG_VERSION_MISMATCH": 400, "GRASS_MSG_DEVICE_UNSUPPORTED": 401,
        "GRASS_MSG_BACKEND_CALL_FAILED": 402, "GRASS_MSG_OUT_OF_MEMORY": 403, "GRASS_MSG_INTERNAL_ERROR": 404,
        "GRASS_MSG_BAKE_CACHE": 405, "GRASS_MSG_DEVICE_LOST": 406, "GRASS_MSG_TIME_BACKWARDS": 407,
        "GRASS_MSG_GL_CONTEXT_NOT_CURRENT": 408, "GRASS_MSG_PIPELINE_CACHE": 409,
        "GRASS_MSG_DEBUG_LABELS_UNAVAILABLE": 410,
        "GRASS_MSG_FRAMES_IN_FLIGHT": 411,
        "GRASS_MSG_VELOCITY_TARGET": 412, "GRASS_MSG_COLLIDER_TILE_CAP": 413,
        "GRASS_MSG_GBUFFER_TARGET": 414, "GRASS_MSG_MESH_FIELD": 415,
        "GRASS_MSG_CONTEXT_CREATED": 500, "GRASS_MSG_PATCH_GENERATED": 501,
    },
    "grass_depth_mode": {"GRASS_DEPTH_LESS": 0, "GRASS_DEPTH_GREATER": 1},
    "grass_debug_labels": {"GRASS_DEBUG_LABELS_AUTO": 0, "GRASS_DEBUG_LABELS_OFF": 1, "GRASS_DEBUG_LABELS_ON": 2},
    "grass_backend": {"GRASS_BACKEND_NONE": 0, "GRASS_BACKEND_GL": 1, "GRASS_BACKEND_VULKAN": 2},
    "grass_threshold_mode": {"GRASS_THRESHOLD_UNIFORM": 0, "GRASS_THRESHOLD_CLUSTERED": 1},
    "grass_mesh_density_source": {
        "GRASS_MESH_DENSITY_UNIFORM": 0, "GRASS_MESH_DENSITY_PER_VERTEX": 1, "GRASS_MESH_DENSITY_MAP": 2,
    },
    "grass_mesh_seeding": {"GRASS_MESH_SEEDING_SINGLE_BLADES": 0, "GRASS_MESH_SEEDING_TUFTS": 1},
    "grass_map_format": {
        "GRASS_MAP_FORMAT_R8_UNORM": 1, "GRASS_MAP_FORMAT_R16_UNORM": 2, "GRASS_MAP_FORMAT_R32_FLOAT": 3,
        "GRASS_MAP_FORMAT_RGBA8_UNORM": 4, "GRASS_MAP_FORMAT_RGBA16_UNORM": 5, "GRASS_MAP_FORMAT_RGBA32_FLOAT": 6,
    },
    "grass_tier_kind": {"GRASS_TIER_GEOMETRY": 0, "GRASS_TIER_VOLUME": 1, "GRASS_TIER_IMAGE": 2},
    "grass_pass_kind": {"GRASS_PASS_COLOR": 0, "GRASS_PASS_DEPTH": 1, "GRASS_PASS_GBUFFER": 2},
    "grass_gbuffer_semantic": {
        "GRASS_GBUFFER_NONE": 0, "GRASS_GBUFFER_ALBEDO": 1, "GRASS_GBUFFER_NORMAL": 2, "GRASS_GBUFFER_MATERIAL": 3,
        "GRASS_GBUFFER_VELOCITY": 4,
    },
    "grass_gbuffer_format": {
        "GRASS_GBUFFER_FORMAT_UNORM": 0, "GRASS_GBUFFER_FORMAT_SNORM": 1, "GRASS_GBUFFER_FORMAT_FLOAT": 2,
    },
    "grass_shadow_compare": {"GRASS_SHADOW_COMPARE_LESS_EQUAL": 0, "GRASS_SHADOW_COMPARE_GREATER_EQUAL": 1},
    "grass_light_kind": {"GRASS_LIGHT_DIRECTIONAL": 0, "GRASS_LIGHT_POINT": 1, "GRASS_LIGHT_SPOT": 2},
    "grass_lod_answer": {"GRASS_LOD_DISCARD": 0, "GRASS_LOD_SPLIT": 1, "GRASS_LOD_DRAW": 2},
    "grass_lod_test_kind": {
        "GRASS_LOD_TEST_DISTANCE_BAND": 1, "GRASS_LOD_TEST_MACRO_CELL": 2, "GRASS_LOD_TEST_CALLBACK": 3,
        "GRASS_LOD_TEST_UNPLANARITY": 4, "GRASS_LOD_TEST_HILLTOP": 5,
    },
    "grass_quality_level": {
        "GRASS_QUALITY_REFERENCE": 0, "GRASS_QUALITY_HIGH": 1, "GRASS_QUALITY_DEFAULT": 2, "GRASS_QUALITY_LOW": 3,
        "GRASS_QUALITY_FASTEST": 4,
    },
    "grass_view_flags": {
        "GRASS_VIEW_FLAG_NONE": 0, "GRASS_VIEW_FLAG_NO_DEPTH_TEST": 1, "GRASS_VIEW_FLAG_DEBUG_TIERS": 2,
        "GRASS_VIEW_FLAG_DEBUG_CELLS": 4, "GRASS_VIEW_FLAG_DEBUG_THRESHOLDS": 8, "GRASS_VIEW_FLAG_ENCODE_SRGB": 16,
    },
    "grass_wind_source_kind": {
        "GRASS_WIND_SOURCE_POINT": 0, "GRASS_WIND_SOURCE_CONE": 1, "GRASS_WIND_SOURCE_BLAST": 2,
    },
    "grass_collider_shape": {"GRASS_COLLIDER_SPHERE": 0, "GRASS_COLLIDER_CAPSULE": 1},
    "grass_distance_culling": {
        "GRASS_DISTANCE_CULLING_OFF": 0, "GRASS_DISTANCE_CULLING_BLADE_INDEX": 1,
        "GRASS_DISTANCE_CULLING_THRESHOLD": 2,
    },
    "grass_pipeline_feature_bits": {
        "GRASS_PIPELINE_FEATURE_WIND": 0x1, "GRASS_PIPELINE_FEATURE_WIND_MAP": 0x2,
        "GRASS_PIPELINE_FEATURE_INTERACTION": 0x4, "GRASS_PIPELINE_FEATURE_BLADE_CULLING": 0x8,
        "GRASS_PIPELINE_FEATURE_DEBUG_VIEWS": 0x10, "GRASS_PIPELINE_FEATURE_ALL": 0x1F,
        "GRASS_PIPELINE_FEATURE_DEPTH_PASS": 0x20, "GRASS_PIPELINE_FEATURE_SHADOW_RECEIVE": 0x40,
        "GRASS_PIPELINE_FEATURE_MOTION_VECTORS": 0x80, "GRASS_PIPELINE_FEATURE_HOST_LIGHTS": 0x100,
        "GRASS_PIPELINE_FEATURE_GBUFFER": 0x200, "GRASS_PIPELINE_FEATURE_ALL_VIEWS": 0x3E0,
    },
}
for _values in ENUMS.values():
    globals().update(_values)

grass_enum = c_int
grass_bool = c_uint32

# ---- Callback types -------------------------------------------------------------------

# GRASS_API_PTR and GRASS_VKAPI_PTR are __stdcall on Windows (grass.h, grass_vk.h): ctypes'
# WINFUNCTYPE there (the same as CFUNCTYPE on 64-bit Windows), the C convention elsewhere.
_API_FUNCTYPE = getattr(ctypes, "WINFUNCTYPE", CFUNCTYPE) if sys.platform == "win32" else CFUNCTYPE

grass_log_fn = _API_FUNCTYPE(None, c_void_p, grass_enum, grass_enum, c_char_p)
grass_alloc_fn = _API_FUNCTYPE(c_void_p, c_void_p, c_size_t, c_size_t)
grass_free_fn = _API_FUNCTYPE(None, c_void_p, c_void_p)
# grass_gl_proc is a function pointer; a loader returns its address (or None).
grass_gl_get_proc_address_fn = _API_FUNCTYPE(c_void_p, c_void_p, c_char_p)
grass_vk_get_instance_proc_addr_fn = _API_FUNCTYPE(c_void_p, c_void_p, c_char_p)

# ---- Structs ----------------------------------------------------------------------------


class grass_allocator(Structure):
    _fields_ = [("alloc_fn", grass_alloc_fn), ("free_fn", grass_free_fn), ("user_data", c_void_p)]


class grass_context_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("allocator", grass_allocator), ("log_fn", grass_log_fn),
                ("log_user_data", c_void_p), ("log_level", grass_enum), ("depth_mode", grass_enum),
                ("cache_directory", c_char_p)]


_HEAPS = DEFINES["GRASS_MAX_MEMORY_HEAPS"]


class grass_debug_labels_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("labels", grass_enum)]


class grass_memory_stats(Structure):
    _fields_ = [("host_bytes", c_uint64), ("host_allocations", c_uint64), ("gpu_bytes", c_uint64),
                ("host_bytes_peak", c_uint64), ("dynamics_gpu_bytes", c_uint64), ("heap_count", c_uint32),
                ("heap_budget_known", c_uint32), ("device_allocations", c_uint64),
                ("heap_size", c_uint64 * _HEAPS), ("heap_allocated", c_uint64 * _HEAPS),
                ("heap_in_use", c_uint64 * _HEAPS), ("heap_budget", c_uint64 * _HEAPS),
                ("heap_usage", c_uint64 * _HEAPS)]


class grass_patch_id(Structure):
    _fields_ = [("index", c_uint32), ("generation", c_uint16), ("owner", c_uint16)]


class grass_field_id(Structure):
    _fields_ = [("index", c_uint32), ("generation", c_uint16), ("owner", c_uint16)]


class grass_map_id(Structure):
    _fields_ = [("index", c_uint32), ("generation", c_uint16), ("owner", c_uint16)]


class grass_patch_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("blade_count", c_uint32), ("subdivisions", c_uint32),
                ("length_min", c_float), ("length_max", c_float), ("width_min", c_float), ("width_max", c_float),
                ("tilt_min", c_float), ("tilt_max", c_float), ("bend_min", c_float), ("bend_max", c_float),
                ("root_color", c_float * 3), ("tip_color", c_float * 3), ("blade_color_variation", c_float),
                ("vertex_color_variation", c_float), ("threshold_mode", grass_enum), ("cluster_sigma", c_float),
                ("cluster_frequency", c_uint32), ("ao_impact", c_float), ("ao_height", c_float), ("seed", c_uint64)]


class grass_patch_info(Structure):
    _fields_ = [("blade_count", c_uint32), ("vertex_count", c_uint32), ("triangle_count", c_uint32),
                ("bounds_min", c_float * 3), ("bounds_max", c_float * 3), ("content_hash", c_uint64)]


class grass_map_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("pixels", c_void_p), ("width", c_uint32),
                ("height", c_uint32), ("row_pitch", c_uint32), ("format", grass_enum)]


class grass_map_stack(Structure):
    _fields_ = [("density", grass_map_id), ("color", grass_map_id), ("ambient", grass_map_id),
                ("diffuse", grass_map_id), ("height", grass_map_id), ("height_scale", c_float),
                ("cell_to_map", c_double * 6)]


class grass_tier_desc(Structure):
    _fields_ = [("kind", grass_enum), ("slices", c_uint32)]


class grass_lod_node(Structure):
    _fields_ = [("level", c_uint32), ("cell_x", c_uint32), ("cell_z", c_uint32), ("cells_x", c_uint32),
                ("cells_z", c_uint32), ("tier", c_uint32), ("center", c_double * 3), ("radius", c_double),
                ("distance_min", c_double), ("distance_max", c_double), ("height_min", c_double),
                ("height_max", c_double)]


grass_lod_test_fn = _API_FUNCTYPE(grass_enum, c_void_p, POINTER(grass_lod_node))


class grass_lod_test(Structure):
    _fields_ = [("kind", grass_enum), ("tier", c_uint32), ("begin", c_float), ("end", c_float),
                ("transition_in", c_float), ("transition_out", c_float), ("edge_ratio", c_float),
                ("max_macro_cells", c_uint32), ("callback", grass_lod_test_fn), ("user_data", c_void_p),
                ("max_unplanarity", c_float), ("unplanarity_ratio", c_float)]


class grass_quality_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("blades_everywhere", grass_bool),
                ("distance_scale", c_float), ("transition_scale", c_float), ("slice_scale", c_float),
                ("macro_cell_scale", c_float), ("blade_subdivisions", c_uint32), ("blade_fraction", c_float),
                ("msaa_samples", c_uint32)]


class grass_field_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("patch", grass_patch_id), ("cells_x", c_uint32),
                ("cells_z", c_uint32), ("cell_size", c_double), ("base_transform", c_double * 16),
                ("density", c_float), ("density_map", POINTER(grass_map_desc)), ("mirror_tiling", grass_bool),
                ("mirror_seed", c_uint32), ("tiers", POINTER(grass_tier_desc)), ("tier_count", c_uint32),
                ("lod_tests", POINTER(grass_lod_test)), ("lod_test_count", c_uint32),
                ("transition_window", c_float), ("maps", grass_map_stack)]


class grass_mesh_field_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("patch", grass_patch_id), ("patch_scale", c_float),
                ("positions", POINTER(c_float)), ("position_stride", c_uint32), ("normals", POINTER(c_float)),
                ("normal_stride", c_uint32), ("uvs", POINTER(c_float)), ("uv_stride", c_uint32),
                ("vertex_count", c_uint64), ("indices", POINTER(c_uint32)), ("index_count", c_uint64),
                ("transform", c_double * 16), ("density", c_float), ("density_source", grass_enum),
                ("vertex_density", POINTER(c_float)), ("vertex_density_stride", c_uint32), ("maps", grass_map_stack),
                ("seeding", grass_enum), ("tuft_min_distance", c_float), ("tuft_radius", c_float),
                ("blades_per_tuft", c_uint32), ("patch_blades", c_uint32), ("seed", c_uint32)]


class grass_grass_type_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("patch", grass_patch_id), ("density", c_float),
                ("density_map", grass_map_id), ("tiers", POINTER(grass_tier_desc)), ("tier_count", c_uint32),
                ("lod_tests", POINTER(grass_lod_test)), ("lod_test_count", c_uint32)]


class grass_view_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("camera_position", c_double * 3),
                ("view", c_float * 16), ("projection", c_float * 16), ("viewport", c_int32 * 4),
                ("sun_direction", c_float * 3), ("sun_color", c_float * 3), ("ambient_color", c_float * 3),
                ("time", c_double), ("flags", c_uint32)]


class grass_stereo_view_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("camera_position", c_double * 3),
                ("view", c_float * 16), ("projection", c_float * 16)]


class grass_lod_origin_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("position", c_double * 3)]


class grass_view_pass_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("pass", grass_enum), ("depth_bias_constant", c_float),
                ("depth_bias_slope", c_float)]


class grass_gbuffer_attachment(Structure):
    _fields_ = [("semantic", grass_enum), ("format", grass_enum), ("write_mask", c_uint32)]


class grass_view_gbuffer_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("attachment_count", c_uint32),
                ("attachments", grass_gbuffer_attachment * DEFINES["GRASS_MAX_GBUFFER_ATTACHMENTS"])]


class grass_shadow_receive_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("shadow_map", c_uint64), ("vk_image_layout", c_uint32),
                ("cascade_count", c_uint32), ("world_to_shadow", (c_float * 16) * 4), ("cascade_end", c_float * 4),
                ("compare", grass_enum), ("depth_bias", c_float), ("filter_radius", c_float)]


class grass_view_motion_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("previous_camera_position", c_double * 3),
                ("previous_view", c_float * 16), ("previous_projection", c_float * 16), ("jitter", c_float * 2),
                ("previous_jitter", c_float * 2), ("previous_time", c_double), ("velocity_attachment", c_uint32)]


class grass_light(Structure):
    _fields_ = [("kind", grass_enum), ("position", c_double * 3), ("direction", c_float * 3), ("color", c_float * 3),
                ("intensity", c_float), ("range", c_float), ("inner_cone_angle", c_float),
                ("outer_cone_angle", c_float)]


class grass_view_lights_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("light_count", c_uint32), ("lights", POINTER(grass_light)),
                ("specular_strength", c_float), ("specular_exponent", c_float), ("ambient_sh_enabled", c_uint32),
                ("ambient_sh", (c_float * 3) * 9)]


class grass_frame_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("frame_index", c_uint64),
                ("completed_frame_index", c_uint64), ("time", c_double)]


_KINDS = DEFINES["GRASS_TIER_KIND_COUNT"]


class grass_frame_stats(Structure):
    _fields_ = [("fields_drawn", c_uint64), ("nodes_visited", c_uint64), ("cells_drawn", c_uint64),
                ("blades_submitted", c_uint64), ("blades_drawn", c_uint64), ("triangles", c_uint64),
                ("plan_ms", c_double), ("lod_test_calls", c_uint64), ("nodes_culled", c_uint64),
                ("instances", c_uint64 * _KINDS), ("macro_cells", c_uint64 * _KINDS), ("cells", c_uint64 * _KINDS),
                ("nodes_empty", c_uint64), ("draws", c_uint64), ("colliders", c_uint64),
                ("colliders_in_map", c_uint64), ("interaction_texels", c_uint64), ("time_step", c_double)]


class grass_blade_mechanics(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("stiffness", c_float), ("mass", c_float),
                ("wind_response", c_float), ("trample_depth", c_float), ("recovery_time", c_float),
                ("variation", c_float)]


class grass_wind_source(Structure):
    _fields_ = [("kind", grass_enum), ("position", c_double * 3), ("direction", c_float * 3),
                ("cone_angle", c_float), ("speed", c_float), ("radius", c_float), ("start_time", c_double),
                ("duration", c_float), ("front_speed", c_float)]


class grass_wind_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("direction", c_float * 3), ("speed", c_float),
                ("gust_strength", c_float), ("gust_length", c_float), ("turbulence", c_float),
                ("gravity", c_float * 3), ("sources", POINTER(grass_wind_source)), ("source_count", c_uint32)]


class grass_wind_map_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("map", grass_map_id), ("speed", c_float),
                ("cell_to_map", c_double * 6)]


class grass_collider(Structure):
    _fields_ = [("shape", grass_enum), ("radius", c_float), ("center", c_double * 3), ("end", c_double * 3),
                ("velocity", c_float * 3)]

    # center's 0.5 development name, as the header's alias (GRASS_ENABLE_DEPRECATED): the same
    # storage, with a DeprecationWarning; also a keyword of the constructor.
    @property
    def centre(self):
        warnings.warn("grass_collider.centre was renamed center in grass 0.5", DeprecationWarning, stacklevel=2)
        return self.center

    @centre.setter
    def centre(self, value):
        warnings.warn("grass_collider.centre was renamed center in grass 0.5", DeprecationWarning, stacklevel=2)
        self.center[:] = tuple(value)


class grass_interaction_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("up", c_float * 3), ("resolution", c_uint32),
                ("level_count", c_uint32), ("texel_size", c_float * 2)]


class grass_blade_tessellation_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("enabled", grass_bool), ("error_pixels", c_float)]


class grass_blade_culling_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("orientation", grass_bool),
                ("orientation_limit", c_float), ("view_frustum", grass_bool), ("frustum_tolerance", c_float),
                ("distance", grass_enum), ("distance_levels", c_uint32), ("distance_max", c_float)]


class grass_pipeline_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("features", c_uint32), ("cache_data", c_void_p),
                ("cache_data_size", c_uint64)]


class grass_gl_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("get_proc_address", grass_gl_get_proc_address_fn),
                ("get_proc_address_user_data", c_void_p)]


class grass_vk_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p),
                ("get_instance_proc_addr", grass_vk_get_instance_proc_addr_fn), ("instance", c_void_p),
                ("physical_device", c_void_p), ("device", c_void_p), ("queue_family", c_uint32),
                ("render_pass", c_uint64), ("subpass", c_uint32), ("color_format", c_uint32),
                ("depth_format", c_uint32), ("sample_count", c_uint32), ("frames_in_flight", c_uint32)]


class grass_vk_host_objects_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("allocation_callbacks", c_void_p),
                ("pipeline_cache", c_uint64)]


class grass_vk_multiview_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("view_mask", c_uint32)]


class grass_vk_depth_pass_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("render_pass", c_uint64), ("subpass", c_uint32),
                ("depth_format", c_uint32), ("sample_count", c_uint32)]


class grass_vk_velocity_target_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("color_attachment_count", c_uint32),
                ("velocity_attachment", c_uint32), ("color_formats", c_uint32 * 7)]


class grass_vk_gbuffer_target_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("color_attachment_count", c_uint32),
                ("color_formats", c_uint32 * 8)]


class grass_vk_record_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("command_buffer", c_void_p)]


class grass_vk_prepare_desc(Structure):
    _fields_ = [("type", grass_enum), ("next", c_void_p), ("command_buffer", c_void_p)]


STRUCTS = {name: cls for name, cls in globals().items()
           if isinstance(cls, type) and issubclass(cls, Structure) and name.startswith("grass_")}

# ---- Functions: name -> (restype, argtypes) -----------------------------------------------

_ctx = c_void_p  # grass_context*, opaque
_P = POINTER
FUNCTIONS = {
    # grass.h
    "grass_get_library_version": (c_uint32, []),
    "grass_result_string": (c_char_p, [grass_enum]),
    "grass_default_context_desc": (grass_context_desc, []),
    "grass_default_debug_labels_desc": (grass_debug_labels_desc, []),
    "grass_create_context": (grass_enum, [c_uint32, _P(grass_context_desc), _P(_ctx)]),
    "grass_destroy_context": (None, [_ctx]),
    "grass_get_context_backend": (grass_enum, [_ctx]),
    "grass_get_last_error": (c_char_p, [_ctx]),
    "grass_get_memory_stats": (grass_enum, [_ctx, _P(grass_memory_stats)]),
    "grass_patch_id_equal": (grass_bool, [grass_patch_id, grass_patch_id]),
    "grass_field_id_equal": (grass_bool, [grass_field_id, grass_field_id]),
    "grass_map_id_equal": (grass_bool, [grass_map_id, grass_map_id]),
    "grass_patch_id_is_null": (grass_bool, [grass_patch_id]),
    "grass_field_id_is_null": (grass_bool, [grass_field_id]),
    "grass_map_id_is_null": (grass_bool, [grass_map_id]),
    "grass_default_patch_desc": (grass_patch_desc, []),
    "grass_create_patch": (grass_enum, [_ctx, _P(grass_patch_desc), _P(grass_patch_id)]),
    "grass_destroy_patch": (grass_enum, [_ctx, grass_patch_id]),
    "grass_get_patch_info": (grass_enum, [_ctx, grass_patch_id, _P(grass_patch_info)]),
    "grass_get_patch_thresholds": (grass_enum, [_ctx, grass_patch_id, _P(c_float), c_uint32]),
    "grass_default_map_desc": (grass_map_desc, []),
    "grass_create_map": (grass_enum, [_ctx, _P(grass_map_desc), _P(grass_map_id)]),
    "grass_update_map": (grass_enum, [_ctx, grass_map_id, c_uint32, c_uint32, _P(grass_map_desc)]),
    "grass_destroy_map": (grass_enum, [_ctx, grass_map_id]),
    "grass_default_lod_setup": (None, [c_double, _P(grass_tier_desc), _P(grass_lod_test)]),
    "grass_quality_preset": (grass_quality_desc, [grass_enum]),
    "grass_apply_quality": (grass_enum, [_ctx, _P(grass_quality_desc), c_double, _P(grass_patch_desc),
                                         _P(grass_tier_desc), _P(c_uint32), _P(grass_lod_test), _P(c_uint32)]),
    "grass_default_field_desc": (grass_field_desc, []),
    "grass_default_grass_type_desc": (grass_grass_type_desc, []),
    "grass_create_field": (grass_enum, [_ctx, _P(grass_field_desc), _P(grass_field_id)]),
    "grass_default_mesh_field_desc": (grass_mesh_field_desc, []),
    "grass_create_mesh_field": (grass_enum, [_ctx, _P(grass_mesh_field_desc), _P(grass_field_id)]),
    "grass_destroy_field": (grass_enum, [_ctx, grass_field_id]),
    "grass_default_view_desc": (grass_view_desc, []),
    "grass_default_stereo_view_desc": (grass_stereo_view_desc, []),
    "grass_default_lod_origin_desc": (grass_lod_origin_desc, []),
    "grass_begin_frame": (grass_enum, [_ctx, _P(grass_view_desc)]),
    "grass_end_frame": (grass_enum, [_ctx]),
    "grass_default_view_pass_desc": (grass_view_pass_desc, []),
    "grass_default_view_gbuffer_desc": (grass_view_gbuffer_desc, []),
    "grass_default_shadow_receive_desc": (grass_shadow_receive_desc, []),
    "grass_default_view_motion_desc": (grass_view_motion_desc, []),
    "grass_default_light": (grass_light, []),
    "grass_default_view_lights_desc": (grass_view_lights_desc, []),
    "grass_default_frame_desc": (grass_frame_desc, []),
    "grass_begin_host_frame": (grass_enum, [_ctx, _P(grass_frame_desc)]),
    "grass_plan_view": (grass_enum, [_ctx, _P(grass_view_desc), _P(c_uint32)]),
    "grass_get_frame_stats": (grass_enum, [_ctx, _P(grass_frame_stats)]),
    "grass_get_tier_gpu_ms": (grass_enum, [_ctx, _P(c_double), _P(grass_bool)]),
    "grass_default_blade_mechanics": (grass_blade_mechanics, []),
    "grass_set_blade_mechanics": (grass_enum, [_ctx, grass_patch_id, _P(grass_blade_mechanics)]),
    "grass_default_wind_desc": (grass_wind_desc, []),
    "grass_set_wind": (grass_enum, [_ctx, _P(grass_wind_desc)]),
    "grass_default_wind_map_desc": (grass_wind_map_desc, []),
    "grass_set_field_wind_map": (grass_enum, [_ctx, grass_field_id, _P(grass_wind_map_desc)]),
    "grass_set_colliders": (grass_enum, [_ctx, _P(grass_collider), c_uint32]),
    "grass_default_interaction_desc": (grass_interaction_desc, []),
    "grass_set_interaction": (grass_enum, [_ctx, _P(grass_interaction_desc)]),
    "grass_default_blade_culling_desc": (grass_blade_culling_desc, []),
    "grass_set_blade_culling": (grass_enum, [_ctx, grass_field_id, _P(grass_blade_culling_desc)]),
    "grass_default_blade_tessellation_desc": (grass_blade_tessellation_desc, []),
    "grass_quality_blade_tessellation": (grass_blade_tessellation_desc, [grass_enum]),
    "grass_set_blade_tessellation": (grass_enum, [_ctx, grass_field_id, _P(grass_blade_tessellation_desc)]),
    "grass_default_pipeline_desc": (grass_pipeline_desc, []),
    "grass_prepare_pipelines": (grass_enum, [_ctx, _P(grass_pipeline_desc)]),
    "grass_get_pipeline_cache_data": (grass_enum, [_ctx, c_void_p, _P(c_uint64)]),
    # grass_gl.h
    "grass_default_gl_desc": (grass_gl_desc, []),
    "grass_gl_create_context": (grass_enum, [c_uint32, _P(grass_context_desc), _P(grass_gl_desc), _P(_ctx)]),
    "grass_gl_render": (grass_enum, [_ctx]),
    "grass_gl_render_view": (grass_enum, [_ctx, c_uint32]),
    # grass_vk.h
    "grass_default_vk_desc": (grass_vk_desc, []),
    "grass_vk_create_context": (grass_enum, [c_uint32, _P(grass_context_desc), _P(grass_vk_desc), _P(_ctx)]),
    "grass_default_vk_prepare_desc": (grass_vk_prepare_desc, []),
    "grass_default_vk_host_objects_desc": (grass_vk_host_objects_desc, []),
    "grass_default_vk_multiview_desc": (grass_vk_multiview_desc, []),
    "grass_default_vk_depth_pass_desc": (grass_vk_depth_pass_desc, []),
    "grass_default_vk_velocity_target_desc": (grass_vk_velocity_target_desc, []),
    "grass_default_vk_gbuffer_target_desc": (grass_vk_gbuffer_target_desc, []),
    "grass_vk_prepare": (grass_enum, [_ctx, _P(grass_vk_prepare_desc)]),
    "grass_default_vk_record_desc": (grass_vk_record_desc, []),
    "grass_vk_record": (grass_enum, [_ctx, _P(grass_vk_record_desc)]),
    "grass_vk_record_view": (grass_enum, [_ctx, c_uint32, _P(grass_vk_record_desc)]),
}


def _candidates():
    env = os.environ.get("GRASS_LIBRARY")
    if env:
        return [env]
    here = os.path.dirname(os.path.abspath(__file__))
    found = [os.path.join(here, "libgrass.so.0"), os.path.join(here, "libgrass.so")]
    try:  # written by cmake --install (integration/python/install-python.cmake)
        from importlib import import_module
        found.append(import_module(f"{__package__}._config").LIBRARY)
    except ImportError:
        pass
    return found + ["libgrass.so.0"]


def load_library():
    """Loads libgrass: $GRASS_LIBRARY, else libgrass.so.0 next to this package, else the
    library cmake --install installed with the package (grass/_config.py), else the system
    loader's libgrass.so.0 (an installed grass, or LD_LIBRARY_PATH). Declares every
    function's signature and checks the library's major version."""
    errors = []
    for path in _candidates():
        if os.sep in path and not os.path.exists(path):
            errors.append(f"{path}: no such file")
            continue
        try:
            lib = ctypes.CDLL(path)
            break
        except OSError as e:
            errors.append(str(e))
    else:
        raise OSError("libgrass not found (set GRASS_LIBRARY to the path of libgrass.so): " + "; ".join(errors))
    for name, (restype, argtypes) in FUNCTIONS.items():
        fn = getattr(lib, name)
        fn.restype = restype
        fn.argtypes = argtypes
    version = lib.grass_get_library_version()
    if version >> 22 != GRASS_VERSION_MAJOR or ((version >> 12) & 0x3FF) < GRASS_VERSION_MINOR:
        raise OSError(f"{lib._name} is version {version >> 22}.{(version >> 12) & 0x3FF}; this binding needs "
                      f"{GRASS_VERSION_MAJOR}.{GRASS_VERSION_MINOR} or a later minor version")
    return lib
