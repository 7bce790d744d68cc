//! A Stable Diffusion pipeline in the layout of Hugging Face Optimum's ONNX export
//! (`optimum-cli export onnx --model stabilityai/stable-diffusion-2-1-base DIR`):
//!
//! ```text
//! DIR/model_index.json
//! DIR/scheduler/scheduler_config.json
//! DIR/tokenizer/{vocab.json, merges.txt, special_tokens_map.json, tokenizer_config.json}
//! DIR/text_encoder/model.onnx        input_ids → last_hidden_state (, pooler_output)
//! DIR/unet/model.onnx (+ model.onnx_data)  sample, timestep, encoder_hidden_states → out_sample
//! DIR/vae_encoder/model.onnx         sample → latent_sample | latent_parameters (mean, logvar)
//! DIR/vae_decoder/model.onnx         latent_sample → sample
//! DIR/taesd_encoder/, taesd_decoder/ optional tiny autoencoder (latents already scaled)
//! ```
//!
//! fp32 and fp16 exports both load (inputs and outputs are converted at the boundary). Names, ranks
//! and element types are checked on load; a mismatch is an error naming the file.
use super::guidance::{Cond, NoisePredictor, ViewsPredictor};
use super::runtime::{Data, OnnxModel, Output, PortSpec, Provider};
use super::schedule::{Schedule, SchedulerConfig};
use super::tokenizer::ClipTokenizer;
use ort::value::TensorElementType as T;
use std::path::{Path, PathBuf};
use std::time::Instant;

const FLOAT: &[T] = &[T::Float32, T::Float16];

/// How to run the models.
#[derive(Debug, Clone, Copy, Default)]
pub struct ModelOptions {
    pub provider: Provider,
    /// Intra-op threads (ONNX Runtime's default when `None`).
    pub threads: Option<usize>,
}

/// Which autoencoder a call uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Codec {
    /// The pipeline's VAE.
    Vae,
    /// The tiny autoencoder when the directory has one, else the VAE.
    Fast,
}

struct Autoencoder {
    encoder: Option<OnnxModel>,
    decoder: OnnxModel,
    /// Latent = encoder mean × scaling; decoder input = latent / scaling.
    scaling: f64,
}

/// Text embeddings of one prompt: `seq × hidden` values.
#[derive(Debug, Clone, PartialEq)]
pub struct Embedding {
    pub data: Vec<f32>,
    pub seq: usize,
    pub hidden: usize,
}

/// Wall time spent inside ONNX Runtime running each model (seconds), the host's conversions
/// around those runs, and the UNet's runs and items, since the last
/// [`StableDiffusion::take_times`]: the split of a prior's time that `bench --generate` reports.
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize)]
pub struct ModelTimes {
    /// ONNX Runtime's `session.run` of the text encoder.
    pub text_encoder: f64,
    /// ONNX Runtime's `session.run` of the UNet.
    pub unet: f64,
    /// ONNX Runtime's `session.run` of the autoencoder's encoder and decoder (the VAE or the
    /// tiny one).
    pub autoencoder: f64,
    /// Host work preparing the models' inputs and reading their outputs: f32 ↔ f16, batching
    /// the UNet's inputs, scaling latents, the image layout changes around the autoencoder and
    /// the finiteness check of outputs.
    pub conversions: f64,
    pub unet_runs: usize,
    pub unet_items: usize,
}

/// A loaded pipeline.
pub struct StableDiffusion {
    pub dir: PathBuf,
    pub tokenizer: ClipTokenizer,
    pub schedule: Schedule,
    pub latent_channels: usize,
    text_encoder: OnnxModel,
    unet: OnnxModel,
    vae: Autoencoder,
    fast: Option<Autoencoder>,
    opts: ModelOptions,
    /// UNet run sizes (latent size, batch) the provider probe has passed.
    probed: Vec<((usize, usize), usize)>,
    /// The most items one UNet run takes (the probe's split), none when unlimited.
    max_batch: Option<usize>,
    /// A cap on the items of one UNet run set by the caller ([`Self::set_unet_max_batch`]).
    cap: Option<usize>,
    /// Provider probes run ([`Self::probes_run`]).
    probes: usize,
    times: ModelTimes,
}

