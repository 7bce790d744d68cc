#!/usr/bin/env python3
"""Shrink a CUDA library for one GPU generation, for carrying it where the size is limited.

    fatbin_keep.py LIB.so ARCH OUT.so     # e.g. fatbin_keep.py libonnxruntime_providers_cuda.so 90 out.so
    fatbin_keep.py LIB.so                 # lists the embedded machine code by kind and arch

A CUDA library embeds its kernels in the ELF section `.nv_fatbin`: a run of fat binaries, each a
header (magic 0xBA55ED50, version, header size, payload size) followed by entries (kind 1 PTX,
2 ELF/cubin; entry header size; payload size; the SM architecture at byte 28). The CUDA driver
picks the entry for the device's architecture and reads no other. This writes a copy whose
entries for every other architecture are zeroed in place (headers, offsets and sizes unchanged),
so the file compresses to the size of one generation's code: ONNX Runtime 1.31.1's CUDA provider
(284 MB, machine code for sm_75 to sm_120) becomes 52 MB with xz, keeping sm_90 for an H100/H200.
The result runs only on devices of ARCH. A measuring aid (scripts/dev/device_measure.sh), not
something to ship.
"""
import collections
import struct
import subprocess
import sys

MAGIC = 0xBA55ED50


def fatbin_section(path):
    out = subprocess.check_output(["readelf", "-S", "-W", path]).decode()
    for line in out.splitlines():
        if ".nv_fatbin" in line:
            fields = line.split("]", 1)[1].split()
            return int(fields[3], 16), int(fields[4], 16)
    sys.exit(f"{path}: no .nv_fatbin section")


def entries(data, off, size):
    """(entry payload offset, payload size, kind, arch) of every entry."""
    p, end = off, off + size
    while p + 16 <= end:
        magic, _ver, hsize, fsize = struct.unpack_from("<IHHQ", data, p)
        if magic != MAGIC:
            p += 8  # fat binaries are 8-aligned; padding between them
            continue
        q, qend = p + hsize, p + hsize + fsize
        while q < qend:
            kind, _ever, ehsize, payload = struct.unpack_from("<HHII", data, q)
            arch = struct.unpack_from("<I", data, q + 28)[0]
            yield q + ehsize, payload, kind, arch
            q += ehsize + payload
        p = qend


def main(argv):
    if len(argv) not in (1, 3):
        sys.exit(__doc__)
    data = bytearray(open(argv[0], "rb").read())
    off, size = fatbin_section(argv[0])
    total, count = collections.Counter(), collections.Counter()
    keep = int(argv[1]) if len(argv) == 3 else None
    zeroed = 0
    for start, payload, kind, arch in entries(data, off, size):
        key = ("ptx" if kind == 1 else "elf" if kind == 2 else f"kind{kind}", arch)
        total[key] += payload
        count[key] += 1
        if keep is not None and arch != keep:
            data[start:start + payload] = bytes(payload)
            zeroed += payload
    for key in sorted(total):
        print(f"{key[0]} sm_{key[1]}: {count[key]} entries, {total[key] / 2**20:.1f} MiB")
    if keep is not None:
        open(argv[2], "wb").write(data)
        print(f"{argv[2]}: {zeroed / 2**20:.1f} MiB of other architectures zeroed")


if __name__ == "__main__":
    main(sys.argv[1:])
