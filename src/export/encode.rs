//! Video files from RGB frames: H.264 in an MP4 container (Cisco's OpenH264, built from its
//! bundled source by the `openh264` crate, muxed by the pure-Rust `mp4` crate) or an animated
//! GIF (`image`). Each writer fills a temporary sibling of its target and renames it on
//! [`VideoSink::finish`], so a failed or interrupted encode never leaves a half file.
use image::codecs::gif::{GifEncoder, Repeat};
use image::{Delay, Frame, RgbaImage};
use openh264::encoder::{
    BitRate, Encoder, EncoderConfig, FrameRate, FrameType, IntraFramePeriod, RateControlMode,
};
use openh264::formats::{RgbSliceU8, YUVBuffer};
use openh264::OpenH264API;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

/// Why a video cannot be written.
#[derive(Debug, thiserror::Error)]
pub enum EncodeError {
    #[error("{path}: {msg}")]
    Io { path: String, msg: String },
    #[error("H.264 encoder: {0}")]
    H264(String),
    #[error("MP4 muxer: {0}")]
    Mp4(String),
    #[error("GIF encoder: {0}")]
    Gif(String),
    #[error("{0}")]
    Invalid(String),
}

pub type Result<T> = std::result::Result<T, EncodeError>;

/// The container a file name asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Container {
    Mp4,
    Gif,
}

impl Container {
    /// From the extension of `path` (`.mp4` or `.gif`, any case).
    pub fn of(path: &Path) -> Result<Container> {
        match path
            .extension()
            .and_then(|e| e.to_str())
            .map(|e| e.to_ascii_lowercase())
            .as_deref()
        {
            Some("mp4") => Ok(Container::Mp4),
            Some("gif") => Ok(Container::Gif),
            _ => Err(EncodeError::Invalid(format!(
                "{}: the output must end in .mp4 or .gif",
                path.display()
            ))),
        }
    }
}

/// Receives frames of one size, in order, as tightly packed 8-bit RGB rows.
pub trait VideoSink {
    fn push(&mut self, rgb: &[u8]) -> Result<()>;
    /// Completes the file and moves it into place.
    fn finish(self: Box<Self>) -> Result<()>;
}

/// A writer for `path` in the container its extension names. MP4 needs even sides (H.264's
/// 4:2:0 chroma halves each side).
pub fn open(path: &Path, width: u32, height: u32, fps: f64) -> Result<Box<dyn VideoSink>> {
    if !(fps.is_finite() && fps > 0.0 && fps <= 240.0) {
        return Err(EncodeError::Invalid(format!(
            "frame rate {fps}: give 0 < fps <= 240"
        )));
    }
    Ok(match Container::of(path)? {
        Container::Mp4 => Box::new(Mp4Sink::new(path, width, height, fps)?),
        Container::Gif => Box::new(GifSink::new(path, width, height, fps)?),
    })
}

/// A temporary sibling of `path`, removed on drop unless it was renamed into place.
struct TempFile {
    tmp: PathBuf,
    path: PathBuf,
    done: bool,
}

impl TempFile {
    fn create(path: &Path) -> Result<(TempFile, File)> {
        let mut name = path.file_name().unwrap_or_default().to_os_string();
        name.push(".tmp");
        let tmp = path.with_file_name(name);
        let f = File::create(&tmp).map_err(|e| io_err(&tmp, e))?;
        Ok((
            TempFile {
                tmp,
                path: path.to_path_buf(),
                done: false,
            },
            f,
        ))
    }

    fn commit(mut self) -> Result<()> {
        std::fs::rename(&self.tmp, &self.path).map_err(|e| io_err(&self.path, e))?;
        self.done = true;
        Ok(())
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        if !self.done {
            let _ = std::fs::remove_file(&self.tmp);
        }
    }
}

fn io_err(path: &Path, e: impl std::fmt::Display) -> EncodeError {
    EncodeError::Io {
        path: path.display().to_string(),
        msg: e.to_string(),
    }
}

fn check_frame(rgb: &[u8], w: u32, h: u32) -> Result<()> {
    if rgb.len() != (w * h * 3) as usize {
        return Err(EncodeError::Invalid(format!(
            "frame of {} bytes for {w}x{h} RGB",
            rgb.len()
        )));
    }
    Ok(())
}

/// Time units per second of the MP4 movie and track (90 kHz, the usual video clock).
const TIMESCALE: u32 = 90_000;
/// An IDR (seekable) frame at least every this many seconds.
const KEYFRAME_SECONDS: f64 = 2.0;
/// Target bits per pixel per frame: 0.2 keeps the noisy texture of splat renders sharp at
/// moderate sizes (640x480 at 30 fps: 1.8 Mbit/s).
const BITS_PER_PIXEL: f64 = 0.2;

