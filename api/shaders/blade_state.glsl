// Per-blade state (jahrmann2017 5, docs/responsive.md "Per-blade state"): the tip of a blade
// that remembers where it was. Jahrmann moves the tip v2 by (r + g + w) dt + d each frame
// (eq. 1): recovery weakened by the collision strength eta (eq. 2-3), gravity and wind, and
// the push-out d of colliders (eq. 14-16); then the state is validated (eq. 9, 11, 13). Here
// the tip has a velocity as well, so that a gust makes it lag and overshoot: a damped spring
// whose rest point is exactly the stateless equilibrium (blade_equilibrium), stepped exactly
// (no integration error, stable at any dt). Pure functions, no bindings: included after
// blade_dynamics.glsl (BladePose, validate_blade, blade_equilibrium, blade_forces).
//
// The state keeps the *free* tip: the spring's point before eq. 11 and 13 (eq. 9 applies to
// it). The drawn pose validates it (blade_state_pose), so under constant forces the state
// converges to the stateless pose exactly and a blade handed between the two does not jump.

// Mirrored in api/src/dynamics/blade_state.hpp (a test compares them).
const float kBladeStateSubstep = 1.0 / 60.0; // the longest substep (s)
const int kBladeStateMaxSubsteps = 16;       // a step of dt: min(ceil(dt / substep), 16) equal substeps
const float kBladeStateDamping = 0.4;        // the tip's damping ratio at full recovery (eta 0)
const float kBladeStateEtaBuild = 50.0;      // eta per second for a push-out of the whole length (eq. 16)
const float kBladeStateMinRecovery = 0.1;    // eq. 3: recovery is at least this share of its strength
const float kBladeStateMaxDeflection = 100.0; // the free tip stays within this many lengths of I_v2 (per axis)

struct BladeState {
    vec3 v2;       // the free tip relative to the root (world m): eq. 9 applied, not eq. 11 and 13
    vec3 velocity; // its velocity (m/s)
    float eta;     // collision strength (eq. 2-3, 16), 0..1
};

// A blade's rest pose as the state needs it: relative to its root, world metres.
struct BladeRest {
    vec3 i1;      // rest v1
    vec3 i2;      // rest v2
    vec3 up;      // unit
    float len;    // drawn rest length (drawn_length of i1, i2), eq. 13 keeps it
    int segments; // segments the blade is drawn with
};

// A collider as the state sees it (api/src/foundation/frame_plan.hpp GpuCollider, moved to
// the blade's root): where it is at the end of the step.
struct BladeCollider {
    vec4 a;        // xyz: centre (sphere) or one axis end (capsule) relative to the root (m), w: radius
    vec4 b;        // xyz: the capsule's other end relative to the root (m), w: shape (0 sphere, 1 capsule)
    vec4 velocity; // xyz: m/s; it was at a - velocity t, t seconds before the step's end
};

// Supplied by the shader that includes this file: the colliders that may touch the blade
// being stepped (blade_state_step reads them, nothing else does).
int blade_state_collider_count();
BladeCollider blade_state_collider(int k);

// Two vec4 a blade (api/src/dynamics/blade_state.hpp kBladeStateBytes): (v2, eta), (velocity, 0).
void blade_state_pack(BladeState s, out vec4 a, out vec4 b) {
    a = vec4(s.v2, s.eta);
    b = vec4(s.velocity, 0.0);
}

BladeState blade_state_unpack(vec4 a, vec4 b) {
    BladeState s;
    s.v2 = a.xyz;
    s.velocity = b.xyz;
    s.eta = a.w;
    return s;
}

// The spring's rest point: the equilibrium of recovery weakened to `recovery` (eq. 3)
// against `forces` (m/s^2), as blade_equilibrium computes it for full recovery, held within
// kBladeStateMaxDeflection lengths of I_v2.
vec3 blade_state_target(BladeRest rest, float stiffness, vec3 forces, float recovery) {
    vec3 deflection = rest.len * forces / (stiffness * recovery);
    float largest = max(max(abs(deflection.x), abs(deflection.y)), abs(deflection.z));
    float limit = kBladeStateMaxDeflection * rest.len;
    if (largest > limit) deflection *= limit / largest;
    return rest.i2 + deflection;
}

