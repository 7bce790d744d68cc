#version 460
#extension GL_GOOGLE_include_directive : require
// Lane-serial stable scatter: one invocation walks its chunk in order and writes each pair to the
// next slot of its digit, starting from the scanned histogram.
#extension GL_EXT_control_flow_attributes : require
#include "common.glsl"
#include "sort.glsl"

layout(binding = 0) uniform usamplerBuffer keys_in;
layout(binding = 1) uniform usamplerBuffer vals_in;
BUF_RW(2, uint, keys_out);
BUF_RW(3, uint, vals_out);
BUF_RO(4, uint, offsets);
layout(push_constant) uniform Push { uint n; uint shift; uint num_chunks; } pc;

void main() {
    uint chunk = group_linear() * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (chunk >= pc.num_chunks) return;
    uint off[SORT_SERIAL_RADIX];
    for (uint d = 0u; d < SORT_SERIAL_RADIX; d++) off[d] = offsets.data[d * pc.num_chunks + chunk];
    uint begin = chunk * SORT_CHUNK;
    uint end = min(pc.n, begin + SORT_CHUNK);
    for (uint i = begin; i < end; i += 4u) {
        uvec4 k = texelFetch(keys_in, int(i >> 2u));
        uvec4 v = texelFetch(vals_in, int(i >> 2u));
        [[unroll]] for (uint c = 0u; c < 4u; c++) {
            if (i + c < end) {
                uint d = (k[c] >> pc.shift) & (SORT_SERIAL_RADIX - 1u);
                uint o = off[d];
                off[d] = o + 1u;
                keys_out.data[o] = k[c];
                vals_out.data[o] = v[c];
            }
        }
    }
}
