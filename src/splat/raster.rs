//! The GPU rasterizer forward pass: project -> depth sort -> emit intersections -> stable tile
//! sort -> tile ranges -> segmented blend. Exact depth order (brush's two 32-bit sorts instead
//! of a 64-bit key), INRIA blending semantics, and no invocation loops past lavapipe's limit.
use super::cloud::Gaussians;
use super::scan::ScanScratch;
use super::sort::{RadixSort, SortScratch};
use crate::camera::Camera;
use crate::gpu::push_matches;
use crate::gpu::{
    groups_for, kernels, Buffer, BufferUsage, Context, GpuError, Kernel, Result, Stream, Timings,
};
use bytemuck::{Pod, Zeroable};
use std::sync::Mutex;

/// Threads per workgroup of the per-Gaussian and per-intersection kernels.
const WG: u32 = 128;

/// Camera as the projection kernels read it (`CameraData` in `glsl/raster.glsl`).
#[repr(C)]
#[derive(Debug, Clone, Copy, Pod, Zeroable)]
pub struct CameraData {
    pub row0: [f32; 4],
    pub row1: [f32; 4],
    pub row2: [f32; 4],
    pub campos: [f32; 4],
    pub focal: [f32; 2],
    pub size: [f32; 2],
}

impl CameraData {
    pub fn new(cam: &Camera) -> CameraData {
        let (r, t) = cam.world_to_camera();
        let row = |i: usize| [r[i][0] as f32, r[i][1] as f32, r[i][2] as f32, t[i] as f32];
        CameraData {
            row0: row(0),
            row1: row(1),
            row2: row(2),
            campos: [
                cam.position[0] as f32,
                cam.position[1] as f32,
                cam.position[2] as f32,
                0.0,
            ],
            focal: [cam.fx as f32, cam.fy as f32],
            size: [cam.width as f32, cam.height as f32],
        }
    }
}

#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct ProjectPush {
    cam: CameraData,
    n: u32,
    sh_degree: u32,
    tiles_x: u32,
    tiles_y: u32,
}
#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct EmitPush {
    n: u32,
    tiles_x: u32,
    num_tiles: u32,
}
#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct BlendPush {
    width: u32,
    height: u32,
    tiles_x: u32,
    seg_begin: u32,
    first: u32,
}
push_matches!(ProjectPush, PROJECT);
push_matches!(EmitPush, EMIT);
push_matches!(BlendPush, BLEND);
push_matches!(bytes 8, TILE_RANGES);
push_matches!(bytes 4, GATHER_COUNTS);

/// Gaussian parameters on the device.
pub struct GpuGaussians {
    pub means: Buffer,
    pub scales: Buffer,
    pub rotations: Buffer,
    pub opacities: Buffer,
    pub sh: Buffer,
    pub n: u32,
    pub sh_degree: u32,
}

impl GpuGaussians {
    /// Uploads `g` (checked for consistent array sizes).
    pub fn upload(ctx: &Context, g: &Gaussians) -> Result<GpuGaussians> {
        g.check().map_err(|msg| GpuError::Kernel {
            kernel: "upload gaussians".into(),
            msg,
        })?;
        Ok(GpuGaussians {
            means: Buffer::from_slice(ctx, "means", &g.means)?,
            scales: Buffer::from_slice(ctx, "log scales", &g.scales)?,
            rotations: Buffer::from_slice(ctx, "rotations", &g.rotations)?,
            opacities: Buffer::from_slice(ctx, "opacity logits", &g.opacities)?,
            sh: Buffer::from_slice(ctx, "sh", &g.sh)?,
            n: g.len() as u32,
            sh_degree: g.sh_degree,
        })
    }

    /// Reads the parameters back.
    pub fn download(&self) -> Result<Gaussians> {
        let n = self.n as usize;
        let k = super::cloud::sh_coeffs(self.sh_degree);
        Ok(Gaussians {
            means: self.means.read(n)?,
            scales: self.scales.read(n)?,
            rotations: self.rotations.read(n)?,
            opacities: self.opacities.read(n)?,
            sh: self.sh.read(n * k * 3)?,
            sh_degree: self.sh_degree,
        })
    }
}

