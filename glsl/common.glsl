// Shared helpers for every kernel. Workgroup size is specialization constant 0, set from Rust.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_shuffle : require

// Float atomic add on a storage buffer declared with ATOMIC_FLOAT element type. build.rs also
// compiles every kernel using it with CAS_ATOMICS, for devices without shaderBufferFloat32AtomicAdd.
#ifdef CAS_ATOMICS
#define ATOMIC_FLOAT uint
// Bounded retries (lavapipe cuts long loops); updates are pre-reduced per subgroup, so contention is low.
#define FLOAT_ATOMIC_ADD(buf, idx, val) { uint i_ = (idx); float v_ = (val); uint old_ = buf.data[i_]; \
    for (uint k_ = 0u; k_ < 4096u; k_++) { uint prev_ = atomicCompSwap(buf.data[i_], old_, floatBitsToUint(uintBitsToFloat(old_) + v_)); \
        if (prev_ == old_) break; old_ = prev_; } }
#else
#extension GL_EXT_shader_atomic_float : require
#define ATOMIC_FLOAT float
#define FLOAT_ATOMIC_ADD(buf, idx, val) atomicAdd(buf.data[idx], (val))
#endif

layout(local_size_x_id = 0) in;
// The smallest subgroup size the device may use (specialization constant 1, set from Rust), so
// subgroup-size-dependent paths are chosen when the pipeline is built rather than per invocation.
layout(constant_id = 1) const uint MIN_SUBGROUP_SIZE = 1u;

// Storage buffers are declared with an instance name: the host binds them by that name.
#define BUF_RO(b, T, name) layout(std430, binding = b) readonly buffer name##_block { T data[]; } name
#define BUF_RW(b, T, name) layout(std430, binding = b) buffer name##_block { T data[]; } name

// Dispatches wider than 65,535 workgroups are folded into y (see gpu::groups_for).
uint group_linear() { return gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x; }

// Word i of a buffer bound as a uvec4 texel buffer (`uniform usamplerBuffer`).
uint fetch_u32(usamplerBuffer buf, uint i) { return texelFetch(buf, int(i >> 2u))[i & 3u]; }
