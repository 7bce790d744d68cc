//! Stable GPU radix sort of `u32` key / `u32` value pairs, 8 bits per pass, reduce-then-scan
//! (no forward-progress assumptions, so it runs on lavapipe's subgroup size of 8).
use super::scan::{Scan, ScanScratch};
use crate::gpu::{
    groups_for, kernels, Buffer, BufferUsage, Context, GpuError, Kernel, Result, Stream,
};

/// How a pass counts and scatters.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SortVariant {
    /// Workgroups of SORT_BLOCK keys ranked with subgroup ballots: for GPUs.
    Subgroup,
    /// One invocation per chunk of SORT_CHUNK keys, sequential: for CPU devices (lavapipe),
    /// where it is several times faster.
    Serial,
}

impl SortVariant {
    /// The variant for a device: serial on CPU devices, unless `DREAMSCENE_SORT` says
    /// `subgroup` or `serial`.
    pub fn for_device(ctx: &Context) -> SortVariant {
        let choices = [
            ("subgroup", SortVariant::Subgroup),
            ("serial", SortVariant::Serial),
        ];
        crate::util::env_choice("DREAMSCENE_SORT", &choices).unwrap_or(
            if ctx.info().device_type == "CPU" {
                SortVariant::Serial
            } else {
                SortVariant::Subgroup
            },
        )
    }

    /// Keys per histogram column.
    fn block(self) -> u32 {
        match self {
            SortVariant::Subgroup => kernels::SORT_BLOCK,
            SortVariant::Serial => kernels::SORT_CHUNK,
        }
    }

    /// Bits per pass and the number of digits.
    fn digit(self) -> (u32, u32) {
        match self {
            SortVariant::Subgroup => (8, kernels::SORT_RADIX),
            SortVariant::Serial => (kernels::SORT_SERIAL_BITS, kernels::SORT_SERIAL_RADIX),
        }
    }
}

/// The radix-sort kernels.
pub struct RadixSort {
    count: Kernel,
    scatter: Kernel,
    scan: Scan,
    variant: SortVariant,
}

/// Ping-pong and histogram buffers for sorting up to `capacity` pairs.
pub struct SortScratch {
    capacity: u32,
    keys: Buffer,
    vals: Buffer,
    hist: Buffer,
    scan: ScanScratch,
}

impl SortScratch {
    pub fn new(ctx: &Context, capacity: u32) -> Result<SortScratch> {
        let cap = capacity.max(1);
        // Room for either variant's histogram.
        let hist_len = (cap.div_ceil(kernels::SORT_BLOCK) * kernels::SORT_RADIX)
            .max(cap.div_ceil(kernels::SORT_CHUNK) * kernels::SORT_SERIAL_RADIX);
        Ok(SortScratch {
            capacity: cap,
            keys: Buffer::new(
                ctx,
                "sort keys (ping-pong)",
                cap as u64 * 4,
                BufferUsage::Device,
            )?,
            vals: Buffer::new(
                ctx,
                "sort values (ping-pong)",
                cap as u64 * 4,
                BufferUsage::Device,
            )?,
            hist: Buffer::new(
                ctx,
                "sort histogram",
                hist_len as u64 * 4,
                BufferUsage::Device,
            )?,
            scan: ScanScratch::new(ctx, hist_len)?,
        })
    }

    /// Pairs this scratch can sort.
    pub fn capacity(&self) -> u32 {
        self.capacity
    }
}

impl RadixSort {
    /// The sort in the variant suited to the device ([`SortVariant::for_device`]).
    pub fn new(ctx: &Context) -> Result<RadixSort> {
        Self::with_variant(ctx, SortVariant::for_device(ctx))
    }

