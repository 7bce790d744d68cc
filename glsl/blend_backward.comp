#version 460
#extension GL_GOOGLE_include_directive : require
// Backward of the alpha blend for one segment (seg_len splats) of every tile's list: one
// workgroup per 16x16 tile, PIXELS_PER_INVOCATION pixels per invocation, splats broadcast by
// subgroupShuffle as in the forward. Each pixel walks front to back again (same decisions as the forward, bounded by
// its last contributor) and needs no division by T: with C_full the final colour (background
// included) and C_j the colour up to and including splat j,
//     dC/dalpha_j = T_j c_j - (C_full - C_j) / (1 - alpha_j).
// A splat's nine screen-space gradients are summed over the subgroup's pixels (subgroupAdd) and
// added to its per-Gaussian slot with one float atomic per value, spread over the first 8 lanes.
// Running colour and T carry over to the next segment through `state`. Segments are SEGMENT
// splats long, or SEGMENT_CAS where atomics are compare-and-swap loops, whose iterations count
// against lavapipe's loop limit too.
#extension GL_EXT_control_flow_attributes : require
#include "common.glsl"
#include "raster.glsl"

// Read through uvec4 texel buffers: on lavapipe a texel fetch is one vector gather, where a
// lane-varying storage-buffer load is a scalar loop over the lanes.
layout(binding = 0) uniform usamplerBuffer proj;       // PROJ_STRIDE / 4 texels per splat
layout(binding = 1) uniform usamplerBuffer isect_ids;  // four ids per texel
BUF_RO(2, uvec2, ranges);
BUF_RO(3, vec4, color);       // forward: rgb without background, final T
BUF_RO(4, uint, last);        // forward: one past the last contributor; bit 31 = done
BUF_RO(5, vec4, grad_color);  // dL/d(pixel colour over the background), rgb
BUF_RW(6, vec4, state);       // running colour and T between segments
BUF_RW(7, ATOMIC_FLOAT, grad2d); // per Gaussian: d xy (2), d conic (3), d opacity, d rgb (3)
layout(push_constant) uniform Push { uint width; uint height; uint tiles_x; uint seg_begin; uint seg_len; uint first;
                                     float bg_r; float bg_g; float bg_b; } pc;

const uint K = PIXELS_PER_INVOCATION;  // 1, or BLEND_PIXELS when built with WIDE_PIXELS
const uint STRIDE = TILE * TILE / K;