fn read_json(path: &Path) -> Result<serde_json::Value, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    serde_json::from_str(&text).map_err(|e| format!("{}: malformed JSON: {e}", path.display()))
}

fn load_autoencoder(
    dir: &Path,
    enc: &str,
    dec: &str,
    default_scaling: f64,
    opts: &ModelOptions,
) -> Result<Autoencoder, String> {
    let cfg = dir.join(dec).join("config.json");
    let scaling = if cfg.is_file() {
        read_json(&cfg)?
            .get("scaling_factor")
            .and_then(|v| v.as_f64())
            .unwrap_or(default_scaling)
    } else {
        default_scaling
    };
    if !(scaling.is_finite() && scaling > 0.0) {
        return Err(format!(
            "{}: scaling_factor must be positive",
            cfg.display()
        ));
    }
    let decoder = OnnxModel::load(
        &dir.join(dec).join("model.onnx"),
        opts.provider,
        opts.threads,
        &[PortSpec {
            names: &["latent_sample"],
            ranks: &[4],
            types: FLOAT,
        }],
        &[PortSpec {
            names: &["sample"],
            ranks: &[4],
            types: FLOAT,
        }],
    )?;
    let enc_path = dir.join(enc).join("model.onnx");
    let encoder = if enc_path.is_file() {
        Some(OnnxModel::load(
            &enc_path,
            opts.provider,
            opts.threads,
            &[PortSpec {
                names: &["sample"],
                ranks: &[4],
                types: FLOAT,
            }],
            &[PortSpec {
                names: &["latent_sample", "latent_parameters"],
                ranks: &[4],
                types: FLOAT,
            }],
        )?)
    } else {
        None
    };
    Ok(Autoencoder {
        encoder,
        decoder,
        scaling,
    })
}

impl StableDiffusion {
    /// Checks, without loading anything, that `dir` looks like a Stable Diffusion ONNX export
    /// (its index and the three models it needs), so a command refuses before any work.
    pub fn check_dir(dir: &Path) -> Result<(), String> {
        let shown = dir.display();
        if !dir.is_dir() {
            return Err(format!("{shown}: model directory not found"));
        }
        let index = dir.join("model_index.json");
        if !index.is_file() {
            return Err(format!(
                "{shown}: not a Stable Diffusion ONNX export (model_index.json missing); export one \
                 with `optimum-cli export onnx --model stabilityai/stable-diffusion-2-1-base DIR`"
            ));
        }
        read_json(&index)?;
        for sub in ["text_encoder", "unet", "vae_decoder"] {
            let p = dir.join(sub).join("model.onnx");
            if !p.is_file() {
                return Err(format!("{}: missing", p.display()));
            }
        }
        Ok(())
    }