// Eq. 9 on the free tip: above the root's plane, and no velocity into it there.
void blade_state_keep_above(inout BladeState s, vec3 up) {
    float height = dot(up, s.v2);
    if (height < 0.0) {
        s.v2 -= up * height;
        s.velocity -= up * min(dot(up, s.velocity), 0.0);
    }
}

// The state equal to the stateless pose under `forces` (blade_equilibrium): at rest there,
// no collision strength. A blade entering the stepped window starts here.
BladeState blade_state_at_rest(BladeRest rest, float stiffness, vec3 forces) {
    BladeState s;
    s.v2 = rest.len > 0.0 ? blade_state_target(rest, max(stiffness, 1e-3), forces, 1.0) : rest.i2;
    s.velocity = vec3(0.0);
    s.eta = 0.0;
    blade_state_keep_above(s, rest.up);
    return s;
}

// The drawn pose of a state: its free tip validated (eq. 9, 11, 13).
BladePose blade_state_pose(BladeState s, BladeRest rest) {
    BladePose pose;
    pose.v1 = rest.i1;
    pose.v2 = s.v2;
    pose.shade = 1.0;
    if (rest.len > 0.0) validate_blade(pose, rest.i1, rest.i2, rest.up, rest.len, rest.len, rest.segments);
    return pose;
}

// e^(-alpha t) C(t) and e^(-alpha t) S(t) of the damped spring x'' + 2 alpha x' + omega2 x = 0,
// whose solution is x(t) = e^(-alpha t) (C x0 + S (u0 + alpha x0)): C = cos(beta t),
// S = sin(beta t) / beta with beta^2 = omega2 - alpha^2 (under-damped), or cosh and sinh /
// beta (over-damped, written without overflow). Exact for any t >= 0.
void blade_state_spring(float alpha, float omega2, float t, out float ec, out float es) {
    float d = omega2 - alpha * alpha;
    float e = exp(-alpha * t);
    float beta = sqrt(abs(d));
    if (beta * t < 1e-3) {
        ec = e;
        es = e * t;
    } else if (d > 0.0) {
        ec = e * cos(beta * t);
        es = e * sin(beta * t) / beta;
    } else {
        float grow = exp((beta - alpha) * t), fall = exp(-(beta + alpha) * t);
        ec = 0.5 * (grow + fall);
        es = 0.5 * (grow - fall) / beta;
    }
}

// Eq. 15: the translation that moves point p out of a collider (sphere or capsule) of
// radius r around the closest point q of its axis; zero outside. Under the axis: up.
vec3 blade_state_push_out(vec3 p, BladeCollider c, vec3 shift, vec3 up) {
    vec3 a = c.a.xyz + shift;
    vec3 q = a;
    if (c.b.w > 0.5) {
        vec3 axis = c.b.xyz + shift - a;
        float axis2 = dot(axis, axis);
        q = axis2 > 0.0 ? a + axis * clamp(dot(p - a, axis) / axis2, 0.0, 1.0) : a;
    }
    float r = c.a.w;
    vec3 away = p - q;
    float d = length(away);
    if (d >= r) return vec3(0.0);
    return (d > 1e-6 * r ? away / d : up) * (r - d);
}

// The push-out of a pose by collider c: its tip and its midpoint m (eq. 14; m's translation
// x 4 moves v2, as jahrmann2017 5.3 does).
vec3 blade_state_contact(BladePose pose, BladeCollider c, vec3 shift, vec3 up) {
    vec3 mid = 0.5 * pose.v1 + 0.25 * pose.v2;
    return blade_state_push_out(pose.v2, c, shift, up) + 4.0 * blade_state_push_out(mid, c, shift, up);
}

