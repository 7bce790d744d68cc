//! The provider probe: before a GPU execution provider runs the UNet, two small graphs are run on
//! it and on the CPU provider at the run's sizes and compared — an attention-sized Softmax (the
//! scores of the UNet's first self-attention: batch × heads × tokens × tokens, where a GPU
//! provider may return wrong values without an error once the tensor outgrows a storage binding)
//! and a 3×3 Conv at the latent size and the first block's width. The graphs are committed under
//! `src/diffusion/probe/` (scripts/dev/make_probe_graphs.py writes them) and embedded here.
//!
//! The verdict: trust the provider; split the UNet batch into runs of at most `max_batch` items
//! (the Softmax is right at a smaller batch); or fall back to the CPU provider (the Conv is wrong,
//! or the Softmax is wrong even one item at a time).
use super::runtime::{Data, OnnxModel, PortSpec, Provider};
use ort::value::TensorElementType as T;
use rand::{Rng, SeedableRng};
use rayon::prelude::*;
use std::path::Path;

const SOFTMAX_FP32: &[u8] = include_bytes!("probe/softmax_fp32.onnx");
const SOFTMAX_FP16: &[u8] = include_bytes!("probe/softmax_fp16.onnx");
const CONV_FP32: &[u8] = include_bytes!("probe/conv_fp32.onnx");
const CONV_FP16: &[u8] = include_bytes!("probe/conv_fp16.onnx");

/// The two probed operations.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Op {
    Softmax,
    Conv,
}

/// The sizes of a run the probe reproduces.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ProbeSizes {
    /// Items in one UNet run (views × conditionings).
    pub batch: usize,
    /// Attention heads of the first UNet block.
    pub heads: usize,
    /// Latent height and width (tokens of the first self-attention = h × w).
    pub hw: (usize, usize),
    /// Channels of the first UNet block.
    pub channels: usize,
    /// Whether the models are fp16 (the probe graphs then compute in fp16).
    pub half: bool,
}

impl ProbeSizes {
    /// The sizes of a run of the UNet in `dir` (its `unet/config.json`: `num_attention_heads`,
    /// else `attention_head_dim`, which diffusers' SD configs use for the head count; and
    /// `block_out_channels`), defaulting to SD 2.1's first block (5 heads, 320 channels).
    pub fn for_unet(dir: &Path, hw: (usize, usize), batch: usize, half: bool) -> ProbeSizes {
        let cfg: Option<serde_json::Value> = std::fs::read_to_string(dir.join("unet/config.json"))
            .ok()
            .and_then(|t| serde_json::from_str(&t).ok());
        let first = |key: &str| -> Option<usize> {
            let v = cfg.as_ref()?.get(key)?;
            let n = v.as_u64().or_else(|| v.as_array()?.first()?.as_u64())?;
            usize::try_from(n).ok().filter(|n| *n > 0)
        };
        ProbeSizes {
            batch: batch.max(1),
            heads: first("num_attention_heads")
                .or_else(|| first("attention_head_dim"))
                .unwrap_or(5),
            hw,
            channels: first("block_out_channels").unwrap_or(320),
            half,
        }
    }
}

/// One comparison: the largest difference relative to the reference's largest magnitude (at
/// least 1), against the tolerance of the precision.
#[derive(Debug, Clone, PartialEq)]
pub struct Check {
    pub op: Op,
    pub batch: usize,
    pub error: f32,
    pub tolerance: f32,
}

impl Check {
    pub fn passed(&self) -> bool {
        self.error.is_finite() && self.error <= self.tolerance
    }
}

/// What to do with the provider.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Verdict {
    Trust,
    /// Run the UNet on at most this many items at a time.
    Split {
        max_batch: usize,
    },
    /// Use the CPU provider instead; the reason names the failed check.
    Fallback {
        reason: String,
    },
}

/// The probe's checks in order and its verdict.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    pub checks: Vec<Check>,
    pub verdict: Verdict,
}

/// Tolerances: fp32 providers agree to float rounding; fp16 ones store 11 significant bits and
/// may accumulate a Conv in fp16 (measured on the WebGPU EP: 2% of the output range).
fn tolerance(op: Op, half: bool) -> f32 {
    match (op, half) {
        (_, false) => 1e-3,
        (Op::Softmax, true) => 1e-2,
        (Op::Conv, true) => 5e-2,
    }
}

