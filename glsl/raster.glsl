// Rasterizer constants (INRIA 3DGS semantics), mirrored to Rust by build.rs.
const uint TILE = 16u; // export
const float NEAR_PLANE = 0.2; // export
const float COV_BLUR = 0.3; // export
const float ALPHA_MAX = 0.99; // export
const float ALPHA_MIN = 0.003921568627451; // export
const float T_MIN = 0.0001; // export
// Tiles are kept when the splat's power at the nearest pixel centre is within its alpha cutoff
// plus this margin, so f32 rounding never drops a tile that a pixel would use.
const float CULL_MARGIN = 0.01; // export
// Pixels each invocation of the `_wide` blend kernels handles (a workgroup is then
// TILE * TILE / BLEND_PIXELS invocations). On lavapipe every splat broadcast and every subgroup
// reduction is a loop over the lanes, so sharing them among 8 pixels makes the forward blend
// 1.8x and its backward 2.3x faster; GPUs keep one pixel per invocation for occupancy.
const uint BLEND_PIXELS = 8u; // export
#ifdef WIDE_PIXELS
const uint PIXELS_PER_INVOCATION = BLEND_PIXELS;
#else
const uint PIXELS_PER_INVOCATION = 1u;
#endif
// Splats of one tile blended per dispatch: lavapipe cuts every invocation after 65,535 loop
// iterations, and the blend loop makes about SEGMENT * (1 + 1/subgroup) of them.
const uint SEGMENT = 16384u; // export
// The same for the blend backward built with CAS atomics (nine CAS loops per splat per subgroup).
const uint SEGMENT_CAS = 2048u; // export
// Floats per projected splat: (x, y, depth, opacity), (conic a, b, c, radius), (r, g, b, 0).
const uint PROJ_STRIDE = 12u; // export

// Camera for projection kernels: world-to-camera rows with translation in w.
struct CameraData {
    vec4 row0;
    vec4 row1;
    vec4 row2;
    vec4 campos;   // xyz; w unused
    vec2 focal;
    vec2 size;     // width, height in pixels
};

bool finite_f(float x) { return (floatBitsToUint(x) & 0x7f800000u) != 0x7f800000u; }

// Minimum over the box [lo, hi] of a dx^2 + 2 b dx dy + c dy^2 (a, c > 0), as the CPU reference.
float box_min_quadratic(vec3 con, vec2 lo, vec2 hi) {
    if (lo.x <= 0.0 && hi.x >= 0.0 && lo.y <= 0.0 && hi.y >= 0.0) return 0.0;
    precise float best = 3.0e38;
    for (int e = 0; e < 2; e++) {
        precise float dx = e == 0 ? lo.x : hi.x;
        precise float dy = clamp(-con.y * dx / con.z, lo.y, hi.y);
        best = min(best, con.x * dx * dx + 2.0 * con.y * dx * dy + con.z * dy * dy);
        precise float ey = e == 0 ? lo.y : hi.y;
        precise float ex = clamp(-con.y * ey / con.x, lo.x, hi.x);
        best = min(best, con.x * ex * ex + 2.0 * con.y * ex * ey + con.z * ey * ey);
    }
    return best;
}

// Whether a splat reaches alpha >= 1/255 (plus CULL_MARGIN) at a pixel centre of tile (tx, ty).
bool tile_touched(vec2 xy, vec3 con, float opacity, uint tx, uint ty) {
    precise float thr = log(opacity / ALPHA_MIN) + CULL_MARGIN;
    if (thr < 0.0) return false;
    precise vec2 lo = vec2(float(tx * TILE) + 0.5, float(ty * TILE) + 0.5) - xy;
    precise vec2 hi = lo + vec2(float(TILE) - 1.0);
    return 0.5 * box_min_quadratic(con, lo, hi) <= thr;
}

uvec4 unpack_rect(uvec2 r) { return uvec4(r.x & 0xffffu, r.x >> 16, r.y & 0xffffu, r.y >> 16); }
