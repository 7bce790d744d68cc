#version 460
#extension GL_GOOGLE_include_directive : require
// Writes one (tile, gaussian) intersection per tile a splat reaches, in depth order. It repeats
// the projection's tile test on the stored values; should the two ever disagree, the slots are
// capped at the counted number and any left over get the sentinel tile `num_tiles`.
#include "common.glsl"
#include "raster.glsl"

BUF_RO(0, uint, ids);
BUF_RO(1, uint, counts);
BUF_RO(2, uint, offsets);
BUF_RO(3, vec4, proj);
BUF_RO(4, uvec2, rects);
BUF_RW(5, uint, tile_keys);
BUF_RW(6, uint, isect_ids);
layout(push_constant) uniform Push { uint n; uint tiles_x; uint num_tiles; } pc;

void main() {
    uint j = group_linear() * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (j >= pc.n) return;
    uint g = ids.data[j];
    uint cnt = counts.data[g];
    if (cnt == 0u) return;
    uint off = offsets.data[j];
    vec4 p0 = proj.data[3u * g];
    vec4 p1 = proj.data[3u * g + 1u];
    uvec4 r = unpack_rect(rects.data[g]);
    uint k = 0u;
    for (uint ty = r.y; ty < r.w; ty++)
        for (uint tx = r.x; tx < r.z; tx++)
            if (k < cnt && tile_touched(p0.xy, p1.xyz, p0.w, tx, ty)) {
                tile_keys.data[off + k] = ty * pc.tiles_x + tx;
                isect_ids.data[off + k] = g;
                k++;
            }
    for (; k < cnt; k++) { tile_keys.data[off + k] = pc.num_tiles; isect_ids.data[off + k] = g; }
}
