#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
// Front-to-back alpha blending of one segment (SEGMENT splats) of every tile's depth-sorted list;
// one workgroup per 16x16 tile. Each invocation blends PIXELS_PER_INVOCATION pixels of the tile
// (local pixels t + k * STRIDE), so in the `_wide` build every splat broadcast (subgroupShuffle,
// 3.6x faster than shared-memory staging on lavapipe) serves several pixels. Pixel state (colour, T,
// depth, last contributor, done) carries over to the next segment's dispatch, which keeps each
// invocation far below lavapipe's 65,535-iteration loop limit.
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

const uint K = PIXELS_PER_INVOCATION;  // 1, or BLEND_PIXELS when built with WIDE_PIXELS
const uint STRIDE = TILE * TILE / K;

void main() {
    uint tile = group_linear();
    uint t = gl_LocalInvocationID.x;
    uint tx = tile % pc.tiles_x, ty = tile / pc.tiles_x;

    vec3 C[K];
    float T[K], D[K];
    uint lastc[K], pix[K];
    bool done[K], inside[K];
    vec2 pf[K];
    [[unroll]] for (uint k = 0u; k < K; k++) {
        uint l = t + k * STRIDE;
        uint px = tx * TILE + (l % TILE), py = ty * TILE + (l / TILE);
        inside[k] = px < pc.width && py < pc.height;
        pix[k] = py * pc.width + px;
        pf[k] = vec2(px, py) + 0.5;
        C[k] = vec3(0.0); T[k] = 1.0; D[k] = 0.0; lastc[k] = 0u;
        done[k] = !inside[k];
        if (inside[k] && pc.first == 0u) {
            vec4 c = color.data[pix[k]];
            C[k] = c.rgb; T[k] = c.a; D[k] = depth.data[pix[k]];
            uint last_word = last.data[pix[k]];
            done[k] = (last_word & 0x80000000u) != 0u;
            lastc[k] = last_word & 0x7fffffffu;
        }
    }
    uvec2 range = ranges.data[tile];
    uint begin = range.x + pc.seg_begin;
    uint end = min(range.y, begin + SEGMENT);
    uint n = begin < end ? end - begin : 0u;
    uint sg = gl_SubgroupSize;
    uint lane = gl_SubgroupInvocationID;
    for (uint b = 0u; b < n; b += sg) {
        bool all_done = true;
        [[unroll]] for (uint k = 0u; k < K; k++) all_done = all_done && done[k];
        if (subgroupAll(all_done)) break;
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
            [[unroll]] for (uint k = 0u; k < K; k++) {
                vec2 d = q0.xy - pf[k];
                float power = -0.5 * (q1.x * d.x * d.x + q1.z * d.y * d.y) - q1.y * d.x * d.y;
                float alpha = min(ALPHA_MAX, q0.w * exp(power));
                if (!done[k] && power <= 0.0 && alpha >= ALPHA_MIN) {
                    float nextT = T[k] * (1.0 - alpha);
                    if (nextT < T_MIN) {
                        done[k] = true;
                    } else {
                        float w = alpha * T[k];
                        C[k] += q2 * w;
                        D[k] += q0.z * w;
                        T[k] = nextT;
                        lastc[k] = begin + b + j + 1u - range.x;
                    }
                }
            }
        }
    }
    [[unroll]] for (uint k = 0u; k < K; k++) {
        if (inside[k]) {
            color.data[pix[k]] = vec4(C[k], T[k]);
            depth.data[pix[k]] = D[k];
            last.data[pix[k]] = lastc[k] | (done[k] ? 0x80000000u : 0u);
        }
    }
}
