#version 460
#extension GL_GOOGLE_include_directive : require
// Front-to-back alpha blending of one segment (SEGMENT splats) of every tile's depth-sorted list;
// one workgroup per 16x16 tile, one pixel per invocation. Splats are loaded one per lane and
// broadcast with subgroupShuffle (3.6x faster than shared-memory staging on lavapipe). Pixel
// state (colour, T, depth, last contributor, done) carries over to the next segment's dispatch,
// which keeps each invocation far below lavapipe's 65,535-iteration loop limit.
#include "common.glsl"
#include "raster.glsl"

// Read through uvec4 texel buffers: on lavapipe a texel fetch is one vector gather, where a
// lane-varying storage-buffer load is a scalar loop over the lanes.
layout(binding = 0) uniform usamplerBuffer proj;       // PROJ_STRIDE / 4 texels per splat
layout(binding = 1) uniform usamplerBuffer isect_ids;  // four ids per texel
BUF_RO(2, uvec2, ranges);
BUF_RW(3, vec4, color);    // rgb without background, T
BUF_RW(4, float, depth);   // sum z * alpha * T
BUF_RW(5, uint, last);     // one past the last contributing list index (tile-relative); bit 31 = done
layout(push_constant) uniform Push { uint width; uint height; uint tiles_x; uint seg_begin; uint first; } pc;

void main() {
    uint tile = group_linear();
    uint t = gl_LocalInvocationID.x;
    uint tx = tile % pc.tiles_x, ty = tile / pc.tiles_x;
    uint px = tx * TILE + (t % TILE), py = ty * TILE + (t / TILE);
    bool inside = px < pc.width && py < pc.height;
    uint pix = py * pc.width + px;
    vec2 pf = vec2(px, py) + 0.5;

    vec3 C = vec3(0.0);
    float T = 1.0;
    float D = 0.0;
    uint lastc = 0u;
    bool done = !inside;
    if (inside && pc.first == 0u) {
        vec4 c = color.data[pix];
        C = c.rgb; T = c.a; D = depth.data[pix];
        uint l = last.data[pix];
        done = (l & 0x80000000u) != 0u;
        lastc = l & 0x7fffffffu;
    }
    uvec2 range = ranges.data[tile];
    uint begin = range.x + pc.seg_begin;
    uint end = min(range.y, begin + SEGMENT);
    uint n = begin < end ? end - begin : 0u;
    uint sg = gl_SubgroupSize;
    uint lane = gl_SubgroupInvocationID;
    for (uint b = 0u; b < n; b += sg) {
        if (subgroupAll(done)) break;
        vec4 p0 = vec4(0.0), p1 = vec4(0.0), p2 = vec4(0.0);
        if (b + lane < n) {
            uint g = fetch_u32(isect_ids, begin + b + lane);
            p0 = uintBitsToFloat(texelFetch(proj, int(3u * g)));
            p1 = uintBitsToFloat(texelFetch(proj, int(3u * g + 1u)));
            p2 = uintBitsToFloat(texelFetch(proj, int(3u * g + 2u)));
        }
        uint cnt = min(sg, n - b);
        for (uint j = 0u; j < cnt; j++) {
            vec4 q0 = subgroupShuffle(p0, j);
            vec4 q1 = subgroupShuffle(p1, j);
            vec3 q2 = subgroupShuffle(p2.xyz, j);
            if (done) continue;
            vec2 d = q0.xy - pf;
            float power = -0.5 * (q1.x * d.x * d.x + q1.z * d.y * d.y) - q1.y * d.x * d.y;
            if (power > 0.0) continue;
            float alpha = min(ALPHA_MAX, q0.w * exp(power));
            if (alpha < ALPHA_MIN) continue;
            float nextT = T * (1.0 - alpha);
            if (nextT < T_MIN) { done = true; continue; }
            float w = alpha * T;
            C += q2 * w;
            D += q0.z * w;
            T = nextT;
            lastc = begin + b + j + 1u - range.x;
        }
    }
    if (inside) {
        color.data[pix] = vec4(C, T);
        depth.data[pix] = D;
        last.data[pix] = lastc | (done ? 0x80000000u : 0u);
    }
}