    /// Opens and checks a model directory.
    pub fn open(dir: &Path, opts: &ModelOptions) -> Result<StableDiffusion, String> {
        let opts = &ModelOptions {
            provider: opts.provider.resolved(),
            ..*opts
        };
        Self::check_dir(dir)?;
        let shown = dir.display();
        let tokenizer = ClipTokenizer::load(&dir.join("tokenizer"))?;
        let sched_path = dir.join("scheduler/scheduler_config.json");
        let schedule = Schedule::new(SchedulerConfig::read(&sched_path)?)
            .map_err(|e| format!("{}: {e}", sched_path.display()))?;
        let text_encoder = OnnxModel::load(
            &dir.join("text_encoder/model.onnx"),
            opts.provider,
            opts.threads,
            &[PortSpec {
                names: &["input_ids"],
                ranks: &[2],
                types: &[T::Int32, T::Int64],
            }],
            &[PortSpec {
                names: &["last_hidden_state"],
                ranks: &[3],
                types: FLOAT,
            }],
        )?;
        let unet = OnnxModel::load(
            &dir.join("unet/model.onnx"),
            opts.provider,
            opts.threads,
            &[
                PortSpec {
                    names: &["sample"],
                    ranks: &[4],
                    types: FLOAT,
                },
                PortSpec {
                    names: &["timestep"],
                    ranks: &[0, 1],
                    types: &[T::Int64, T::Float32, T::Float16],
                },
                PortSpec {
                    names: &["encoder_hidden_states"],
                    ranks: &[3],
                    types: FLOAT,
                },
            ],
            &[PortSpec {
                names: &["out_sample"],
                ranks: &[4],
                types: FLOAT,
            }],
        )?;
        let latent_channels = match unet.inputs[0].dims[1] {
            c if c > 0 => c as usize,
            _ => 4,
        };
        // The text encoder's width must be what the UNet attends to, when both are static.
        let (te_w, un_w) = (text_encoder.outputs[0].dims[2], unet.inputs[2].dims[2]);
        if te_w > 0 && un_w > 0 && te_w != un_w {
            return Err(format!(
                "{shown}: the text encoder's hidden size {te_w} differs from the UNet's \
                 encoder_hidden_states width {un_w}"
            ));
        }
        let c = latent_channels as i64;
        unet.expect_dim(
            false,
            0,
            1,
            &[c],
            "the UNet predicts noise of its sample's shape",
        )?;
        text_encoder.expect_dim(
            true,
            0,
            1,
            &[tokenizer.max_length as i64],
            "the tokenizer's model_max_length",
        )?;
        let vae = load_autoencoder(dir, "vae_encoder", "vae_decoder", 0.18215, opts)?;
        let fast = if dir.join("taesd_decoder/model.onnx").is_file() {
            Some(load_autoencoder(
                dir,
                "taesd_encoder",
                "taesd_decoder",
                1.0,
                opts,
            )?)
        } else {
            None
        };
        for ae in std::iter::once(&vae).chain(fast.as_ref()) {
            ae.decoder
                .expect_dim(true, 0, 1, &[c], "the UNet's latent channels")?;
            ae.decoder.expect_dim(false, 0, 1, &[3], "RGB images")?;
            if let Some(e) = &ae.encoder {
                e.expect_dim(true, 0, 1, &[3], "RGB images")?;
                e.expect_dim(
                    false,
                    0,
                    1,
                    &[c, 2 * c],
                    "latents, or their mean and log-variance",
                )?;
            }
        }
        Ok(StableDiffusion {
            dir: dir.to_path_buf(),
            tokenizer,
            schedule,
            latent_channels,
            text_encoder,
            unet,
            vae,
            fast,
            opts: *opts,
            probed: vec![],
            max_batch: None,
            cap: None,
            probes: 0,
            times: ModelTimes::default(),
        })
    }

    /// The provider the models run on (the CPU after the probe fell back).
    pub fn provider(&self) -> Provider {
        self.opts.provider
    }

    /// How many times the provider probe has run (each builds its small graphs' sessions and
    /// runs them at the UNet's sizes).
    pub fn probes_run(&self) -> usize {
        self.probes
    }

    /// The most items one UNet run takes after the probe split the batch.
    pub fn unet_max_batch(&self) -> Option<usize> {
        self.max_batch
    }

    /// Caps the items of one UNet run (`None`: no cap beyond the probe's). A cap of one view's
    /// prompts runs the views of an iteration one by one, as before they were batched (for
    /// benchmarks and tests; the results are the same).
    pub fn set_unet_max_batch(&mut self, most: Option<usize>) {
        self.cap = most.map(|m| m.max(1));
    }

    /// The cap [`Self::set_unet_max_batch`] set, if any.
    pub fn unet_cap(&self) -> Option<usize> {
        self.cap
    }

    /// The time spent in each model since the last call, and resets it.
    pub fn take_times(&mut self) -> ModelTimes {
        std::mem::take(&mut self.times)
    }

    /// Adds host conversion time spent outside this pipeline's calls (a caller's layout changes
    /// of the images it encodes or decodes) to [`ModelTimes::conversions`].
    pub fn add_conversion_seconds(&mut self, seconds: f64) {
        self.times.conversions += seconds;
    }

