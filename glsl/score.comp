#version 460
#extension GL_GOOGLE_include_directive : require
// The 3D Gaussian filtering score, accumulated over the (pixel, Gaussian) pairs that contribute
// to one view under the forward pass's rules (power <= 0, alpha >= 1/255, T stays >= T_MIN):
//   mode 0, the authors' code:   score[g] += 1 / z_g^2
//   mode 1, paper, first pass:   pixel max volume  maxV(r) = max V(g) over contributing g
//   mode 2, paper, second pass:  score[g] += V(g) / (z_g^2 * maxV(r))
// Tiles are walked in segments like the blend (lavapipe's loop limit); per-pixel state carries over.
// Each splat's contributions are summed over the subgroup before one atomic add.
#include "common.glsl"
#include "raster.glsl"

BUF_RO(0, vec4, proj);
BUF_RO(1, uint, isect_ids);
BUF_RO(2, uvec2, ranges);
BUF_RO(3, float, scales);
BUF_RW(4, vec4, pstate);         // per pixel: T, done, maxV, unused
BUF_RW(5, ATOMIC_FLOAT, score);
layout(push_constant) uniform Push { uint width; uint height; uint tiles_x; uint seg_begin; uint first; uint mode; } pc;

float volume(uint g) {
    return exp(scales.data[3u * g] + scales.data[3u * g + 1u] + scales.data[3u * g + 2u]);
}

void main() {
    uint tile = group_linear();
    uint t = gl_LocalInvocationID.x;
    uint tx = tile % pc.tiles_x, ty = tile / pc.tiles_x;
    uint px = tx * TILE + (t % TILE), py = ty * TILE + (t / TILE);
    bool inside = px < pc.width && py < pc.height;
    uint pix = py * pc.width + px;
    vec2 pf = vec2(px, py) + 0.5;
    float T = 1.0;
    bool done = !inside;
    float maxv = 0.0;
    if (inside) {
        vec4 st = pstate.data[pix];
        if (pc.first == 0u) { T = st.x; done = st.y != 0.0; }
        maxv = st.z;   // from the mode-1 pass (mode 2), or the running max (mode 1)
        if (pc.first != 0u && pc.mode == 1u) maxv = 0.0;
    }
    uvec2 range = ranges.data[tile];
    uint begin = range.x + pc.seg_begin;
    uint end = min(range.y, begin + SEGMENT);
    uint n = begin < end ? end - begin : 0u;
    uint sg = gl_SubgroupSize;
    uint lane = gl_SubgroupInvocationID;
    for (uint b = 0u; b < n; b += sg) {
        if (subgroupAll(done)) break;
        vec4 p0 = vec4(0.0), p1 = vec4(0.0);
        uint gid = 0u;
        float vol = 0.0;
        if (b + lane < n) {
            gid = isect_ids.data[begin + b + lane];
            p0 = proj.data[3u * gid]; p1 = proj.data[3u * gid + 1u];
            vol = pc.mode == 0u ? 0.0 : volume(gid);
        }
        uint cnt = min(sg, n - b);
        for (uint j = 0u; j < cnt; j++) {
            vec4 q0 = subgroupShuffle(p0, j);
            vec4 q1 = subgroupShuffle(p1, j);
            uint g = subgroupShuffle(gid, j);
            float v = subgroupShuffle(vol, j);
            float w = 0.0;
            if (!done) {
                vec2 d = q0.xy - pf;
                float power = -0.5 * (q1.x * d.x * d.x + q1.z * d.y * d.y) - q1.y * d.x * d.y;
                float alpha = min(ALPHA_MAX, q0.w * exp(power));
                if (power <= 0.0 && alpha >= ALPHA_MIN) {
                    float nextT = T * (1.0 - alpha);
                    if (nextT < T_MIN) {
                        done = true;
                    } else {
                        T = nextT;
                        float inv_z2 = 1.0 / (q0.z * q0.z);
                        if (pc.mode == 0u) w = inv_z2;
                        else if (pc.mode == 1u) maxv = max(maxv, v);
                        else w = v * inv_z2 / maxv;
                    }
                }
            }
            if (pc.mode != 1u) {
                float total = subgroupAdd(w);
                if (subgroupElect() && total != 0.0) FLOAT_ATOMIC_ADD(score, g, total);
            }
        }
    }
    if (inside) pstate.data[pix] = vec4(T, done ? 1.0 : 0.0, maxv, 0.0);
}