struct Mp4Sink {
    encoder: Encoder,
    yuv: YUVBuffer,
    writer: Option<mp4::Mp4Writer<BufWriter<File>>>,
    /// The file until the track is added (it needs the first frame's SPS and PPS).
    file: Option<BufWriter<File>>,
    tmp: TempFile,
    width: u32,
    height: u32,
    fps: f64,
    frames: u64,
}

impl Mp4Sink {
    fn new(path: &Path, width: u32, height: u32, fps: f64) -> Result<Mp4Sink> {
        if !width.is_multiple_of(2) || !height.is_multiple_of(2) || width < 16 || height < 16 {
            return Err(EncodeError::Invalid(format!(
                "MP4 size {width}x{height}: H.264 needs even sides of at least 16 pixels"
            )));
        }
        let bps = (BITS_PER_PIXEL * (width * height) as f64 * fps).clamp(1e5, 5e7) as u32;
        let config = EncoderConfig::new()
            .bitrate(BitRate::from_bps(bps))
            .max_frame_rate(FrameRate::from_hz(fps as f32))
            .rate_control_mode(RateControlMode::Quality)
            // Every rendered frame must reach the file: a skipped frame would shorten the video.
            .skip_frames(false)
            .intra_frame_period(IntraFramePeriod::from_num_frames(
                (KEYFRAME_SECONDS * fps).round().max(1.0) as u32,
            ));
        let encoder = Encoder::with_api_config(OpenH264API::from_source(), config)
            .map_err(|e| EncodeError::H264(e.to_string()))?;
        let (tmp, f) = TempFile::create(path)?;
        Ok(Mp4Sink {
            encoder,
            yuv: YUVBuffer::new(width as usize, height as usize),
            writer: None,
            file: Some(BufWriter::new(f)),
            tmp,
            width,
            height,
            fps,
            frames: 0,
        })
    }

    fn start(&mut self, sps: &[u8], pps: &[u8]) -> Result<()> {
        let brand = |s: &str| {
            s.parse::<mp4::FourCC>()
                .map_err(|e| EncodeError::Mp4(e.to_string()))
        };
        let config = mp4::Mp4Config {
            major_brand: brand("isom")?,
            minor_version: 512,
            compatible_brands: vec![
                brand("isom")?,
                brand("iso2")?,
                brand("avc1")?,
                brand("mp41")?,
            ],
            timescale: TIMESCALE,
        };
        let file = self
            .file
            .take()
            .ok_or_else(|| EncodeError::Mp4("started twice".into()))?;
        let mut w = mp4::Mp4Writer::write_start(file, &config)
            .map_err(|e| EncodeError::Mp4(e.to_string()))?;
        let mut track = mp4::TrackConfig::from(mp4::MediaConfig::AvcConfig(mp4::AvcConfig {
            width: self.width as u16,
            height: self.height as u16,
            seq_param_set: sps.to_vec(),
            pic_param_set: pps.to_vec(),
        }));
        track.timescale = TIMESCALE;
        w.add_track(&track)
            .map_err(|e| EncodeError::Mp4(e.to_string()))?;
        self.writer = Some(w);
        Ok(())
    }
}

/// The NAL units of an Annex-B stream without their start codes.
fn nal_units(annex_b: &[u8]) -> Vec<&[u8]> {
    openh264::nal_units(annex_b)
        .map(|n| {
            let skip = n.iter().take_while(|b| **b == 0).count();
            // The start code is 0x000001 or 0x00000001; what follows is the NAL itself.
            if n.get(skip) == Some(&1) {
                &n[skip + 1..]
            } else {
                n
            }
        })
        .filter(|n| !n.is_empty())
        .collect()
}

impl VideoSink for Mp4Sink {
    fn push(&mut self, rgb: &[u8]) -> Result<()> {
        check_frame(rgb, self.width, self.height)?;
        let (w, h) = (self.width as usize, self.height as usize);
        self.yuv.read_rgb8(RgbSliceU8::new(rgb, (w, h)));
        let bits = self
            .encoder
            .encode(&self.yuv)
            .map_err(|e| EncodeError::H264(e.to_string()))?;
        let sync = matches!(bits.frame_type(), FrameType::IDR);
        if matches!(bits.frame_type(), FrameType::Skip | FrameType::Invalid) {
            return Err(EncodeError::H264(format!(
                "frame {} was not encoded ({:?})",
                self.frames,
                bits.frame_type()
            )));
        }
        let stream = bits.to_vec();
        let nals = nal_units(&stream);
        if self.writer.is_none() {
            let find = |t: u8| nals.iter().find(|n| n[0] & 0x1f == t).copied();
            let (Some(sps), Some(pps)) = (find(7), find(8)) else {
                return Err(EncodeError::H264(
                    "the first frame carries no SPS/PPS".into(),
                ));
            };
            self.start(sps, pps)?;
        }
        // AVC samples: every NAL but parameter sets, each behind its 4-byte big-endian length.
        let mut sample = Vec::with_capacity(stream.len() + 16);
        for n in nals.iter().filter(|n| !matches!(n[0] & 0x1f, 7 | 8)) {
            sample.extend_from_slice(&(n.len() as u32).to_be_bytes());
            sample.extend_from_slice(n);
        }
        let at = |i: u64| (i as f64 * TIMESCALE as f64 / self.fps).round() as u64;
        let (start, end) = (at(self.frames), at(self.frames + 1));
        let writer = self
            .writer
            .as_mut()
            .ok_or_else(|| EncodeError::Mp4("no track".into()))?;
        writer
            .write_sample(
                1,
                &mp4::Mp4Sample {
                    start_time: start,
                    duration: (end - start) as u32,
                    rendering_offset: 0,
                    is_sync: sync,
                    bytes: sample.into(),
                },
            )
            .map_err(|e| EncodeError::Mp4(e.to_string()))?;
        self.frames += 1;
        Ok(())
    }

