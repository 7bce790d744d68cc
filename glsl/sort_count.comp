#version 460
#extension GL_GOOGLE_include_directive : require
// Per-block digit histogram for one radix-sort pass: hist[digit * num_blocks + block].
// The digit-major layout lets one exclusive scan give every (digit, block) its output offset.
#include "common.glsl"
#include "sort.glsl"

BUF_RO(0, uint, keys);
BUF_RW(1, uint, hist);
layout(push_constant) uniform Push { uint n; uint shift; uint num_blocks; } pc;

shared uint s_hist[SORT_RADIX];

void main() {
    uint block = group_linear();
    if (block >= pc.num_blocks) return;
    uint t = gl_LocalInvocationID.x;
    s_hist[t] = 0u;
    barrier();
    uint base = block * SORT_BLOCK;
    for (uint i = 0u; i < SORT_BLOCK / SORT_COUNT_WG; i++) {
        uint idx = base + i * SORT_COUNT_WG + t;
        if (idx < pc.n) atomicAdd(s_hist[(keys.data[idx] >> pc.shift) & 255u], 1u);
    }
    barrier();
    hist.data[t * pc.num_blocks + block] = s_hist[t];
}