    /// The sort in a given variant.
    pub fn with_variant(ctx: &Context, variant: SortVariant) -> Result<RadixSort> {
        if variant == SortVariant::Serial {
            return Ok(RadixSort {
                count: Kernel::new(ctx, kernels::SORT_COUNT_SERIAL, kernels::SORT_SERIAL_WG)?,
                scatter: Kernel::new(ctx, kernels::SORT_SCATTER_SERIAL, kernels::SORT_SERIAL_WG)?,
                scan: Scan::new(ctx)?,
                variant,
            });
        }
        if ctx.info().subgroup_size < kernels::SORT_MIN_SUBGROUP {
            return Err(GpuError::NoDevice(format!(
                "the radix sort needs subgroups of at least {} lanes; `{}` has {}",
                kernels::SORT_MIN_SUBGROUP,
                ctx.info().name,
                ctx.info().subgroup_size
            )));
        }
        Ok(RadixSort {
            count: Kernel::new(ctx, kernels::SORT_COUNT, kernels::SORT_COUNT_WG)?,
            scatter: Kernel::new(ctx, kernels::SORT_SCATTER, kernels::SORT_SCATTER_WG)?,
            scan: Scan::new(ctx)?,
            variant,
        })
    }

    /// Which variant this is.
    pub fn variant(&self) -> SortVariant {
        self.variant
    }

    /// The scan used inside the sort, reusable by callers.
    pub fn scan(&self) -> &Scan {
        &self.scan
    }

    /// Records a stable sort of the first `n` pairs of (`keys`, `vals`) by the low `bits` bits of
    /// the keys (higher bits must be zero or are ignored in order). The result is left in `keys`
    /// and `vals`.
    pub fn record(
        &self,
        s: &mut Stream,
        keys: &Buffer,
        vals: &Buffer,
        n: u32,
        bits: u32,
        scratch: &SortScratch,
    ) -> Result<()> {
        if n > scratch.capacity {
            return Err(GpuError::Kernel {
                kernel: "sort".into(),
                msg: format!("{n} pairs with scratch for {}", scratch.capacity),
            });
        }
        if n <= 1 || bits == 0 {
            return Ok(());
        }
        let (digit_bits, radix) = self.variant.digit();
        let passes = bits.min(32).div_ceil(digit_bits);
        let num_blocks = n.div_ceil(self.variant.block());
        let hist_len = num_blocks * radix;
        // Workgroups: one per block, or one per SORT_SERIAL_WG chunks.
        let groups = match self.variant {
            SortVariant::Subgroup => num_blocks,
            SortVariant::Serial => num_blocks.div_ceil(kernels::SORT_SERIAL_WG),
        };
        for pass in 0..passes {
            let (src_k, src_v, dst_k, dst_v) = if pass % 2 == 0 {
                (keys, vals, &scratch.keys, &scratch.vals)
            } else {
                (&scratch.keys, &scratch.vals, keys, vals)
            };
            let push = [n, pass * digit_bits, num_blocks];
            s.dispatch(
                &self.count,
                &[("keys", src_k), ("hist", &scratch.hist)],
                bytemuck::bytes_of(&push),
                groups_for(groups),
            )?;
            self.scan
                .record(s, &scratch.hist, hist_len, &scratch.scan)?;
            s.dispatch(
                &self.scatter,
                &[
                    ("keys_in", src_k),
                    ("vals_in", src_v),
                    ("keys_out", dst_k),
                    ("vals_out", dst_v),
                    ("offsets", &scratch.hist),
                ],
                bytemuck::bytes_of(&push),
                groups_for(groups),
            )?;
        }
        if passes % 2 == 1 {
            s.copy(&scratch.keys, keys, n as u64 * 4);
            s.copy(&scratch.vals, vals, n as u64 * 4);
        }
        Ok(())
    }

    /// Sorts host data on the device: a convenience for tests and tools.
    pub fn sort_pairs(
        &self,
        ctx: &Context,
        keys: &[u32],
        vals: &[u32],
        bits: u32,
    ) -> Result<(Vec<u32>, Vec<u32>)> {
        assert_eq!(keys.len(), vals.len(), "keys and values differ in length");
        let n = keys.len() as u32;
        let kb = Buffer::from_slice(ctx, "sort keys", keys)?;
        let vb = Buffer::from_slice(ctx, "sort values", vals)?;
        let scratch = SortScratch::new(ctx, n)?;
        let mut s = Stream::new(ctx)?;
        self.record(&mut s, &kb, &vb, n, bits, &scratch)?;
        s.submit()?;
        Ok((kb.read(n as usize)?, vb.read(n as usize)?))
    }
}
