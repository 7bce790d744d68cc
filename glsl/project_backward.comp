#version 460
#extension GL_GOOGLE_include_directive : require
// Backward of the projection, one Gaussian per invocation: from its screen-space gradient (summed
// over pixels by blend_backward) to its raw parameters: means, log-scales, quaternions (through
// the normalisation), opacity logits and SH coefficients (through the view direction too). The
// parameter gradients are added to (so several views can accumulate); the screen-space slot is
// cleared for the next view. Also accumulates the densification statistics of 3DGS: the norm of
// the centre gradient in NDC units, the number of views the Gaussian was visible in, and its
// largest screen radius. Mirrors src/splat/reference_grad.rs line by line.
#include "common.glsl"
#include "raster.glsl"

BUF_RO(0, float, means);
BUF_RO(1, float, scales);
BUF_RO(2, vec4, rotations);
BUF_RO(3, float, opacities);
BUF_RO(4, float, sh);
BUF_RO(5, vec4, proj);
BUF_RW(6, float, grad2d);
BUF_RW(7, float, grad_means);
BUF_RW(8, float, grad_scales);
BUF_RW(9, vec4, grad_rotations);
BUF_RW(10, float, grad_opacities);
BUF_RW(11, float, grad_sh);
BUF_RW(12, vec4, stats);        // (sum of NDC centre-gradient norms, views visible, max radius, 0)
layout(push_constant) uniform Push { CameraData cam; uint n; uint sh_degree; uint pad0; uint pad1; } pc;

const float SH_C0 = 0.28209479177387814;
const float SH_C1 = 0.4886025119029199;
const float SH_C2[5] = float[](1.0925484305920792, -1.0925484305920792, 0.31539156525252005, -1.0925484305920792, 0.5462742152960396);
const float SH_C3[7] = float[](-0.5900435899266435, 2.890611442640554, -0.4570457994644658, 0.3731763325901154,
                               -0.4570457994644658, 1.445305721320277, -0.5900435899266435);

// SH basis values and their derivatives with respect to the unit direction.
void sh_basis(uint degree, vec3 d, out float b[16], out vec3 db[16]) {
    float x = d.x, y = d.y, z = d.z;
    for (uint k = 0u; k < 16u; k++) { b[k] = 0.0; db[k] = vec3(0.0); }
    b[0] = SH_C0;
    if (degree >= 1u) {
        b[1] = -SH_C1 * y; db[1] = vec3(0.0, -SH_C1, 0.0);
        b[2] = SH_C1 * z;  db[2] = vec3(0.0, 0.0, SH_C1);
        b[3] = -SH_C1 * x; db[3] = vec3(-SH_C1, 0.0, 0.0);
    }
    if (degree >= 2u) {
        float xx = x * x, yy = y * y, zz = z * z;
        b[4] = SH_C2[0] * x * y;              db[4] = SH_C2[0] * vec3(y, x, 0.0);
        b[5] = SH_C2[1] * y * z;              db[5] = SH_C2[1] * vec3(0.0, z, y);
        b[6] = SH_C2[2] * (2.0 * zz - xx - yy); db[6] = SH_C2[2] * vec3(-2.0 * x, -2.0 * y, 4.0 * z);
        b[7] = SH_C2[3] * x * z;              db[7] = SH_C2[3] * vec3(z, 0.0, x);
        b[8] = SH_C2[4] * (xx - yy);          db[8] = SH_C2[4] * vec3(2.0 * x, -2.0 * y, 0.0);
        if (degree >= 3u) {
            b[9] = SH_C3[0] * y * (3.0 * xx - yy);
            db[9] = SH_C3[0] * vec3(6.0 * x * y, 3.0 * xx - 3.0 * yy, 0.0);
            b[10] = SH_C3[1] * x * y * z;
            db[10] = SH_C3[1] * vec3(y * z, x * z, x * y);
            b[11] = SH_C3[2] * y * (4.0 * zz - xx - yy);
            db[11] = SH_C3[2] * vec3(-2.0 * x * y, 4.0 * zz - xx - 3.0 * yy, 8.0 * y * z);
            b[12] = SH_C3[3] * z * (2.0 * zz - 3.0 * xx - 3.0 * yy);
            db[12] = SH_C3[3] * vec3(-6.0 * x * z, -6.0 * y * z, 6.0 * zz - 3.0 * xx - 3.0 * yy);
            b[13] = SH_C3[4] * x * (4.0 * zz - xx - yy);
            db[13] = SH_C3[4] * vec3(4.0 * zz - 3.0 * xx - yy, -2.0 * x * y, 8.0 * x * z);
            b[14] = SH_C3[5] * z * (xx - yy);
            db[14] = SH_C3[5] * vec3(2.0 * x * z, -2.0 * y * z, xx - yy);
            b[15] = SH_C3[6] * x * (xx - 3.0 * yy);
            db[15] = SH_C3[6] * vec3(3.0 * xx - 3.0 * yy, -6.0 * x * y, 0.0);
        }
    }
}

