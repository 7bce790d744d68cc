#version 460
#extension GL_GOOGLE_include_directive : require
// Stable scatter of one radix-sort pass. Each subgroup owns a contiguous segment of the block and
// ranks its keys round by round: lanes with the same digit are found with eight ballots (one per
// digit bit), so the rank needs no atomics and works for any subgroup size from 8 to 128.
// Three workgroup barriers per block, which matters on lavapipe where a barrier costs ~1 us.
#extension GL_EXT_control_flow_attributes : require
#include "common.glsl"
#include "sort.glsl"

BUF_RO(0, uint, keys_in);
BUF_RO(1, uint, vals_in);
BUF_RW(2, uint, keys_out);
BUF_RW(3, uint, vals_out);
BUF_RO(4, uint, offsets);   // exclusive scan of the digit-major histogram
layout(push_constant) uniform Push { uint n; uint shift; uint num_blocks; } pc;

const uint MAX_SUBGROUPS = SORT_SCATTER_WG / SORT_MIN_SUBGROUP;
const uint KPT = SORT_BLOCK / SORT_SCATTER_WG;  // keys per thread

shared uint s_cnt[MAX_SUBGROUPS * SORT_RADIX];  // per (subgroup, digit): running count, then prefix
shared uint s_base[SORT_RADIX];

void main() {
    uint block = group_linear();
    if (block >= pc.num_blocks) return;
    uint t = gl_LocalInvocationID.x;
    uint sg = gl_SubgroupID;
    uint lane = gl_SubgroupInvocationID;
    uint nsg = gl_NumSubgroups;

    for (uint i = t; i < nsg * SORT_RADIX; i += SORT_SCATTER_WG) s_cnt[i] = 0u;
    for (uint d = t; d < SORT_RADIX; d += SORT_SCATTER_WG) s_base[d] = offsets.data[d * pc.num_blocks + block];
    barrier();

    uint seg_len = SORT_BLOCK / nsg;
    uint seg = block * SORT_BLOCK + sg * seg_len;
    uint lkey[KPT];
    uint lrank[KPT];
    [[unroll]] for (uint r = 0u; r < KPT; r++) {
        uint idx = seg + r * gl_SubgroupSize + lane;
        bool valid = idx < pc.n;
        uint key = valid ? keys_in.data[idx] : 0u;
        uint digit = (key >> pc.shift) & 255u;
        uvec4 peers = subgroupBallot(valid);
        [[unroll]] for (uint b = 0u; b < 8u; b++) {
            bool bit = ((digit >> b) & 1u) != 0u;
            uvec4 bal = subgroupBallot(bit);
            peers &= bit ? bal : ~bal;
        }
        uint before = subgroupBallotExclusiveBitCount(peers);
        uint count = subgroupBallotBitCount(peers);
        uint leader_lane = valid ? subgroupBallotFindLSB(peers) : lane;
        // Only the digit's leader lane touches the subgroup's counter, and it hands the running
        // count to its peers by shuffle: no execution barrier inside the loop (on lavapipe a
        // subgroup barrier costs as much as a workgroup one). The next round's ballots
        // reconverge the subgroup; the memory barrier makes the write visible to the next leader.
        uint slot = sg * SORT_RADIX + digit;
        uint run = 0u;
        if (valid && leader_lane == lane) { run = s_cnt[slot]; s_cnt[slot] = run + count; }
        run = subgroupShuffle(run, leader_lane);
        subgroupMemoryBarrierShared();
        lkey[r] = key;
        lrank[r] = run + before;
    }
    barrier();
    for (uint d = t; d < SORT_RADIX; d += SORT_SCATTER_WG) {
        uint run = 0u;
        for (uint s = 0u; s < nsg; s++) { uint c = s_cnt[s * SORT_RADIX + d]; s_cnt[s * SORT_RADIX + d] = run; run += c; }
    }
    barrier();
    [[unroll]] for (uint r = 0u; r < KPT; r++) {
        uint idx = seg + r * gl_SubgroupSize + lane;
        if (idx < pc.n) {
            uint digit = (lkey[r] >> pc.shift) & 255u;
            uint pos = s_base[digit] + s_cnt[sg * SORT_RADIX + digit] + lrank[r];
            keys_out.data[pos] = lkey[r];
            vals_out.data[pos] = vals_in.data[idx];
        }
    }
}
