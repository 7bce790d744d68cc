#version 460
#extension GL_GOOGLE_include_directive : require
// ranges[tile] = [start, end) of the tile's run in the tile-sorted intersection list.
// `ranges` must be zeroed first; sentinel tiles (>= num_tiles) are ignored.
#include "common.glsl"

BUF_RO(0, uint, tile_keys);
BUF_RW(1, uvec2, ranges);
layout(push_constant) uniform Push { uint m; uint num_tiles; } pc;

void main() {
    uint k = group_linear() * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (k >= pc.m) return;
    uint t = tile_keys.data[k];
    if (t >= pc.num_tiles) return;
    if (k == 0u || tile_keys.data[k - 1u] != t) ranges.data[t].x = k;
    if (k + 1u == pc.m || tile_keys.data[k + 1u] != t) ranges.data[t].y = k + 1u;
}