void main() {
    uint i = group_linear() * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (i >= pc.n) return;
    float g2[9];
    for (uint k = 0u; k < 9u; k++) { g2[k] = grad2d.data[9u * i + k]; grad2d.data[9u * i + k] = 0.0; }
    float radius = proj.data[3u * i + 1u].w;
    if (!(radius > 0.0)) return; // culled in the forward: no gradient

    vec3 m = vec3(means.data[3u * i], means.data[3u * i + 1u], means.data[3u * i + 2u]);
    vec3 W0 = pc.cam.row0.xyz, W1 = pc.cam.row1.xyz, W2 = pc.cam.row2.xyz;
    vec3 p = vec3(dot(W0, m) + pc.cam.row0.w, dot(W1, m) + pc.cam.row1.w, dot(W2, m) + pc.cam.row2.w);
    float z = p.z;
    vec4 q = rotations.data[i];
    float ql = length(q);
    vec4 qn = q / ql;
    float r = qn.x, x = qn.y, y = qn.z, w = qn.w;
    vec3 R0 = vec3(1.0 - 2.0 * (y * y + w * w), 2.0 * (x * y - r * w), 2.0 * (x * w + r * y));
    vec3 R1 = vec3(2.0 * (x * y + r * w), 1.0 - 2.0 * (x * x + w * w), 2.0 * (y * w - r * x));
    vec3 R2 = vec3(2.0 * (x * w - r * y), 2.0 * (y * w + r * x), 1.0 - 2.0 * (x * x + y * y));
    vec3 s = exp(vec3(scales.data[3u * i], scales.data[3u * i + 1u], scales.data[3u * i + 2u]));
    vec3 M0 = R0 * s, M1 = R1 * s, M2 = R2 * s;   // rows of M = R diag(s)
    vec3 S0 = vec3(dot(M0, M0), dot(M0, M1), dot(M0, M2));
    vec3 S1 = vec3(S0.y, dot(M1, M1), dot(M1, M2));
    vec3 S2 = vec3(S0.z, S1.z, dot(M2, M2));      // rows of Sigma = M M^T
    vec2 f = pc.cam.focal;
    vec2 lim = 1.3 * 0.5 * pc.cam.size / f;
    vec2 u = p.xy / z;
    bvec2 clamped = bvec2(u.x < -lim.x || u.x > lim.x, u.y < -lim.y || u.y > lim.y);
    vec2 tt = clamp(u, -lim, lim) * z;
    float zz = z * z;
    vec3 j0 = vec3(f.x / z, 0.0, -f.x * tt.x / zz);
    vec3 j1 = vec3(0.0, f.y / z, -f.y * tt.y / zz);
    vec3 tm0 = j0.x * W0 + j0.y * W1 + j0.z * W2;  // rows of T = J W
    vec3 tm1 = j1.x * W0 + j1.y * W1 + j1.z * W2;
    vec3 st0 = vec3(dot(S0, tm0), dot(S1, tm0), dot(S2, tm0));
    vec3 st1 = vec3(dot(S0, tm1), dot(S1, tm1), dot(S2, tm1));
    float a = dot(tm0, st0) + COV_BLUR;
    float b = dot(tm0, st1);
    float c = dot(tm1, st1) + COV_BLUR;
    float det = a * c - b * b;
    float det2 = det * det;

    // conic -> 2D covariance
    float ga = g2[2], gb = g2[3], gc = g2[4];
    float da = (-c * c * ga + b * c * gb - b * b * gc) / det2;
    float db = (2.0 * b * c * ga - (a * c + b * b) * gb + 2.0 * a * b * gc) / det2;
    float dc = (-b * b * ga + a * b * gb - a * a * gc) / det2;
    // covariance -> T rows -> J -> camera-space position
    vec3 gt0 = 2.0 * da * st0 + db * st1;
    vec3 gt1 = 2.0 * dc * st1 + db * st0;
    vec3 gj0 = vec3(dot(gt0, W0), dot(gt0, W1), dot(gt0, W2));
    vec3 gj1 = vec3(dot(gt1, W0), dot(gt1, W1), dot(gt1, W2));
    vec3 gp = vec3(0.0);
    gp.z += -gj0.x * f.x / zz - gj1.y * f.y / zz;
    if (clamped.x) { gp.z += gj0.z * f.x * tt.x / (zz * z); }
    else { gp.x += -gj0.z * f.x / zz; gp.z += gj0.z * 2.0 * f.x * p.x / (zz * z); }
    if (clamped.y) { gp.z += gj1.z * f.y * tt.y / (zz * z); }
    else { gp.y += -gj1.z * f.y / zz; gp.z += gj1.z * 2.0 * f.y * p.y / (zz * z); }
    vec2 gxy = vec2(g2[0], g2[1]);
    gp.xy += gxy * f / z;
    gp.z += -dot(gxy, f * p.xy) / zz;
    vec3 gm = gp.x * W0 + gp.y * W1 + gp.z * W2;
    // covariance -> Sigma -> M = R diag(s): rows of dL/dM
    vec3 P0 = tm0.x * M0 + tm0.y * M1 + tm0.z * M2;
    vec3 P1 = tm1.x * M0 + tm1.y * M1 + tm1.z * M2;
    vec3 A0 = 2.0 * da * P0 + db * P1, A1 = db * P0 + 2.0 * dc * P1;
    vec3 G0 = tm0.x * A0 + tm1.x * A1, G1 = tm0.y * A0 + tm1.y * A1, G2 = tm0.z * A0 + tm1.z * A1;
    vec3 gscale = (G0 * R0 + G1 * R1 + G2 * R2) * s;
    vec3 H0 = G0 * s, H1 = G1 * s, H2 = G2 * s;   // dL/dR rows
    vec4 gq = 2.0 * vec4(
        -w * H0.y + y * H0.z + w * H1.x - x * H1.z - y * H2.x + x * H2.y,
        y * H0.y + w * H0.z + y * H1.x - 2.0 * x * H1.y - r * H1.z + w * H2.x + r * H2.y - 2.0 * x * H2.z,
        -2.0 * y * H0.x + x * H0.y + r * H0.z + x * H1.x + w * H1.z - r * H2.x + w * H2.y - 2.0 * y * H2.z,
        -2.0 * w * H0.x - r * H0.y + x * H0.z + r * H1.x - 2.0 * w * H1.y + y * H1.z + x * H2.x + y * H2.y);
    vec4 grot = (gq - qn * dot(qn, gq)) / ql;
    // opacity
    float o = 1.0 / (1.0 + exp(-opacities.data[i]));
    float gop = g2[5] * o * (1.0 - o);
    // colour: SH coefficients and the view direction
    vec3 d = m - pc.cam.campos.xyz;
    float dl = length(d);
    vec3 dir = d / dl;
    float basis[16];
    vec3 dbasis[16];
    sh_basis(pc.sh_degree, dir, basis, dbasis);
    uint kc = (pc.sh_degree + 1u) * (pc.sh_degree + 1u);
    uint base = i * kc * 3u;
    vec3 raw = vec3(0.5);
    for (uint k = 0u; k < kc; k++)
        raw += basis[k] * vec3(sh.data[base + 3u * k], sh.data[base + 3u * k + 1u], sh.data[base + 3u * k + 2u]);
    vec3 grgb = vec3(g2[6], g2[7], g2[8]);
    grgb = mix(grgb, vec3(0.0), lessThan(raw, vec3(0.0)));
    vec3 gdir = vec3(0.0);
    for (uint k = 0u; k < kc; k++) {
        vec3 coef = vec3(sh.data[base + 3u * k], sh.data[base + 3u * k + 1u], sh.data[base + 3u * k + 2u]);
        grad_sh.data[base + 3u * k] += basis[k] * grgb.x;
        grad_sh.data[base + 3u * k + 1u] += basis[k] * grgb.y;
        grad_sh.data[base + 3u * k + 2u] += basis[k] * grgb.z;
        gdir += dot(coef, grgb) * dbasis[k];
    }
    gm += (gdir - dir * dot(dir, gdir)) / dl;

    grad_means.data[3u * i] += gm.x;
    grad_means.data[3u * i + 1u] += gm.y;
    grad_means.data[3u * i + 2u] += gm.z;
    grad_scales.data[3u * i] += gscale.x;
    grad_scales.data[3u * i + 1u] += gscale.y;
    grad_scales.data[3u * i + 2u] += gscale.z;
    grad_rotations.data[i] += grot;
    grad_opacities.data[i] += gop;
    vec4 st = stats.data[i];
    stats.data[i] = vec4(st.x + length(gxy * 0.5 * pc.cam.size), st.y + 1.0, max(st.z, radius), 0.0);
}