    /// Makes every model's input conversion take `delay` longer
    /// ([`OnnxModel::plant_slow_conversion`]): a test hook for the timings' split.
    pub fn plant_slow_conversion(&mut self, delay: std::time::Duration) {
        let ae = |a: &mut Autoencoder| {
            a.decoder.plant_slow_conversion(delay);
            if let Some(e) = a.encoder.as_mut() {
                e.plant_slow_conversion(delay);
            }
        };
        ae(&mut self.vae);
        if let Some(f) = self.fast.as_mut() {
            ae(f);
        }
        self.text_encoder.plant_slow_conversion(delay);
        self.unet.plant_slow_conversion(delay);
    }

    /// Books one model call begun at `t0` whose ONNX Runtime part took `session` seconds: that
    /// part to the model's time, the rest to the conversions.
    fn book(&mut self, t0: Instant, session: f64, model: fn(&mut ModelTimes) -> &mut f64) {
        *model(&mut self.times) += session;
        self.times.conversions += (t0.elapsed().as_secs_f64() - session).max(0.0);
    }

    /// Probes a GPU provider at a UNet run of `batch` items at latent size `hw` (once per size)
    /// and acts on the verdict: splits later runs, or reloads every model on the CPU provider
    /// with a warning. The CPU provider is not probed.
    pub fn probe_provider(&mut self, hw: (usize, usize), batch: usize) -> Result<(), String> {
        self.probe_provider_with(hw, batch, None)
    }

    /// [`Self::probe_provider`] with a test hook that plants wrong provider outputs.
    pub fn probe_provider_with(
        &mut self,
        hw: (usize, usize),
        batch: usize,
        tamper: Option<super::probe::Tamper>,
    ) -> Result<(), String> {
        // A provider right at a batch is right at every smaller one of the same latent size
        // (the hazard is a tensor outgrowing a storage binding): the object's chain points, its
        // pseudo-ground truth and the null prompt's runs share one probe.
        if (self.opts.provider == Provider::Cpu && tamper.is_none())
            || self.probed.iter().any(|&(h, b)| h == hw && b >= batch)
        {
            return Ok(());
        }
        self.probes += 1;
        let sizes =
            super::probe::ProbeSizes::for_unet(&self.dir, hw, batch, self.precision() == "fp16");
        let report = super::probe::probe(self.opts.provider, &sizes, tamper)?;
        let name = format!("{:?}", self.opts.provider).to_lowercase();
        match report.verdict {
            super::probe::Verdict::Trust => {}
            super::probe::Verdict::Split { max_batch } => {
                eprintln!(
                    "warning: provider {name}: a {batch}-item UNet run is wrong on this device; \
                     running at most {max_batch} items at a time"
                );
                self.max_batch = Some(self.max_batch.map_or(max_batch, |m| m.min(max_batch)));
                self.probed.push((hw, max_batch));
            }
            super::probe::Verdict::Fallback { reason } => {
                eprintln!("warning: provider {name}: {reason}; using the CPU provider instead");
                let cpu = ModelOptions {
                    provider: Provider::Cpu,
                    ..self.opts
                };
                let (cap, times, probes) = (self.cap, self.times, self.probes);
                *self = StableDiffusion::open(&self.dir, &cpu)?;
                (self.cap, self.times, self.probes) = (cap, times, probes);
            }
        }
        self.probed.push((hw, batch));
        Ok(())
    }

    /// The latent size the UNet declares, else `unet/config.json`'s `sample_size`, else 64.
    pub fn default_latent_size(&self) -> (usize, usize) {
        let d = &self.unet.inputs[0].dims;
        if d[2] > 0 && d[3] > 0 {
            return (d[2] as usize, d[3] as usize);
        }
        let s = read_json(&self.dir.join("unet/config.json"))
            .ok()
            .and_then(|v| v.get("sample_size").and_then(|s| s.as_u64()))
            .filter(|s| *s > 0 && *s <= 512)
            .unwrap_or(64) as usize;
        (s, s)
    }

    /// Whether the VAE has its encoder (renders cannot be guided without one).
    pub fn has_vae_encoder(&self) -> bool {
        self.vae.encoder.is_some()
    }

