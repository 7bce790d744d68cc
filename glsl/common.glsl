// Shared helpers for every kernel. Workgroup size is specialization constant 0, set from Rust.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_shuffle : require

layout(local_size_x_id = 0) in;

// Storage buffers are declared with an instance name: the host binds them by that name.
#define BUF_RO(b, T, name) layout(std430, binding = b) readonly buffer name##_block { T data[]; } name
#define BUF_RW(b, T, name) layout(std430, binding = b) buffer name##_block { T data[]; } name

// Dispatches wider than 65,535 workgroups are folded into y (see gpu::groups_for).
uint group_linear() { return gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x; }
