#version 450
// The test program of tests/render/blade_state_test.cpp: api/shaders/blade_state.glsl on a
// buffer of synthetic blades, one invocation a blade, included as blade.vert includes the
// responsive parts (no feature bit: the draw blocks and maps it declares are never read).
#ifndef VULKAN
#define GRASS_FEATURES 0u
#define TEST_BINDING(gl, vk) gl
#else
#define TEST_BINDING(gl, vk) vk
#endif
#define GRASS_RESPONSIVE 1
#include "blade_interface.glsl"
#include "lighting.glsl" // mirror_signs (blade_dynamics.glsl's cell_blade_pose)
#include "wind.glsl"
#include "interaction.glsl"
#include "blade_dynamics.glsl"
#include "blade_state.glsl"

layout(local_size_x = 64) in;

struct TestBlade {
    vec4 i1;      // xyz: rest v1 relative to the root (m), w: stiffness (m/s^2)
    vec4 i2;      // xyz: rest v2, w: segments
    vec4 up;      // xyz: unit up, w: recovery time (s)
    vec4 front;   // xyz: unit front, w: wind response
    vec4 wind;    // xyz: wind at the root (m/s), w: mass
    vec4 gravity; // xyz: gravity minus standard gravity (m/s^2)
};
layout(std430, binding = TEST_BINDING(4, 20)) readonly buffer Blades {
    TestBlade blades[];
};
layout(std430, binding = TEST_BINDING(5, 21)) buffer States {
    vec4 states[]; // two a blade (blade_state_pack)
};
layout(std430, binding = TEST_BINDING(6, 22)) writeonly buffer Poses {
    vec4 poses[]; // four a blade: the state's drawn v1, v2 (w: eta), the stateless pose's v1, v2
};
layout(std430, binding = TEST_BINDING(7, 23)) readonly buffer Params {
    float dt;
    int mode; // 0: blade_state_at_rest, 1: blade_state_step, 2: write the constants into poses[0..1]
    int collider_count;
    int blade_count;
    BladeCollider colliders[];
};

int blade_state_collider_count() { return collider_count; }
BladeCollider blade_state_collider(int k) { return colliders[k]; }

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (mode == 2) {
        if (i == 0u) {
            poses[0] = vec4(kBladeStateSubstep, float(kBladeStateMaxSubsteps), kBladeStateDamping, kBladeStateEtaBuild);
            poses[1] = vec4(kBladeStateMinRecovery, kBladeStateMaxDeflection, 0.0, 0.0);
        }
        return;
    }
    if (i >= uint(blade_count)) return;
    TestBlade b = blades[i];
    BladeRest rest;
    rest.i1 = b.i1.xyz;
    rest.i2 = b.i2.xyz;
    rest.up = b.up.xyz;
    rest.segments = int(b.i2.w);
    rest.len = drawn_length(rest.i1, rest.i2, rest.segments);
    BladeMechanics m;
    m.stiffness = b.i1.w;
    m.mass = b.wind.w;
    m.response = b.front.w;
    vec3 forces = rest.len > 0.0 ? blade_forces(m, b.wind.xyz, b.gravity.xyz, rest.i2, rest.up, b.front.xyz, rest.len)
                                 : vec3(0.0);
    BladeState s;
    if (mode == 0) {
        s = blade_state_at_rest(rest, m.stiffness, forces);
    } else {
        s = blade_state_unpack(states[2u * i], states[2u * i + 1u]);
        blade_state_step(s, rest, m.stiffness, forces, b.up.w, dt);
    }
    vec4 a, c;
    blade_state_pack(s, a, c);
    states[2u * i] = a;
    states[2u * i + 1u] = c;
    BladePose pose = blade_state_pose(s, rest);
    BladePose still = rest.len > 0.0 ? blade_equilibrium(rest.i1, rest.i2, rest.up, rest.len, m.stiffness, forces,
                                                         rest.segments)
                                     : pose;
    poses[4u * i] = vec4(pose.v1, rest.len);
    poses[4u * i + 1u] = vec4(pose.v2, s.eta);
    poses[4u * i + 2u] = vec4(still.v1, 0.0);
    poses[4u * i + 3u] = vec4(still.v2, 0.0);
}