/// The decision, given a way to run one check (`op` at `batch` items): the Conv at the full
/// batch, then the Softmax at the full batch, halving it while it fails.
pub fn decide(
    batch: usize,
    mut check: impl FnMut(Op, usize) -> Result<Check, String>,
) -> Result<Report, String> {
    let mut checks = vec![];
    let batch = batch.max(1);
    let conv = check(Op::Conv, batch)?;
    let conv_ok = conv.passed();
    checks.push(conv);
    if !conv_ok {
        let c = &checks[0];
        let reason = format!(
            "a {batch}-item Conv differs from the CPU provider by {:.3e} (tolerance {:.0e})",
            c.error, c.tolerance
        );
        return Ok(Report {
            checks,
            verdict: Verdict::Fallback { reason },
        });
    }
    let mut b = batch;
    loop {
        let s = check(Op::Softmax, b)?;
        let ok = s.passed();
        let (error, tol) = (s.error, s.tolerance);
        checks.push(s);
        if ok {
            let verdict = if b == batch {
                Verdict::Trust
            } else {
                Verdict::Split { max_batch: b }
            };
            return Ok(Report { checks, verdict });
        }
        if b == 1 {
            let reason = format!(
                "an attention-sized Softmax differs from the CPU provider by {error:.3e} \
                 (tolerance {tol:.0e}) even one item at a time"
            );
            return Ok(Report {
                checks,
                verdict: Verdict::Fallback { reason },
            });
        }
        b = b.div_ceil(2);
    }
}

/// A test hook: changes a provider's output (`op`, batch, values) before the comparison, to plant
/// a wrong result. Production passes `None`.
pub type Tamper<'a> = &'a dyn Fn(Op, usize, &mut [f32]);

struct Pair {
    cpu: OnnxModel,
    gpu: OnnxModel,
}

fn pair(name: &str, bytes: &[u8], provider: Provider, inputs: usize) -> Result<Pair, String> {
    let names: [&[&str]; 3] = [&["x"], &["w"], &["b"]];
    let specs: Vec<PortSpec> = names[..inputs]
        .iter()
        .enumerate()
        .map(|(i, n)| PortSpec {
            names: n,
            ranks: if i == 2 { &[1] } else { &[4] },
            types: &[T::Float32],
        })
        .collect();
    let out = [PortSpec {
        names: &["y"],
        ranks: &[4],
        types: &[T::Float32],
    }];
    Ok(Pair {
        cpu: OnnxModel::load_bytes(name, bytes, Provider::Cpu, None, &specs, &out)?,
        gpu: OnnxModel::load_bytes(name, bytes, provider, None, &specs, &out)?,
    })
}

/// `n` values uniform in (−amp, amp) from `seed`, drawn in parallel (one ChaCha stream per chunk
/// of 2^16): an attention-sized Softmax at 512² holds ~10^9 of them.
fn uniform(seed: u64, n: usize, amp: f32) -> Vec<f32> {
    let mut v = vec![0.0f32; n];
    v.par_chunks_mut(1 << 16).enumerate().for_each(|(k, c)| {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        rng.set_stream(k as u64);
        for x in c {
            *x = rng.gen_range(-amp..amp);
        }
    });
    v
}

/// Largest difference relative to the reference's largest magnitude (at least 1).
pub fn relative_error(got: &[f32], want: &[f32]) -> f32 {
    if got.len() != want.len() {
        return f32::INFINITY;
    }
    let scale = want.par_iter().map(|v| v.abs()).reduce(|| 1.0f32, f32::max);
    got.par_iter()
        .zip(want)
        .map(|(a, b)| {
            let d = (a - b).abs();
            if d.is_nan() {
                f32::INFINITY
            } else {
                d
            }
        })
        .reduce(|| 0.0, f32::max)
        / scale
}

/// Whether a small graph (the fp32 Conv) loads on `provider`: its library, the libraries it
/// needs and a device are found. The error is ONNX Runtime's, which names what is missing.
pub fn loads(provider: Provider) -> Result<(), String> {
    pair("probe conv", CONV_FP32, provider, 3).map(|_| ())
}

