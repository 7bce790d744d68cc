//! Exclusive prefix sum of `u32` on the GPU (multi-level reduce-then-scan, any subgroup size).
use crate::gpu::{groups_for, kernels, Buffer, Context, Kernel, Result, Stream};

/// The scan kernels.
pub struct Scan {
    block: Kernel,
    add: Kernel,
}

/// Block-sum buffers for scanning up to `capacity` elements.
pub struct ScanScratch {
    capacity: u32,
    levels: Vec<Buffer>,
    dummy: Buffer,
}

impl ScanScratch {
    /// Scratch for arrays of up to `capacity` elements.
    pub fn new(ctx: &Context, capacity: u32) -> Result<ScanScratch> {
        let mut levels = Vec::new();
        let mut n = capacity;
        while n > kernels::SCAN_ITEMS {
            n = n.div_ceil(kernels::SCAN_ITEMS);
            levels.push(Buffer::new(
                ctx,
                &format!("scan sums L{}", levels.len()),
                n as u64 * 4,
                crate::gpu::BufferUsage::Device,
            )?);
        }
        let dummy = Buffer::new(ctx, "scan dummy", 16, crate::gpu::BufferUsage::Device)?;
        Ok(ScanScratch {
            capacity,
            levels,
            dummy,
        })
    }

    /// Elements this scratch can scan.
    pub fn capacity(&self) -> u32 {
        self.capacity
    }
}

impl Scan {
    pub fn new(ctx: &Context) -> Result<Scan> {
        Ok(Scan {
            block: Kernel::new(ctx, kernels::SCAN_BLOCK, kernels::SCAN_WG)?,
            add: Kernel::new(ctx, kernels::SCAN_ADD, kernels::SCAN_WG)?,
        })
    }

    /// Records an in-place exclusive scan of the first `n` elements of `data`.
    pub fn record(
        &self,
        s: &mut Stream,
        data: &Buffer,
        n: u32,
        scratch: &ScanScratch,
    ) -> Result<()> {
        assert!(
            n <= scratch.capacity,
            "scan of {n} elements with scratch for {}",
            scratch.capacity
        );
        self.level(s, data, n, &scratch.levels, &scratch.dummy)
    }

    fn level(
        &self,
        s: &mut Stream,
        data: &Buffer,
        n: u32,
        levels: &[Buffer],
        dummy: &Buffer,
    ) -> Result<()> {
        if n == 0 {
            return Ok(());
        }
        let nb = n.div_ceil(kernels::SCAN_ITEMS);
        if nb == 1 {
            let push = [n, 0u32];
            return s.dispatch(
                &self.block,
                &[("data", data), ("sums", dummy)],
                bytemuck::bytes_of(&push),
                groups_for(1),
            );
        }
        let (sums, rest) = levels
            .split_first()
            .expect("scratch has a level per reduction");
        let push = [n, 1u32];
        s.dispatch(
            &self.block,
            &[("data", data), ("sums", sums)],
            bytemuck::bytes_of(&push),
            groups_for(nb),
        )?;
        self.level(s, sums, nb, rest, dummy)?;
        s.dispatch(
            &self.add,
            &[("data", data), ("sums", sums)],
            bytemuck::bytes_of(&n),
            groups_for(nb),
        )
    }
}