void main() {
    uint tile = group_linear();
    uint t = gl_LocalInvocationID.x;
    uint tx = tile % pc.tiles_x, ty = tile / pc.tiles_x;
    uvec2 range = ranges.data[tile];
    uint begin = range.x + pc.seg_begin;
    uint end = min(range.y, begin + pc.seg_len);
    uint n = begin < end ? end - begin : 0u;
    // Tile-relative index of this segment's first splat; pixels are done past their last contributor.
    uint rel0 = pc.seg_begin;

    vec3 full[K], gc[K], run[K];
    float T[K];
    uint lastc[K], pix[K];
    bool done[K], inside[K];
    vec2 pf[K];
    [[unroll]] for (uint k = 0u; k < K; k++) {
        uint l = t + k * STRIDE;
        uint px = tx * TILE + (l % TILE), py = ty * TILE + (l / TILE);
        inside[k] = px < pc.width && py < pc.height;
        pix[k] = py * pc.width + px;
        pf[k] = vec2(px, py) + 0.5;
        full[k] = vec3(0.0); gc[k] = vec3(0.0); run[k] = vec3(0.0); T[k] = 1.0; lastc[k] = 0u;
        if (inside[k]) {
            vec4 c = color.data[pix[k]];
            full[k] = c.rgb + c.a * vec3(pc.bg_r, pc.bg_g, pc.bg_b);
            gc[k] = grad_color.data[pix[k]].rgb;
            lastc[k] = last.data[pix[k]] & 0x7fffffffu;
            if (pc.first == 0u) { vec4 st = state.data[pix[k]]; run[k] = st.rgb; T[k] = st.a; }
        }
        done[k] = !inside[k] || rel0 >= lastc[k];
    }
    uint sg = gl_SubgroupSize;
    uint lane = gl_SubgroupInvocationID;
    for (uint b = 0u; b < n; b += sg) {
        bool all_done = true;
        [[unroll]] for (uint k = 0u; k < K; k++) all_done = all_done && done[k];
        if (subgroupAll(all_done)) break;
        vec4 p0 = vec4(0.0), p1 = vec4(0.0), p2 = vec4(0.0);
        uint gid = 0u;
        if (b + lane < n) {
            gid = fetch_u32(isect_ids, begin + b + lane);
            p0 = uintBitsToFloat(texelFetch(proj, int(3u * gid)));
            p1 = uintBitsToFloat(texelFetch(proj, int(3u * gid + 1u)));
            p2 = uintBitsToFloat(texelFetch(proj, int(3u * gid + 2u)));
        }
        uint cnt = min(sg, n - b);
        for (uint j = 0u; j < cnt; j++) {
            vec4 q0 = subgroupShuffle(p0, j);
            vec4 q1 = subgroupShuffle(p1, j);
            vec3 q2 = subgroupShuffle(p2.xyz, j);
            uint g = subgroupShuffle(gid, j);
            // This invocation's pixels' gradients with respect to the splat, summed.
            vec4 v0 = vec4(0.0), v1 = vec4(0.0);
            float v2 = 0.0;
            bool contrib = false;
            [[unroll]] for (uint k = 0u; k < K; k++) {
                if (!done[k] && rel0 + b + j >= lastc[k]) done[k] = true;
                if (!done[k]) {
                    vec2 d = q0.xy - pf[k];
                    float power = -0.5 * (q1.x * d.x * d.x + q1.z * d.y * d.y) - q1.y * d.x * d.y;
                    float gauss = exp(power);
                    float raw = q0.w * gauss;
                    float alpha = min(ALPHA_MAX, raw);
                    float nextT = T[k] * (1.0 - alpha);
                    if (power <= 0.0 && alpha >= ALPHA_MIN) {
                        if (nextT < T_MIN) {
                            done[k] = true;
                        } else {
                            contrib = true;
                            float w = alpha * T[k];
                            run[k] += q2 * w;
                            vec3 behind = (full[k] - run[k]) / (1.0 - alpha);
                            float dalpha = dot(gc[k], q2 * T[k] - behind);
                            vec3 grgb = gc[k] * w;
                            float dopa = 0.0, dpow = 0.0;
                            if (raw <= ALPHA_MAX) { dopa = dalpha * gauss; dpow = dalpha * alpha; }
                            vec2 dxy = -dpow * vec2(q1.x * d.x + q1.y * d.y, q1.z * d.y + q1.y * d.x);
                            v0 += vec4(dxy, -0.5 * dpow * d.x * d.x, -dpow * d.x * d.y);
                            v1 += vec4(-0.5 * dpow * d.y * d.y, dopa, grgb.rg);
                            v2 += grgb.b;
                            T[k] = nextT;
                        }
                    }
                }
            }
            if (subgroupAny(contrib)) {
                vec4 s0 = subgroupAdd(v0);
                vec4 s1 = subgroupAdd(v1);
                float s2 = subgroupAdd(v2);
                uint o = 9u * g;
                if (MIN_SUBGROUP_SIZE >= 8u) {
                    // Lane k adds value k (lane 0 also the ninth): two atomics per lane instead of
                    // nine from one elected lane; on lavapipe that is 2 lane loops instead of 9.
                    float mine = lane == 0u ? s0.x : lane == 1u ? s0.y : lane == 2u ? s0.z : lane == 3u ? s0.w
                               : lane == 4u ? s1.x : lane == 5u ? s1.y : lane == 6u ? s1.z : s1.w;
                    if (lane < 8u) FLOAT_ATOMIC_ADD(grad2d, o + lane, mine);
                    if (lane == 0u) FLOAT_ATOMIC_ADD(grad2d, o + 8u, s2);
                } else if (subgroupElect()) {
                    FLOAT_ATOMIC_ADD(grad2d, o, s0.x);
                    FLOAT_ATOMIC_ADD(grad2d, o + 1u, s0.y);
                    FLOAT_ATOMIC_ADD(grad2d, o + 2u, s0.z);
                    FLOAT_ATOMIC_ADD(grad2d, o + 3u, s0.w);
                    FLOAT_ATOMIC_ADD(grad2d, o + 4u, s1.x);
                    FLOAT_ATOMIC_ADD(grad2d, o + 5u, s1.y);
                    FLOAT_ATOMIC_ADD(grad2d, o + 6u, s1.z);
                    FLOAT_ATOMIC_ADD(grad2d, o + 7u, s1.w);
                    FLOAT_ATOMIC_ADD(grad2d, o + 8u, s2);
                }
            }
        }
    }
    [[unroll]] for (uint k = 0u; k < K; k++) {
        if (inside[k]) state.data[pix[k]] = vec4(run[k], T[k]);
    }
}