    fn finish(mut self: Box<Self>) -> Result<()> {
        let mut w = self
            .writer
            .take()
            .ok_or_else(|| EncodeError::Invalid("a video needs at least one frame".into()))?;
        w.write_end().map_err(|e| EncodeError::Mp4(e.to_string()))?;
        let mut f = w.into_writer();
        f.flush().map_err(|e| io_err(&self.tmp.tmp, e))?;
        let f = f.into_inner().map_err(|e| io_err(&self.tmp.tmp, e))?;
        f.sync_all().map_err(|e| io_err(&self.tmp.tmp, e))?;
        drop(f);
        self.tmp.commit()
    }
}

/// The GIF bytes, shared with the encoder, which writes its trailer only when dropped.
#[derive(Clone, Default)]
struct SharedBuf(Arc<Mutex<Vec<u8>>>);

impl Write for SharedBuf {
    fn write(&mut self, b: &[u8]) -> std::io::Result<usize> {
        self.0
            .lock()
            .map_err(|_| std::io::Error::other("GIF buffer poisoned"))?
            .extend_from_slice(b);
        Ok(b.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

struct GifSink {
    encoder: GifEncoder<SharedBuf>,
    buf: SharedBuf,
    path: PathBuf,
    width: u32,
    height: u32,
    delay: Delay,
    frames: u64,
}

/// NeuQuant sampling factor of the GIF palette (1 best, 30 fastest); 10 is the encoder's
/// usual trade.
const GIF_SPEED: i32 = 10;

impl GifSink {
    fn new(path: &Path, width: u32, height: u32, fps: f64) -> Result<GifSink> {
        if width > u16::MAX as u32 || height > u16::MAX as u32 {
            return Err(EncodeError::Invalid(format!(
                "GIF size {width}x{height} too large"
            )));
        }
        let buf = SharedBuf::default();
        let mut encoder = GifEncoder::new_with_speed(buf.clone(), GIF_SPEED);
        encoder
            .set_repeat(Repeat::Infinite)
            .map_err(|e| EncodeError::Gif(e.to_string()))?;
        // GIF delays are whole centiseconds; the decoder's rounding is the format's, not ours.
        let delay = Delay::from_numer_denom_ms(1000, (fps.round() as u32).max(1));
        Ok(GifSink {
            encoder,
            buf,
            path: path.to_path_buf(),
            width,
            height,
            delay,
            frames: 0,
        })
    }
}

impl VideoSink for GifSink {
    fn push(&mut self, rgb: &[u8]) -> Result<()> {
        check_frame(rgb, self.width, self.height)?;
        let rgba: Vec<u8> = rgb
            .chunks_exact(3)
            .flat_map(|p| [p[0], p[1], p[2], 255])
            .collect();
        let img = RgbaImage::from_raw(self.width, self.height, rgba)
            .ok_or_else(|| EncodeError::Gif("frame buffer size".into()))?;
        self.encoder
            .encode_frame(Frame::from_parts(img, 0, 0, self.delay))
            .map_err(|e| EncodeError::Gif(e.to_string()))?;
        self.frames += 1;
        Ok(())
    }

    fn finish(self: Box<Self>) -> Result<()> {
        if self.frames == 0 {
            return Err(EncodeError::Invalid(
                "a video needs at least one frame".into(),
            ));
        }
        let GifSink {
            encoder, buf, path, ..
        } = *self;
        drop(encoder);
        let bytes = std::mem::take(
            &mut *buf
                .0
                .lock()
                .map_err(|_| EncodeError::Gif("buffer poisoned".into()))?,
        );
        crate::util::write_atomic(&path, &bytes).map_err(|e| io_err(&path, e))
    }
}
