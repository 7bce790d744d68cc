#version 460
#extension GL_GOOGLE_include_directive : require
// offsets[j] = counts[ids[j]] in depth order, plus a trailing 0 so that the exclusive scan's last
// element is the number of intersections.
#include "common.glsl"

BUF_RO(0, uint, ids);
BUF_RO(1, uint, counts);
BUF_RW(2, uint, offsets);
layout(push_constant) uniform Push { uint n; } pc;

void main() {
    uint j = group_linear() * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (j < pc.n) offsets.data[j] = counts.data[ids.data[j]];
    else if (j == pc.n) offsets.data[j] = 0u;
}
