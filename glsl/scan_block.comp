#version 460
#extension GL_GOOGLE_include_directive : require
// In-place exclusive scan of each SCAN_ITEMS-element block of `data`; block totals go to `sums`.
#include "common.glsl"
#include "scan.glsl"

BUF_RW(0, uint, data);
BUF_RW(1, uint, sums);
layout(push_constant) uniform Push { uint n; uint write_sums; } pc;

// One slot per subgroup; 64 covers subgroups as small as 4 lanes.
shared uint s_part[64];

void main() {
    uint block = group_linear();
    uint t = gl_LocalInvocationID.x;
    uint base = block * SCAN_ITEMS + 4u * t;
    uvec4 v = uvec4(0u);
    for (uint k = 0u; k < 4u; k++) if (base + k < pc.n) v[k] = data.data[base + k];
    uint local = v.x + v.y + v.z + v.w;
    uint pre = subgroupExclusiveAdd(local);
    if (gl_SubgroupInvocationID == gl_SubgroupSize - 1u) s_part[gl_SubgroupID] = pre + local;
    barrier();
    if (t == 0u) {
        uint run = 0u;
        for (uint s = 0u; s < gl_NumSubgroups; s++) { uint x = s_part[s]; s_part[s] = run; run += x; }
        if (pc.write_sums != 0u) sums.data[block] = run;
    }
    barrier();
    uint acc = s_part[gl_SubgroupID] + pre;
    for (uint k = 0u; k < 4u; k++) {
        if (base + k < pc.n) data.data[base + k] = acc;
        acc += v[k];
    }
}