/// Runs the probe for `provider` at `sizes`. `tamper` (tests only) changes the provider's outputs.
pub fn probe(
    provider: Provider,
    sizes: &ProbeSizes,
    tamper: Option<Tamper>,
) -> Result<Report, String> {
    let half = sizes.half;
    let (softmax, conv) = if half {
        (SOFTMAX_FP16, CONV_FP16)
    } else {
        (SOFTMAX_FP32, CONV_FP32)
    };
    let mut sm = pair("probe softmax", softmax, provider, 1)?;
    let mut cv = pair("probe conv", conv, provider, 3)?;
    let (h, w) = sizes.hw;
    let tokens = h * w;
    let c = sizes.channels;
    // A fresh seed for every tensor drawn.
    let mut drawn = 25u64 << 32;
    let mut seed = || {
        drawn += 1;
        drawn
    };
    decide(sizes.batch, |op, b| {
        let (cpu, gpu) = match op {
            Op::Softmax => {
                let shape = vec![b as i64, sizes.heads as i64, tokens as i64, tokens as i64];
                let x = uniform(seed(), b * sizes.heads * tokens * tokens, 4.0);
                let inputs = [(shape, Data::F32(&x))];
                (sm.cpu.run(&inputs)?, sm.gpu.run(&inputs)?)
            }
            Op::Conv => {
                let x = uniform(seed(), b * c * tokens, 1.0);
                let wt = uniform(seed(), c * c * 9, (3.0 / (9 * c) as f32).sqrt());
                let bias = uniform(seed(), c, 0.1);
                let (c64, h64, w64) = (c as i64, h as i64, w as i64);
                let inputs = [
                    (vec![b as i64, c64, h64, w64], Data::F32(&x)),
                    (vec![c64, c64, 3, 3], Data::F32(&wt)),
                    (vec![c64], Data::F32(&bias)),
                ];
                (cv.cpu.run(&inputs)?, cv.gpu.run(&inputs)?)
            }
        };
        let want = &cpu.first().ok_or("probe: no CPU output")?.1;
        let mut got = gpu.into_iter().next().ok_or("probe: no provider output")?.1;
        if let Some(t) = tamper {
            t(op, b, &mut got);
        }
        Ok(Check {
            op,
            batch: b,
            error: relative_error(&got, want),
            tolerance: tolerance(op, half),
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fake(op: Op, batch: usize, error: f32) -> Result<Check, String> {
        Ok(Check {
            op,
            batch,
            error,
            tolerance: 1e-3,
        })
    }

    #[test]
    fn verdicts_follow_the_checks() {
        let r = decide(4, |op, b| fake(op, b, 0.0)).unwrap();
        assert_eq!(r.verdict, Verdict::Trust);
        assert_eq!(r.checks.len(), 2);
        // Softmax wrong above 1 item: halve until right.
        let soft = |op: Op, b: usize, above: usize| {
            fake(
                op,
                b,
                if op == Op::Softmax && b > above {
                    0.45
                } else {
                    0.0
                },
            )
        };
        let r = decide(4, |op, b| soft(op, b, 1)).unwrap();
        assert_eq!(r.verdict, Verdict::Split { max_batch: 1 });
        assert_eq!(
            r.checks.iter().map(|c| c.batch).collect::<Vec<_>>(),
            [4, 4, 2, 1]
        );
        // An odd batch halves upwards (5 → 3).
        let r = decide(5, |op, b| soft(op, b, 3)).unwrap();
        assert_eq!(r.verdict, Verdict::Split { max_batch: 3 });
        // Wrong even one at a time, or a wrong Conv: the CPU.
        let r = decide(2, |op, b| {
            fake(op, b, if op == Op::Softmax { 0.45 } else { 0.0 })
        })
        .unwrap();
        assert!(matches!(r.verdict, Verdict::Fallback { .. }));
        let r = decide(2, |op, b| {
            fake(op, b, if op == Op::Conv { f32::NAN } else { 0.0 })
        })
        .unwrap();
        assert!(matches!(r.verdict, Verdict::Fallback { ref reason } if reason.contains("Conv")));
        assert_eq!(r.checks.len(), 1);
    }

    #[test]
    fn relative_error_scales_and_catches_nan() {
        assert_eq!(relative_error(&[1.0, 2.0], &[1.0, 2.0]), 0.0);
        assert!((relative_error(&[0.0, 4.4], &[0.0, 4.0]) - 0.1).abs() < 1e-6);
        assert!((relative_error(&[0.5], &[0.0]) - 0.5).abs() < 1e-6);
        assert_eq!(relative_error(&[f32::NAN], &[0.0]), f32::INFINITY);
        assert_eq!(relative_error(&[0.0], &[0.0, 1.0]), f32::INFINITY);
    }
}