    /// Whether a tiny autoencoder is present for [`Codec::Fast`].
    pub fn has_fast_codec(&self) -> bool {
        self.fast.is_some()
    }

    /// Element type names of the UNet's sample input ("float32"/"float16").
    pub fn precision(&self) -> &'static str {
        match self.unet.inputs[0].ty {
            T::Float16 => "fp16",
            _ => "fp32",
        }
    }

    /// Token ids → text-encoder outputs, all outputs (shape, values), for one batch.
    pub fn run_text_encoder(&mut self, ids: &[Vec<i64>]) -> Result<Vec<Output>, String> {
        let seq = ids.first().map_or(0, |v| v.len());
        if ids.iter().any(|v| v.len() != seq) {
            return Err("token id rows differ in length".into());
        }
        let t0 = Instant::now();
        let flat: Vec<i64> = ids.concat();
        let out = self
            .text_encoder
            .run(&[(vec![ids.len() as i64, seq as i64], Data::I64(&flat))]);
        let session = self.text_encoder.last_session_seconds();
        self.book(t0, session, |m| &mut m.text_encoder);
        out
    }

    /// Tokenises and encodes prompts (one batch).
    pub fn encode_text(&mut self, prompts: &[&str]) -> Result<Vec<Embedding>, String> {
        let ids: Vec<Vec<i64>> = prompts
            .iter()
            .map(|p| self.tokenizer.encode_padded(p))
            .collect();
        let out = self.run_text_encoder(&ids)?.remove(0);
        let (shape, data) = out;
        let (seq, hidden) = (shape[1] as usize, shape[2] as usize);
        Ok(data
            .chunks(seq * hidden)
            .map(|c| Embedding {
                data: c.to_vec(),
                seq,
                hidden,
            })
            .collect())
    }

    /// One UNet run: `samples[i]` (each `c × h × w`) under `conds[i]` at DDPM timestep `t`.
    pub fn unet_batch(
        &mut self,
        samples: &[&[f32]],
        hw: (usize, usize),
        t: u32,
        conds: &[&Embedding],
    ) -> Result<Vec<Vec<f32>>, String> {
        let b = samples.len();
        let c = self.latent_channels;
        let n = c * hw.0 * hw.1;
        if conds.len() != b || samples.iter().any(|s| s.len() != n) || b == 0 {
            return Err(format!(
                "{}: UNet batch of {} samples (each must be {c}×{}×{}) with {} conditions",
                self.unet.path.display(),
                b,
                hw.0,
                hw.1,
                conds.len()
            ));
        }
        self.probe_provider(hw, b)?;
        if let Some(m) = self
            .max_batch
            .into_iter()
            .chain(self.cap)
            .min()
            .filter(|m| *m < b)
        {
            let mut out = Vec::with_capacity(b);
            for (s, c) in samples.chunks(m).zip(conds.chunks(m)) {
                out.extend(self.unet_batch(s, hw, t, c)?);
            }
            return Ok(out);
        }
        let t0 = Instant::now();
        let (seq, hidden) = (conds[0].seq, conds[0].hidden);
        let sample: Vec<f32> = samples.concat();
        let mut ehs: Vec<f32> = Vec::with_capacity(b * seq * hidden);
        for e in conds {
            ehs.extend_from_slice(&e.data);
        }
        let t_port = &self.unet.inputs[1];
        let (t_shape, t_vals): (Vec<i64>, Vec<f32>) = match t_port.dims.as_slice() {
            [] => (vec![], vec![t as f32]),
            [1] => (vec![1], vec![t as f32]),
            _ => (vec![b as i64], vec![t as f32; b]),
        };
        let out = self.unet.run(&[
            (
                vec![b as i64, c as i64, hw.0 as i64, hw.1 as i64],
                Data::F32(&sample),
            ),
            (t_shape, Data::F32(&t_vals)),
            (vec![b as i64, seq as i64, hidden as i64], Data::F32(&ehs)),
        ]);
        let session = self.unet.last_session_seconds();
        self.times.unet_runs += 1;
        self.times.unet_items += b;
        let out = out?;
        let (shape, data) = out.into_iter().next().ok_or("UNet gave no output")?;
        if shape.iter().product::<i64>() as usize != b * n {
            return Err(format!(
                "{}: out_sample has shape {shape:?}, expected [{b}, {c}, {}, {}]",
                self.unet.path.display(),
                hw.0,
                hw.1
            ));
        }
        let out = data.chunks(n).map(<[f32]>::to_vec).collect();
        self.book(t0, session, |m| &mut m.unet);
        Ok(out)
    }

    fn codec(&mut self, which: Codec) -> &mut Autoencoder {
        match (which, self.fast.as_mut()) {
            (Codec::Fast, Some(f)) => f,
            _ => &mut self.vae,
        }
    }

    /// Latents (`b × c × h × w`, scaled as the UNet sees them) → images `b × 3 × 8h × 8w` in
    /// roughly [−1, 1]. Returns the images and their (height, width).
    pub fn decode(
        &mut self,
        z: &[f32],
        b: usize,
        hw: (usize, usize),
        which: Codec,
    ) -> Result<(Vec<f32>, (usize, usize)), String> {
        let t0 = Instant::now();
        let c = self.latent_channels;
        let ae = self.codec(which);
        let inv = (1.0 / ae.scaling) as f32;
        let scaled: Vec<f32> = z.iter().map(|v| v * inv).collect();
        let out = ae.decoder.run(&[(
            vec![b as i64, c as i64, hw.0 as i64, hw.1 as i64],
            Data::F32(&scaled),
        )]);
        let session = ae.decoder.last_session_seconds();
        let path = ae.decoder.path.clone();
        self.book(t0, session, |m| &mut m.autoencoder);
        let (shape, data) = out?.remove(0);
        if shape.len() != 4 || shape[0] != b as i64 || shape[1] != 3 {
            return Err(format!(
                "{}: decoded shape {shape:?}, expected [{b}, 3, H, W]",
                path.display()
            ));
        }
        Ok((data, (shape[2] as usize, shape[3] as usize)))
    }

    /// Images `b × 3 × H × W` in [−1, 1] → latents (the distribution's mean, scaled). Returns the
    /// latents and their (h, w).
    pub fn encode(
        &mut self,
        image: &[f32],
        b: usize,
        hw: (usize, usize),
        which: Codec,
    ) -> Result<(Vec<f32>, (usize, usize)), String> {
        let c = self.latent_channels;
        let dir = self.dir.display().to_string();
        let ae = self.codec(which);
        let scaling = ae.scaling as f32;
        let enc = ae.encoder.as_mut().ok_or_else(|| {
            format!(
                "{dir}: no encoder for this autoencoder (vae_encoder/ or taesd_encoder/ missing)"
            )
        })?;
        let t0 = Instant::now();
        let out = enc.run(&[(
            vec![b as i64, 3, hw.0 as i64, hw.1 as i64],
            Data::F32(image),
        )]);
        let session = enc.last_session_seconds();
        let (shape, data) = out?.remove(0);
        let ch = shape.get(1).copied().unwrap_or(0) as usize;
        if shape.len() != 4 || (ch != c && ch != 2 * c) {
            return Err(format!(
                "{}: encoder output shape {shape:?}, expected [{b}, {c} or {}, h, w]",
                enc.path.display(),
                2 * c
            ));
        }
        let (h, w) = (shape[2] as usize, shape[3] as usize);
        // latent_parameters carry (mean, logvar): keep the mean.
        let mut z = Vec::with_capacity(b * c * h * w);
        for item in data.chunks(ch * h * w) {
            z.extend(item[..c * h * w].iter().map(|v| v * scaling));
        }
        self.book(t0, session, |m| &mut m.autoencoder);
        Ok((z, (h, w)))
    }
}

