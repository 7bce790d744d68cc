#version 460
#extension GL_GOOGLE_include_directive : require
// Lane-serial digit histogram: one invocation counts one chunk of SORT_CHUNK keys into private
// counters and writes hist[digit * num_chunks + chunk] (digit-major, ready for one exclusive scan).
// Keys arrive as uvec4 texels (see sort.glsl); buffers are allocated in whole 16-byte texels.
#include "common.glsl"
#include "sort.glsl"

layout(binding = 0) uniform usamplerBuffer keys;
BUF_RW(1, uint, hist);
layout(push_constant) uniform Push { uint n; uint shift; uint num_chunks; } pc;

void main() {
    uint chunk = group_linear() * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (chunk >= pc.num_chunks) return;
    uint cnt[SORT_SERIAL_RADIX];
    for (uint d = 0u; d < SORT_SERIAL_RADIX; d++) cnt[d] = 0u;
    uint begin = chunk * SORT_CHUNK;
    uint end = min(pc.n, begin + SORT_CHUNK);
    for (uint i = begin; i < end; i += 4u) {
        uvec4 d = (texelFetch(keys, int(i >> 2u)) >> pc.shift) & (SORT_SERIAL_RADIX - 1u);
        cnt[d.x]++;
        if (i + 1u < end) cnt[d.y]++;
        if (i + 2u < end) cnt[d.z]++;
        if (i + 3u < end) cnt[d.w]++;
    }
    for (uint d = 0u; d < SORT_SERIAL_RADIX; d++) hist.data[d * pc.num_chunks + chunk] = cnt[d];
}
