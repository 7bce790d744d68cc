// Radix sort parameters shared by sort_count and sort_scatter (mirrored to Rust by build.rs).
const uint SORT_BLOCK = 4096u; // export
// 8-bit digits: four passes sort 32-bit keys.
const uint SORT_RADIX = 256u; // export
// Workgroup sizes: the count kernel gives one thread per digit; the scatter keeps its per-subgroup
// digit counters (WG / 8 subgroups x 256 digits x 4 bytes = 16 KiB) under lavapipe's 32 KiB.
const uint SORT_COUNT_WG = 256u; // export
const uint SORT_SCATTER_WG = 128u; // export
// Smallest subgroup the scatter supports (lavapipe's is 8).
const uint SORT_MIN_SUBGROUP = 8u; // export
// Lane-serial variant for CPU devices (lavapipe): each invocation owns a contiguous chunk of
// SORT_CHUNK keys and counts / scatters it sequentially with private counters, which keeps the
// pass stable with no ballots, shared memory or barriers. It reads keys and values four at a time
// through uvec4 texel buffers: llvmpipe turns a texel fetch into one vector gather, where a
// lane-varying storage-buffer load is a scalar loop over the lanes (measured: the count pass
// 15.5 -> 3.5 ms for 4 x 1M keys, the scatter 48 -> 19 ms). Per invocation that is at most
// 2 x SORT_SERIAL_RADIX + SORT_CHUNK / 4 loop iterations, far below lavapipe's 65,535. Digits are 8
// bits wide: 11-bit digits (three passes) measured slower, as 2,048 streams per lane thrash the cache.
const uint SORT_CHUNK = 8192u; // export
const uint SORT_SERIAL_WG = 8u; // export
const uint SORT_SERIAL_BITS = 8u; // export
const uint SORT_SERIAL_RADIX = 256u; // export
