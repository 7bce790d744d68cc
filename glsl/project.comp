#version 460
#extension GL_GOOGLE_include_directive : require
// Projects each Gaussian (EWA, INRIA conventions), evaluates its SH colour, and counts the tiles
// its alpha cutoff reaches. Culled Gaussians get count 0 and depth key 0xffffffff.
#include "common.glsl"
#include "raster.glsl"

BUF_RO(0, float, means);
BUF_RO(1, float, scales);
BUF_RO(2, vec4, rotations);
BUF_RO(3, float, opacities);
BUF_RO(4, float, sh);
BUF_RW(5, vec4, proj);
BUF_RW(6, uvec2, rects);
BUF_RW(7, uint, depth_keys);
BUF_RW(8, uint, ids);
BUF_RW(9, uint, counts);
layout(push_constant) uniform Push { CameraData cam; uint n; uint sh_degree; uint tiles_x; uint tiles_y; } pc;

const float SH_C0 = 0.28209479177387814;
const float SH_C1 = 0.4886025119029199;
const float SH_C2[5] = float[](1.0925484305920792, -1.0925484305920792, 0.31539156525252005, -1.0925484305920792, 0.5462742152960396);
const float SH_C3[7] = float[](-0.5900435899266435, 2.890611442640554, -0.4570457994644658, 0.3731763325901154,
                               -0.4570457994644658, 1.445305721320277, -0.5900435899266435);

void cull(uint i) {
    proj.data[3u * i] = vec4(0.0);
    proj.data[3u * i + 1u] = vec4(0.0);
    proj.data[3u * i + 2u] = vec4(0.0);
    rects.data[i] = uvec2(0u);
    depth_keys.data[i] = 0xffffffffu;
    counts.data[i] = 0u;
}

vec3 sh_color(uint i, vec3 d) {
    uint k = (pc.sh_degree + 1u) * (pc.sh_degree + 1u);
    uint base = i * k * 3u;
#define C(j) vec3(sh.data[base + 3u * (j)], sh.data[base + 3u * (j) + 1u], sh.data[base + 3u * (j) + 2u])
    vec3 c = SH_C0 * C(0u);
    if (pc.sh_degree >= 1u) {
        float x = d.x, y = d.y, z = d.z;
        c += -SH_C1 * y * C(1u) + SH_C1 * z * C(2u) - SH_C1 * x * C(3u);
        if (pc.sh_degree >= 2u) {
            float xx = x * x, yy = y * y, zz = z * z;
            c += SH_C2[0] * x * y * C(4u) + SH_C2[1] * y * z * C(5u) + SH_C2[2] * (2.0 * zz - xx - yy) * C(6u)
               + SH_C2[3] * x * z * C(7u) + SH_C2[4] * (xx - yy) * C(8u);
            if (pc.sh_degree >= 3u) {
                c += SH_C3[0] * y * (3.0 * xx - yy) * C(9u) + SH_C3[1] * x * y * z * C(10u)
                   + SH_C3[2] * y * (4.0 * zz - xx - yy) * C(11u) + SH_C3[3] * z * (2.0 * zz - 3.0 * xx - 3.0 * yy) * C(12u)
                   + SH_C3[4] * x * (4.0 * zz - xx - yy) * C(13u) + SH_C3[5] * z * (xx - yy) * C(14u)
                   + SH_C3[6] * x * (xx - 3.0 * yy) * C(15u);
            }
        }
    }
#undef C
    return c;
}

