#version 460
#extension GL_GOOGLE_include_directive : require
// Fused Adam step over one parameter array: moments, bias-corrected update, and the gradient
// cleared for the next step. A non-finite gradient counts as zero so that one broken pixel cannot
// poison a parameter. Elements with (index % stride) >= rest_from use lr_rest (the SH
// coefficients above degree 0, whose learning rate 3DGS divides by 20); stride 0 disables that.
#include "common.glsl"
#include "raster.glsl"

BUF_RW(0, float, param);
BUF_RW(1, float, grad);
BUF_RW(2, float, moment1);
BUF_RW(3, float, moment2);
layout(push_constant) uniform Push { uint n; uint stride; uint rest_from; float lr; float lr_rest;
                                     float beta1; float beta2; float eps; float bc1; float bc2; } pc;

void main() {
    uint e = group_linear() * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (e >= pc.n) return;
    float g = grad.data[e];
    grad.data[e] = 0.0;
    if (!finite_f(g)) g = 0.0;
    float m = pc.beta1 * moment1.data[e] + (1.0 - pc.beta1) * g;
    float v = pc.beta2 * moment2.data[e] + (1.0 - pc.beta2) * g * g;
    moment1.data[e] = m;
    moment2.data[e] = v;
    float lr = (pc.stride > 0u && e % pc.stride >= pc.rest_from) ? pc.lr_rest : pc.lr;
    param.data[e] -= lr * (m / pc.bc1) / (sqrt(v / pc.bc2) + pc.eps);
}