/// The prompt embeddings a guidance rule draws on.
#[derive(Debug, Clone)]
pub struct Conditioning {
    pub positive: Embedding,
    pub negative: Embedding,
    pub null: Embedding,
    pub edit: Option<Embedding>,
}

impl Conditioning {
    /// Encodes the prompts in one text-encoder run.
    pub fn new(
        sd: &mut StableDiffusion,
        positive: &str,
        negative: &str,
        edit: Option<&str>,
    ) -> Result<Conditioning, String> {
        let mut prompts = vec![positive, negative, ""];
        if let Some(e) = edit {
            prompts.push(e);
        }
        let mut e = sd.encode_text(&prompts)?;
        let short = || "the text encoder returned fewer embeddings than prompts".to_string();
        let edit = if e.len() == 4 { e.pop() } else { None };
        let null = e.pop().ok_or_else(short)?;
        let negative = e.pop().ok_or_else(short)?;
        let positive = e.pop().ok_or_else(short)?;
        Ok(Conditioning {
            positive,
            negative,
            null,
            edit,
        })
    }

    fn get(&self, c: Cond) -> Result<&Embedding, String> {
        match c {
            Cond::Positive => Ok(&self.positive),
            Cond::Negative => Ok(&self.negative),
            Cond::Null => Ok(&self.null),
            Cond::Edit => self
                .edit
                .as_ref()
                .ok_or_else(|| "an edit prompt is needed for the editing rule".to_string()),
        }
    }
}

