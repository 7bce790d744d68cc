#version 460
#extension GL_GOOGLE_include_directive : require
// Adds the scanned block totals back: data[i] += sums[i / SCAN_ITEMS].
#include "common.glsl"
#include "scan.glsl"

BUF_RW(0, uint, data);
BUF_RO(1, uint, sums);
layout(push_constant) uniform Push { uint n; } pc;

void main() {
    uint block = group_linear();
    uint add = sums.data[block];
    uint base = block * SCAN_ITEMS;
    for (uint k = 0u; k < 4u; k++) {
        uint idx = base + k * SCAN_WG + gl_LocalInvocationID.x;
        if (idx < pc.n) data.data[idx] += add;
    }
}