/// Everything a forward pass leaves on the device, kept for the backward pass.
pub struct Frame {
    pub width: u32,
    pub height: u32,
    pub tiles_x: u32,
    pub tiles_y: u32,
    pub n: u32,
    /// Number of (tile, Gaussian) intersections.
    pub intersections: u32,
    /// Longest tile list.
    pub max_tile_len: u32,
    pub proj: Buffer,
    pub isect_ids: Buffer,
    pub ranges: Buffer,
    /// Per pixel: colour without background (rgb) and final transmittance T.
    pub color: Buffer,
    pub depth: Buffer,
    pub last: Buffer,
    pub background: [f32; 3],
    pub timings: Timings,
    /// A host-visible copy of `color`, made by [`Rasterizer::forward_into`] when asked.
    host: Option<Buffer>,
    /// Whether `host` holds this render's colour.
    host_fresh: bool,
}

/// A rendered image read back to the host, row-major.
#[derive(Debug, Clone)]
pub struct RenderOutput {
    pub width: u32,
    pub height: u32,
    /// Colour over the background.
    pub color: Vec<[f32; 3]>,
    pub transmittance: Vec<f32>,
    pub depth: Vec<f32>,
}

impl Frame {
    /// An empty frame for [`Rasterizer::forward_into`] (its buffers grow on the first render).
    pub fn new(ctx: &Context) -> Result<Frame> {
        let b = |name: &str| Buffer::new(ctx, name, 16, BufferUsage::Device);
        Ok(Frame {
            width: 0,
            height: 0,
            tiles_x: 0,
            tiles_y: 0,
            n: 0,
            intersections: 0,
            max_tile_len: 0,
            proj: b("projected")?,
            isect_ids: b("intersection gaussians")?,
            ranges: b("tile ranges")?,
            color: b("pixel colour and T")?,
            depth: b("pixel depth")?,
            last: b("pixel last contributor")?,
            background: [0.0; 3],
            timings: Timings::default(),
            host: None,
            host_fresh: false,
        })
    }

    /// Colour and transmittance per pixel: from the host copy when the render made one, else
    /// read back from the device.
    fn colour_and_t(&self) -> Result<Vec<[f32; 4]>> {
        let np = (self.width * self.height) as usize;
        match &self.host {
            Some(h) if self.host_fresh => h.read(np),
            _ => self.color.read(np),
        }
    }

    /// The image over the background, row-major (one readback, or none after a render that
    /// copied it).
    pub fn colour(&self) -> Result<Vec<[f32; 3]>> {
        let bg = self.background;
        Ok(self
            .colour_and_t()?
            .iter()
            .map(|p| {
                [
                    p[0] + p[3] * bg[0],
                    p[1] + p[3] * bg[1],
                    p[2] + p[3] * bg[2],
                ]
            })
            .collect())
    }

    /// Reads the image back.
    pub fn read(&self) -> Result<RenderOutput> {
        let np = (self.width * self.height) as usize;
        let c = self.colour_and_t()?;
        let bg = self.background;
        Ok(RenderOutput {
            width: self.width,
            height: self.height,
            color: c
                .iter()
                .map(|p| {
                    [
                        p[0] + p[3] * bg[0],
                        p[1] + p[3] * bg[1],
                        p[2] + p[3] * bg[2],
                    ]
                })
                .collect(),
            transmittance: c.iter().map(|p| p[3]).collect(),
            depth: self.depth.read(np)?,
        })
    }
}

/// The forward kernels.
pub struct Rasterizer {
    project: Kernel,
    gather: Kernel,
    emit: Kernel,
    ranges: Kernel,
    blend: Kernel,
    sort: RadixSort,
    timed: bool,
    /// Buffers a pass needs only while it runs, kept between passes.
    scratch: Mutex<Scratch>,
}

/// The forward pass's transient buffers, grown on demand and reused by every later pass.
#[derive(Default)]
struct Scratch {
    rects: Option<Buffer>,
    depth_keys: Option<Buffer>,
    ids: Option<Buffer>,
    counts: Option<Buffer>,
    offsets: Option<Buffer>,
    host: Option<Buffer>,
    depth_sort: Option<SortScratch>,
    scan: Option<ScanScratch>,
    tile_keys: Option<Buffer>,
    tile_sort: Option<SortScratch>,
}

/// A capacity with room to spare: intersection counts change a little from view to view and
/// Gaussian counts with densification, so a buffer grown to exactly the size would be regrown
/// at almost every pass.
fn headroom(count: u32) -> u32 {
    count.saturating_add(count / 4).max(1)
}