/// The UNet as a [`NoisePredictor`] over latents of size `hw`: every call is one batched run.
pub struct UnetPredictor<'a> {
    pub sd: &'a mut StableDiffusion,
    pub cond: &'a Conditioning,
    pub hw: (usize, usize),
    /// UNet runs made (for benchmarks and tests).
    pub runs: usize,
}

impl NoisePredictor for UnetPredictor<'_> {
    fn predict(&mut self, x: &[f32], t: u32, conds: &[Cond]) -> Result<Vec<Vec<f32>>, String> {
        let embs = conds
            .iter()
            .map(|c| self.cond.get(*c))
            .collect::<Result<Vec<_>, _>>()?;
        let samples: Vec<&[f32]> = vec![x; conds.len()];
        self.runs += 1;
        self.sd.unet_batch(&samples, self.hw, t, &embs)
    }
}

/// The UNet as a [`ViewsPredictor`]: view `v` under `conds[v]`'s prompts, every call one run
/// over views × conditions (view-major), split only where the provider probe or
/// [`StableDiffusion::set_unet_max_batch`] caps a run.
pub struct UnetViews<'a> {
    pub sd: &'a mut StableDiffusion,
    pub conds: &'a [&'a Conditioning],
    pub hw: (usize, usize),
    /// Calls made (for benchmarks and tests).
    pub runs: usize,
}

impl ViewsPredictor for UnetViews<'_> {
    fn predict_views(
        &mut self,
        xs: &[&[f32]],
        t: u32,
        conds: &[Cond],
    ) -> Result<Vec<Vec<Vec<f32>>>, String> {
        if xs.len() != self.conds.len() {
            return Err(format!(
                "{} latents for {} views' prompts",
                xs.len(),
                self.conds.len()
            ));
        }
        let mut samples: Vec<&[f32]> = Vec::with_capacity(xs.len() * conds.len());
        let mut embs = Vec::with_capacity(samples.capacity());
        for (x, cond) in xs.iter().zip(self.conds) {
            for c in conds {
                samples.push(x);
                embs.push(cond.get(*c)?);
            }
        }
        self.runs += 1;
        let mut out = self.sd.unet_batch(&samples, self.hw, t, &embs)?.into_iter();
        Ok(xs
            .iter()
            .map(|_| out.by_ref().take(conds.len()).collect())
            .collect())
    }
}

/// Renderer layout (`h × w × 3`, [0, 1]) → model layout (`3 × h × w`, [−1, 1]).
pub fn hwc01_to_chw11(rgb: &[f32], w: usize, h: usize) -> Vec<f32> {
    let mut out = vec![0.0; 3 * w * h];
    super::convert::hwc01_to_chw11_into(rgb, w, h, &mut out);
    out
}

/// Model layout (`3 × h × w`, [−1, 1]) → renderer layout (`h × w × 3`, [0, 1], clamped).
pub fn chw11_to_hwc01(img: &[f32], w: usize, h: usize) -> Vec<f32> {
    super::convert::chw11_to_hwc01(img, w, h)
}