// One step of dt seconds (0..10) of a blade of rest pose `rest`, recovery `stiffness` (m/s^2,
// blade_mechanics) and collision strength decaying over `recovery_time` seconds, under
// `forces` (m/s^2, blade_forces: wind and gravity, constant over the step) and the colliders
// of blade_state_collider. In substeps of at most kBladeStateSubstep (at most
// kBladeStateMaxSubsteps of them, longer beyond 16 x that), each:
// - eta (eq. 2, 16 as rates): it rises by kBladeStateEtaBuild (d / L)^2 per second, d the
//   push-out the colliders give the stateless pose (how hard they hold the blade from its
//   equilibrium), and falls by 1 / recovery_time per second, within 0..1;
// - the spring (eq. 1, 3 with inertia): the tip accelerates by (s / L) recovery (target - v2)
//   - 2 zeta omega velocity, omega^2 = s / L, zeta = kBladeStateDamping, recovery =
//   max(1 - eta, 0.1) (eq. 3) with eta's mean over the substep, target =
//   blade_state_target; solved exactly over the substep;
// - eq. 9 on the free tip;
// - colliders (eq. 14-15) at their place at the substep's end push the validated pose's tip
//   and midpoint out; the free tip moves by that, and loses the velocity into the collider
//   (beyond the collider's own).
void blade_state_step(inout BladeState s, BladeRest rest, float stiffness, vec3 forces, float recovery_time,
                      float dt) {
    if (!(rest.len > 0.0) || !(dt > 0.0)) return;
    stiffness = max(stiffness, 1e-3);
    int n = int(clamp(ceil(dt / kBladeStateSubstep), 1.0, float(kBladeStateMaxSubsteps)));
    float h = dt / float(n);
    float omega2 = stiffness / rest.len;
    float alpha = kBladeStateDamping * sqrt(omega2);
    float decay = 1.0 / max(recovery_time, 1e-3);
    int colliders = blade_state_collider_count();
    BladePose at_rest = blade_equilibrium(rest.i1, rest.i2, rest.up, rest.len, stiffness, forces, rest.segments);
    float limit = kBladeStateMaxDeflection * rest.len;
    for (int step = 1; step <= n; ++step) {
        float before = dt - h * float(step); // the substep's end, seconds before the step's end
        // Eta first: its build depends on the stateless pose and the colliders only, so it
        // is the same at any substep; the spring takes its mean over the substep.
        float build = 0.0;
        for (int k = 0; k < colliders; ++k) {
            BladeCollider c = blade_state_collider(k);
            vec3 held = blade_state_contact(at_rest, c, -c.velocity.xyz * before, rest.up) / rest.len;
            build += kBladeStateEtaBuild * dot(held, held);
        }
        float eta = clamp(s.eta + (build - decay) * h, 0.0, 1.0);
        float recovery = max(1.0 - 0.5 * (s.eta + eta), kBladeStateMinRecovery);
        s.eta = eta;

        vec3 target = blade_state_target(rest, stiffness, forces, recovery);
        float ec, es;
        blade_state_spring(alpha, omega2 * recovery, h, ec, es);
        vec3 x = s.v2 - target;
        vec3 u = s.velocity;
        s.v2 = target + ec * x + es * (u + alpha * x);
        s.velocity = ec * u - es * (omega2 * recovery * x + alpha * u);
        blade_state_keep_above(s, rest.up);

        if (colliders > 0) {
            BladePose pose = blade_state_pose(s, rest);
            for (int k = 0; k < colliders; ++k) {
                BladeCollider c = blade_state_collider(k);
                vec3 d = blade_state_contact(pose, c, -c.velocity.xyz * before, rest.up);
                float d2 = dot(d, d);
                if (d2 > 0.0) {
                    vec3 normal = d * inversesqrt(d2);
                    s.v2 += d;
                    s.velocity -= normal * min(dot(s.velocity - c.velocity.xyz, normal), 0.0);
                }
            }
            s.v2 = rest.i2 + clamp(s.v2 - rest.i2, vec3(-limit), vec3(limit));
            blade_state_keep_above(s, rest.up);
        }
    }
}
