// Bakay's length-preserving bend (bakay2003 3.3) applied to the slice lookups of the volume
// and image tiers, driven by the same wind and press as the blades. A column of rest height
// H bent with angle a = I pi / 2 along d has, at rest fraction u of its height, horizontal
// offset x(u) = H (1 - cos(a u)) / a and height y(u) = H sin(a u) / a: every segment keeps
// its length, the tip at angle a / 2 from the vertical. Bakay's intensity I runs to 1 (the
// tip at 45 degrees); lying grass needs up to 2 (a = pi: the column curls onto the ground).
// Included after wind.glsl and interaction.glsl; used only by variants with GRASS_WIND or
// GRASS_INTERACTION.

const float kMaxBend = 3.08; // a < pi: the tip keeps a little height

struct ShellBend {
    float angle; // a (radians); 0: upright
    vec3 dir;    // world direction of the bend across up (unit, or zero)
    float shade; // press darkening (press_shade)
};

// The tip height over H of a column bent by a: sin(a) / a.
float bend_height(float a) { return a < 1e-4 ? 1.0 : sin(a) / a; }

// The a with sin(a) / a = r, r in (0, 1] (Newton from the series 1 - a^2 / 6).
float bend_for_height(float r) {
    r = clamp(r, 0.0, 1.0);
    float a = min(sqrt(6.0 * (1.0 - r)), kMaxBend);
    for (int i = 0; i < 5; ++i) {
        float f = bend_height(a) - r;
        float df = a < 1e-4 ? -a / 3.0 : (a * cos(a) - sin(a)) / (a * a);
        if (abs(df) < 1e-6) break;
        a = clamp(a - f / df, 0.0, kMaxBend);
    }
    return a;
}

// The bend of the slices' grass (height `height_m`, metres) over camera-relative ground
// point p (the field's point `cell_point`, in cells). Wind: the tip deflection a blade as
// tall would have in blade_dynamics.glsl (the equilibrium of the mean mechanics, an
// upright blade across the wind): its tip at angle phi from the vertical is a column bent
// by a = 2 phi. Press: the a whose tip height y(1) is the cap. The larger bend wins, with its direction.
ShellBend shell_bend(vec3 p, vec3 up, float height_m, vec2 cell_point) {
    ShellBend b;
    b.angle = 0.0;
    b.dir = vec3(0.0);
    b.shade = 1.0;
    if (has_map(GRASS_WIND)) {
        vec3 a = field.mechanics.z * wind_at(p, up, cell_point) + field.mechanics.y * frame.gravity.xyz;
        vec3 across = a - up * dot(a, up);
        float s = max(field.mechanics.x, 1e-3);
        float lateral = length(across) / s;
        float upright = max(1.0 + dot(a, up) / s, 0.0); // eq. 9: never below the ground
        if (lateral > 0.0) {
            b.angle = min(2.0 * atan(lateral, upright), kMaxBend);
            b.dir = across / length(across);
        }
    }
    if (has_map(GRASS_INTERACTION)) {
        float cap;
        vec3 d;
        if (interaction_press(p, height_m, field.trample.x, field.trample.y, cap, d)) {
            float a = bend_for_height(cap / height_m);
            if (a > b.angle) {
                b.angle = a;
                d -= up * dot(d, up);
                b.dir = dot(d, d) > 1e-12 ? normalize(d) : b.dir;
            }
            b.shade = press_shade(cap / height_m);
        }
    }
    return b;
}

// The rest point of a bent column seen at height y (patch units above the ground, column
// height h): its rest height u h and the offset back to its root along the bend's direction
// (patch units). False above the bent column.
bool shell_unbend(float a, float y, float h, out float rest_y, out float back) {
    rest_y = y;
    back = 0.0;
    if (a < 1e-4) return y <= h;
    float s = y * a / h;
    if (s > 1.0) return false;
    float u = asin(s) / a;
    if (u > 1.0) return false;
    rest_y = u * h;
    back = h * (1.0 - cos(a * u)) / a;
    return true;
}