/// [`headroom`] in bytes, held to the device's storage-buffer range (128 MiB on lavapipe).
fn headroom_bytes(ctx: &Context, bytes: u64) -> u64 {
    (bytes + bytes / 4)
        .min(ctx.info().max_storage_buffer_range)
        .max(bytes)
}

/// The buffer in `slot`, (re)allocated with headroom when absent or smaller than `bytes`.
fn grow<'a>(
    ctx: &Context,
    slot: &'a mut Option<Buffer>,
    name: &str,
    bytes: u64,
    usage: BufferUsage,
) -> Result<&'a Buffer> {
    if slot.as_ref().is_none_or(|b| b.size() < bytes) {
        // The old buffer goes first, so the two never hold memory together.
        *slot = None;
        *slot = Some(Buffer::new(ctx, name, headroom_bytes(ctx, bytes), usage)?);
    }
    Ok(slot.as_ref().expect("just made"))
}

/// [`grow`] for a frame's buffer, which always exists.
fn reserve(
    ctx: &Context,
    buf: &mut Buffer,
    name: &str,
    bytes: u64,
    usage: BufferUsage,
) -> Result<()> {
    if buf.size() < bytes {
        *buf = Buffer::new(ctx, name, headroom_bytes(ctx, bytes), usage)?;
    }
    Ok(())
}

/// Sort scratch in `slot` for at least `count` pairs.
fn grow_sort<'a>(
    ctx: &Context,
    slot: &'a mut Option<SortScratch>,
    count: u32,
) -> Result<&'a SortScratch> {
    if slot.as_ref().is_none_or(|s| s.capacity() < count) {
        *slot = None;
        *slot = Some(SortScratch::new(ctx, headroom(count))?);
    }
    Ok(slot.as_ref().expect("just made"))
}

fn bits_for(max_value: u32) -> u32 {
    32 - max_value.leading_zeros()
}

/// How many pixels one invocation of the blend kernels (forward and backward) handles.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BlendWidth {
    /// One pixel per invocation, 256 per tile: for GPUs, where occupancy matters.
    One,
    /// `BLEND_PIXELS` pixels per invocation (the `_wide` kernels): for CPU devices (lavapipe),
    /// where each splat broadcast and subgroup reduction is a loop over the lanes and is shared
    /// by that many pixels.
    Wide,
}

impl BlendWidth {
    /// The width for a device: wide on CPU devices, unless `DREAMSCENE_BLEND` says `one` or `wide`.
    pub fn for_device(ctx: &Context) -> BlendWidth {
        let choices = [("one", BlendWidth::One), ("wide", BlendWidth::Wide)];
        crate::util::env_choice("DREAMSCENE_BLEND", &choices).unwrap_or(
            if ctx.info().device_type == "CPU" {
                BlendWidth::Wide
            } else {
                BlendWidth::One
            },
        )
    }

    /// Invocations per 16x16 tile workgroup.
    pub fn workgroup_size(self) -> u32 {
        match self {
            BlendWidth::One => kernels::TILE * kernels::TILE,
            BlendWidth::Wide => kernels::TILE * kernels::TILE / kernels::BLEND_PIXELS,
        }
    }
}

impl Rasterizer {
    /// The rasterizer with the blend width suited to the device ([`BlendWidth::for_device`]).
    pub fn new(ctx: &Context) -> Result<Rasterizer> {
        Self::with_width(ctx, BlendWidth::for_device(ctx))
    }

    /// The rasterizer with a given blend width (both give the same image).
    pub fn with_width(ctx: &Context, width: BlendWidth) -> Result<Rasterizer> {
        let blend = match width {
            BlendWidth::One => kernels::BLEND,
            BlendWidth::Wide => kernels::BLEND_WIDE,
        };
        Ok(Rasterizer {
            project: Kernel::new(ctx, kernels::PROJECT, WG)?,
            gather: Kernel::new(ctx, kernels::GATHER_COUNTS, WG)?,
            emit: Kernel::new(ctx, kernels::EMIT, WG)?,
            ranges: Kernel::new(ctx, kernels::TILE_RANGES, WG)?,
            blend: Kernel::new(ctx, blend, width.workgroup_size())?,
            sort: RadixSort::new(ctx)?,
            timed: false,
            scratch: Mutex::new(Scratch::default()),
        })
    }