void main() {
    uint i = group_linear() * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (i >= pc.n) return;
    ids.data[i] = i;
    vec3 m = vec3(means.data[3u * i], means.data[3u * i + 1u], means.data[3u * i + 2u]);
    vec3 ls = vec3(scales.data[3u * i], scales.data[3u * i + 1u], scales.data[3u * i + 2u]);
    vec4 q = rotations.data[i];
    float ol = opacities.data[i];
    bool ok = finite_f(m.x) && finite_f(m.y) && finite_f(m.z) && finite_f(ls.x) && finite_f(ls.y) && finite_f(ls.z)
        && finite_f(q.x) && finite_f(q.y) && finite_f(q.z) && finite_f(q.w) && finite_f(ol);
    if (!ok) { cull(i); return; }
    vec3 p = vec3(dot(pc.cam.row0.xyz, m) + pc.cam.row0.w, dot(pc.cam.row1.xyz, m) + pc.cam.row1.w, dot(pc.cam.row2.xyz, m) + pc.cam.row2.w);
    if (!(p.z > NEAR_PLANE)) { cull(i); return; }
    float qn = length(q);
    if (!(qn > 0.0) || !finite_f(qn)) { cull(i); return; }
    q /= qn;
    float r = q.x, x = q.y, y = q.z, z = q.w;
    // The rotation matrix (GLSL constructors take columns).
    mat3 R = mat3(1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y + r * z), 2.0 * (x * z - r * y),
                  2.0 * (x * y - r * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z + r * x),
                  2.0 * (x * z + r * y), 2.0 * (y * z - r * x), 1.0 - 2.0 * (x * x + y * y));
    vec3 s = exp(ls);
    if (!(finite_f(s.x) && finite_f(s.y) && finite_f(s.z))) { cull(i); return; }
    mat3 M = R * mat3(s.x * s.x, 0.0, 0.0, 0.0, s.y * s.y, 0.0, 0.0, 0.0, s.z * s.z);
    mat3 Sigma = M * transpose(R);
    vec2 lim = 1.3 * 0.5 * pc.cam.size / pc.cam.focal;
    float tx = clamp(p.x / p.z, -lim.x, lim.x) * p.z;
    float ty = clamp(p.y / p.z, -lim.y, lim.y) * p.z;
    float zz = p.z * p.z;
    // J * W as two row vectors.
    mat3 W = transpose(mat3(pc.cam.row0.xyz, pc.cam.row1.xyz, pc.cam.row2.xyz)); // columns = rows of world-to-camera
    vec3 j0 = vec3(pc.cam.focal.x / p.z, 0.0, -pc.cam.focal.x * tx / zz);
    vec3 j1 = vec3(0.0, pc.cam.focal.y / p.z, -pc.cam.focal.y * ty / zz);
    vec3 t0 = j0 * W;   // row vector times matrix
    vec3 t1 = j1 * W;
    vec3 st0 = Sigma * t0;
    vec3 st1 = Sigma * t1;
    float a = dot(t0, st0) + COV_BLUR;
    float b = dot(t0, st1);
    float c = dot(t1, st1) + COV_BLUR;
    float det = a * c - b * b;
    if (!(det > 0.0) || !finite_f(det)) { cull(i); return; }
    vec3 conic = vec3(c / det, -b / det, a / det);
    vec2 xy = pc.cam.focal * p.xy / p.z + 0.5 * pc.cam.size;
    float mid = 0.5 * (a + c);
    float lam = mid + sqrt(max(0.1, mid * mid - det));
    float radius = ceil(3.0 * sqrt(lam));
    float opacity = 1.0 / (1.0 + exp(-ol));
    vec3 dir = normalize(m - pc.cam.campos.xyz);
    vec3 rgb = sh_color(i, dir) + 0.5;
    if (!(finite_f(rgb.x) && finite_f(rgb.y) && finite_f(rgb.z) && finite_f(conic.x) && finite_f(conic.y) && finite_f(conic.z)
          && finite_f(xy.x) && finite_f(xy.y) && finite_f(radius))) { cull(i); return; }
    rgb = max(rgb, vec3(0.0));
    vec2 pp = xy - 0.5;
    vec2 grid = vec2(pc.tiles_x, pc.tiles_y);
    uvec2 rmin = uvec2(clamp(floor((pp - radius) / float(TILE)), vec2(0.0), grid));
    uvec2 rmax = uvec2(clamp(floor((pp + radius + float(TILE) - 1.0) / float(TILE)), vec2(0.0), grid));
    uint count = 0u;
    // Bounded by the tile grid (at most 65,535 tiles a side is far beyond any image here).
    for (uint ty_ = rmin.y; ty_ < rmax.y; ty_++)
        for (uint tx_ = rmin.x; tx_ < rmax.x; tx_++)
            if (tile_touched(xy, conic, opacity, tx_, ty_)) count++;
    if (count == 0u) { cull(i); return; }
    proj.data[3u * i] = vec4(xy, p.z, opacity);
    proj.data[3u * i + 1u] = vec4(conic, radius);
    proj.data[3u * i + 2u] = vec4(rgb, 0.0);
    rects.data[i] = uvec2(rmin.x | (rmin.y << 16), rmax.x | (rmax.y << 16));
    depth_keys.data[i] = floatBitsToUint(p.z);
    counts.data[i] = count;
}