    /// Records per-dispatch GPU times into each frame's `timings`.
    pub fn set_timed(&mut self, timed: bool) {
        self.timed = timed;
    }

    fn stream(&self, ctx: &Context, n: u32) -> Result<Stream> {
        if self.timed {
            Stream::timed(ctx, n)
        } else {
            Stream::new(ctx)
        }
    }

    /// Renders `g` from `cam` over `background` into a new frame.
    pub fn forward(
        &self,
        ctx: &Context,
        g: &GpuGaussians,
        cam: &Camera,
        background: [f32; 3],
    ) -> Result<Frame> {
        let mut frame = Frame::new(ctx)?;
        self.forward_into(ctx, g, cam, background, &mut frame, false)?;
        Ok(frame)
    }

    /// Renders `g` from `cam` over `background` into `frame`, reusing its buffers (grown when
    /// too small) and the rasterizer's scratch, so that a loop rendering into the same frames
    /// allocates nothing once the sizes settle. With `read_colour`, the image is also copied to
    /// host-visible memory in the same submission, for [`Frame::colour`].
    pub fn forward_into(
        &self,
        ctx: &Context,
        g: &GpuGaussians,
        cam: &Camera,
        background: [f32; 3],
        frame: &mut Frame,
        read_colour: bool,
    ) -> Result<()> {
        let mut guard = self.scratch.lock().unwrap_or_else(|e| e.into_inner());
        let sc = &mut *guard;
        let n = g.n;
        let tiles_x = cam.width.div_ceil(kernels::TILE);
        let tiles_y = cam.height.div_ceil(kernels::TILE);
        let num_tiles = tiles_x * tiles_y;
        let dev = BufferUsage::Device;
        let n64 = n as u64;
        reserve(ctx, &mut frame.proj, "projected", n64 * 48, dev)?;
        let rects = grow(ctx, &mut sc.rects, "tile rects", n64 * 8, dev)?;
        let depth_keys = grow(ctx, &mut sc.depth_keys, "depth keys", n64 * 4, dev)?;
        let ids = grow(ctx, &mut sc.ids, "depth order", n64 * 4, dev)?;
        let counts = grow(ctx, &mut sc.counts, "tile counts", n64 * 4, dev)?;
        let offsets = grow(
            ctx,
            &mut sc.offsets,
            "intersection offsets",
            (n64 + 1) * 4,
            dev,
        )?;
        // Host-visible: the intersection count (word 0), then the tile ranges.
        let host = grow(
            ctx,
            &mut sc.host,
            "forward readback",
            8 + num_tiles as u64 * 8,
            BufferUsage::Readback,
        )?;
        let depth_sort = grow_sort(ctx, &mut sc.depth_sort, n)?;
        if sc.scan.as_ref().is_none_or(|s| s.capacity() < n + 1) {
            sc.scan = None;
            sc.scan = Some(ScanScratch::new(ctx, headroom(n + 1))?);
        }
        let scan_scratch = sc.scan.as_ref().expect("just made");
        let mut timings = Timings::default();

        let mut s = self.stream(ctx, 64)?;
        let push = ProjectPush {
            cam: CameraData::new(cam),
            n,
            sh_degree: g.sh_degree,
            tiles_x,
            tiles_y,
        };
        s.dispatch(
            &self.project,
            &[
                ("means", &g.means),
                ("scales", &g.scales),
                ("rotations", &g.rotations),
                ("opacities", &g.opacities),
                ("sh", &g.sh),
                ("proj", &frame.proj),
                ("rects", rects),
                ("depth_keys", depth_keys),
                ("ids", ids),
                ("counts", counts),
            ],
            bytemuck::bytes_of(&push),
            groups_for(n.div_ceil(WG)),
        )?;
        self.sort
            .record(&mut s, depth_keys, ids, n, 32, depth_sort)?;
        s.dispatch(
            &self.gather,
            &[("ids", ids), ("counts", counts), ("offsets", offsets)],
            bytemuck::bytes_of(&n),
            groups_for((n + 1).div_ceil(WG)),
        )?;
        self.sort
            .scan()
            .record(&mut s, offsets, n + 1, scan_scratch)?;
        s.copy_region(offsets, n64 * 4, host, 0, 4);
        timings.entries.extend(s.submit()?.entries);
        let m = host.read::<u32>(1)?[0];

        let tile_keys = grow(
            ctx,
            &mut sc.tile_keys,
            "intersection tiles",
            m as u64 * 4,
            dev,
        )?;
        let tile_sort = grow_sort(ctx, &mut sc.tile_sort, m)?;
        reserve(
            ctx,
            &mut frame.isect_ids,
            "intersection gaussians",
            m as u64 * 4,
            dev,
        )?;
        reserve(
            ctx,
            &mut frame.ranges,
            "tile ranges",
            num_tiles as u64 * 8,
            dev,
        )?;
        let mut s = self.stream(ctx, 64)?;
        s.fill(&frame.ranges, 0);
        let push = EmitPush {
            n,
            tiles_x,
            num_tiles,
        };
        s.dispatch(
            &self.emit,
            &[
                ("ids", ids),
                ("counts", counts),
                ("offsets", offsets),
                ("proj", &frame.proj),
                ("rects", rects),
                ("tile_keys", tile_keys),
                ("isect_ids", &frame.isect_ids),
            ],
            bytemuck::bytes_of(&push),
            groups_for(n.div_ceil(WG)),
        )?;
        self.sort.record(
            &mut s,
            tile_keys,
            &frame.isect_ids,
            m,
            bits_for(num_tiles),
            tile_sort,
        )?;
        let push = [m, num_tiles];
        s.dispatch(
            &self.ranges,
            &[("tile_keys", tile_keys), ("ranges", &frame.ranges)],
            bytemuck::bytes_of(&push),
            groups_for(m.div_ceil(WG)),
        )?;
        s.copy_region(&frame.ranges, 0, host, 8, num_tiles as u64 * 8);
        timings.entries.extend(s.submit()?.entries);
        let r: Vec<[u32; 2]> = host.read_at(1, num_tiles as usize)?;
        let max_tile_len = r
            .iter()
            .map(|x| x[1].saturating_sub(x[0]))
            .max()
            .unwrap_or(0);

        let np = cam.width as u64 * cam.height as u64;
        reserve(ctx, &mut frame.color, "pixel colour and T", np * 16, dev)?;
        reserve(ctx, &mut frame.depth, "pixel depth", np * 4, dev)?;
        reserve(ctx, &mut frame.last, "pixel last contributor", np * 4, dev)?;
        let segments = max_tile_len.div_ceil(kernels::SEGMENT).max(1);
        let mut s = self.stream(ctx, segments + 1)?;
        for seg in 0..segments {
            let push = BlendPush {
                width: cam.width,
                height: cam.height,
                tiles_x,
                seg_begin: seg * kernels::SEGMENT,
                first: (seg == 0) as u32,
            };
            s.dispatch(
                &self.blend,
                &[
                    ("proj", &frame.proj),
                    ("isect_ids", &frame.isect_ids),
                    ("ranges", &frame.ranges),
                    ("color", &frame.color),
                    ("depth", &frame.depth),
                    ("last", &frame.last),
                ],
                bytemuck::bytes_of(&push),
                groups_for(num_tiles),
            )?;
        }
        if read_colour {
            let host = match frame.host.take() {
                Some(b) if b.size() >= np * 16 => b,
                _ => Buffer::new(
                    ctx,
                    "pixel colour (host)",
                    headroom_bytes(ctx, np * 16),
                    BufferUsage::Readback,
                )?,
            };
            s.copy(&frame.color, &host, np * 16);
            frame.host = Some(host);
        }
        frame.host_fresh = read_colour;
        timings.entries.extend(s.submit()?.entries);
        frame.width = cam.width;
        frame.height = cam.height;
        frame.tiles_x = tiles_x;
        frame.tiles_y = tiles_y;
        frame.n = n;
        frame.intersections = m;
        frame.max_tile_len = max_tile_len;
        frame.background = background;
        frame.timings = timings;
        Ok(())
    }

    /// Renders host Gaussians: upload, forward, read back.
    pub fn render(
        &self,
        ctx: &Context,
        g: &Gaussians,
        cam: &Camera,
        background: [f32; 3],
    ) -> Result<RenderOutput> {
        let gg = GpuGaussians::upload(ctx, g)?;
        self.forward(ctx, &gg, cam, background)?.read()
    }
}
