//! `dreamscene object`: one object from a prompt, with the shape, Stable Diffusion or oracle
//! prior; writes object.ply, object.json, a turntable and checkpoints.
use anyhow::{bail, Context as _, Result};
use dreamscene::camera::object::{turntable, ObjectFrame};
use dreamscene::diffusion::guidance::MtsRule;
use dreamscene::diffusion::runtime::Provider;
use dreamscene::diffusion::target::{Rule, ISM_DEFAULT};
use dreamscene::generate::filter::FilterConfig;
use dreamscene::generate::object::{
    generate_object, parse_score_rule, Checkpoints, Counts, ObjectConfig,
};
use dreamscene::generate::prior::{OraclePrior, Prior};
use dreamscene::generate::progress::Progress;
use dreamscene::plan::kb::KnowledgeBase;
use dreamscene::shape::{self, ShapeOptions};
use dreamscene::splat::ply::{read_ply, write_ply};
use dreamscene::splat::raster::{GpuGaussians, Rasterizer};
use dreamscene::splat::Gaussians;
use std::path::{Path, PathBuf};

/// Which prior, as `--prior` names it (the library's [`PriorSpec`]).
pub use dreamscene::generate::prior_spec::PriorSpec as PriorChoice;

pub fn parse_prior(s: &str) -> Result<PriorChoice, String> {
    PriorChoice::parse(s)
}

/// The guidance rule of the formation stage by name.
pub fn parse_rule(s: &str) -> Result<Rule, String> {
    match s {
        "mts" => Ok(Rule::Mts { m: 4 }),
        "sds" => Ok(Rule::Sds {
            t_min: 20,
            t_max: 980,
        }),
        "ism" => Ok(ISM_DEFAULT),
        "dreamtime" => Ok(Rule::DreamTime {
            t_min: 20,
            t_max: 980,
            steps: 1500,
        }),
        _ => Err(format!("'{s}': expected mts, sds, ism or dreamtime")),
    }
}

/// `W,D,H` in metres.
pub fn parse_size(s: &str) -> Result<[f64; 3], String> {
    let v: Vec<f64> = s
        .split(',')
        .map(|x| x.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| format!("'{s}': expected W,D,H in metres, e.g. 0.9,0.8,1.0"))?;
    match v[..] {
        [w, d, h] if v.iter().all(|x| x.is_finite() && *x > 0.0 && *x <= 100.0) => Ok([w, d, h]),
        _ => Err(format!(
            "'{s}': expected three positive sizes W,D,H in metres (at most 100)"
        )),
    }
}

/// `text` in lower case as words of letters and digits, one space apart: a prompt and a name
/// compare alike whatever their punctuation ("an x-ray machine" names the x-ray machine).
fn plain_words(text: &str) -> String {
    let words: String = text
        .to_lowercase()
        .chars()
        .map(|c| if c.is_alphanumeric() { c } else { ' ' })
        .collect();
    words.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The knowledge-base kind a prompt names (the longest name or synonym found as whole words),
/// with that name as plain words, if any.
fn find_kind(prompt: &str) -> Option<(String, &'static dreamscene::plan::kb::ObjectKind)> {
    let padded = format!(" {} ", plain_words(prompt));
    let kb = KnowledgeBase::builtin();
    let mut best: Option<(String, &dreamscene::plan::kb::ObjectKind)> = None;
    for (name, kind) in kb.names() {
        let name = plain_words(name);
        let hit = padded.contains(&format!(" {name} ")) || padded.contains(&format!(" {name}s "));
        if hit && best.as_ref().is_none_or(|b| name.len() > b.0.len()) {
            best = Some((name, kind));
        }
    }
    best
}

/// The knowledge-base category a prompt names (the longest name or synonym found as whole
/// words), if any.
pub fn find_category(prompt: &str) -> Option<(String, [f64; 3])> {
    find_kind(prompt).map(|(_, k)| (k.category.clone(), k.size))
}

/// What the shape prior draws from a prompt: its words with the thing's name said as the
/// knowledge base describes it, so a word of the name is never read as a colour or material
/// ("a wood stove" is black cast iron, "a red wood stove" red).
pub fn shape_description(prompt: &str) -> String {
    let plain = format!(" {} ", plain_words(prompt));
    match find_kind(prompt) {
        Some((name, kind)) => {
            let said = if plain.contains(&format!(" {name} ")) {
                format!(" {name} ")
            } else {
                format!(" {name}s ")
            };
            plain
                .replacen(&said, &format!(" {} ", kind.description), 1)
                .trim()
                .to_string()
        }
        None => prompt.to_string(),
    }
}

/// What `object` was asked.
pub struct ObjectArgs {
    pub prompt: String,
    pub out: PathBuf,
    pub size: Option<[f64; 3]>,
    pub models: Option<PathBuf>,
    pub provider: Provider,
    pub prior: PriorChoice,
    pub init: Option<PathBuf>,
    pub config: ObjectConfig,
    pub resume: bool,
    pub turntable: usize,
}

/// Filter settings from the CLI.
pub fn filter_config(off: bool, fraction: f64, rule: &str) -> Result<Option<FilterConfig>> {
    if off {
        return Ok(None);
    }
    if !(0.0..1.0).contains(&fraction) {
        bail!("--filter-fraction {fraction}: expected a fraction in [0, 1)");
    }
    let rule = parse_score_rule(rule)
        .ok_or_else(|| anyhow::anyhow!("--filter-rule '{rule}': expected paper or code"))?;
    Ok(Some(FilterConfig {
        rule,
        fraction,
        ..FilterConfig::default()
    }))
}

/// The models directory: `--models`, else `DREAMSCENE_MODELS`.
pub fn models_dir(models: Option<&Path>) -> Option<PathBuf> {
    models
        .map(Path::to_path_buf)
        .or_else(|| dreamscene::util::env_path("DREAMSCENE_MODELS"))
}

pub const NO_MODELS: &str = "no diffusion models found (--models DIR or DREAMSCENE_MODELS): \
                             this is a draft from the shape prior; the README's \"The diffusion \
                             models\" says how to export Stable Diffusion for full generation";

pub fn run_with(a: ObjectArgs) -> Result<()> {
    if a.prompt.trim().is_empty() {
        bail!("the prompt is empty: say what object to make, e.g. \"a red velvet armchair\"");
    }
    let found = find_category(&a.prompt);
    let (category, kb_size) = found
        .clone()
        .unwrap_or_else(|| ("object".to_string(), [0.8, 0.8, 0.8]));
    let size = a.size.unwrap_or(kb_size);
    let models = models_dir(a.models.as_deref());
    let prior = match (&a.prior, &models) {
        (PriorChoice::Auto, Some(_)) => PriorChoice::Sd,
        (PriorChoice::Auto, None) => {
            eprintln!("{NO_MODELS}");
            PriorChoice::Shape
        }
        (PriorChoice::Sd, None) => {
            bail!("--prior sd needs a model directory (--models DIR or DREAMSCENE_MODELS)")
        }
        (p, _) => p.clone(),
    };
    super::create_dir(&a.out)?;
    if found.is_none() {
        eprintln!(
            "note: no known category in \"{}\"; using a generic {:.2} x {:.2} x {:.2} m box shape",
            a.prompt, size[0], size[1], size[2]
        );
    }
    let cfg = &a.config;
    let shape_init = || -> Result<Gaussians> {
        Ok(shape::build(
            &category,
            size,
            &shape_description(&a.prompt),
            &ShapeOptions {
                gaussians: None,
                seed: cfg.seed,
                variant: 0,
                mount: None,
            },
        )?)
    };
    let init = match &a.init {
        Some(p) => read_ply(p)?,
        None => shape_init()?,
    };
    let frame = ObjectFrame { size };
    let ctx = super::open_device()?;
    let start = std::time::Instant::now();
    let (g, counts, iterations, prior_name) = match prior {
        PriorChoice::Shape | PriorChoice::Auto => {
            let n = init.len();
            let counts = Counts {
                initial: n,
                before_filter: n,
                after_filter: n,
                final_: n,
            };
            (init, counts, 0, "shape".to_string())
        }
        PriorChoice::Sd | PriorChoice::Oracle(_) => {
            let mut p: Box<dyn Prior> = match &prior {
                PriorChoice::Oracle(path) => {
                    let r = read_ply(path)?;
                    Box::new(OraclePrior::new(&ctx, &r, None).map_err(anyhow::Error::msg)?)
                }
                _ => {
                    let dir = models.clone().expect("checked above");
                    if !a.config.resolution.is_multiple_of(8) {
                        bail!(
                            "--resolution {}: Stable Diffusion needs a multiple of 8",
                            cfg.resolution
                        );
                    }
                    let text = if a.prompt.to_lowercase().starts_with("a dslr photo") {
                        a.prompt.clone()
                    } else {
                        format!("A DSLR photo of {}", a.prompt)
                    };
                    Box::new(dreamscene::generate::prior_spec::open_sd(
                        &dir, a.provider, &text, None,
                    )?)
                }
            };
            let name = match &prior {
                PriorChoice::Oracle(path) => format!("oracle:{}", path.display()),
                _ => "sd".to_string(),
            };
            let ck = Checkpoints {
                dir: &a.out.join("checkpoints"),
                resume: a.resume,
                fingerprint: cfg.fingerprint(&a.prompt, &name),
            };
            let total = cfg.iterations as u64
                + if cfg.recon_views > 0 {
                    (cfg.recon_passes * cfg.recon_views as u32) as u64
                } else {
                    0
                }
                + 1;
            let mut progress = Progress::new(total, false);
            let (g, report) = generate_object(
                &ctx,
                &init,
                &frame,
                p.as_mut(),
                cfg,
                Some(&ck),
                &mut progress,
            )?;
            progress.finish();
            eprintln!(
                "formation {:.1} s (gpu {:.1}, prior {:.1}, host {:.1}), filtering {:.1} s, \
                 reconstruction {:.1} s",
                report.stage_seconds[0],
                report.formation_split[0],
                report.formation_split[1],
                report.formation_split[2],
                report.stage_seconds[1],
                report.stage_seconds[2]
            );
            (g, report.counts, cfg.iterations, name)
        }
    };
    let ply = a.out.join("object.ply");
    write_ply(&ply, &g).with_context(|| format!("writing {}", ply.display()))?;
    let seconds = start.elapsed().as_secs_f64();
    let json = serde_json::json!({
        "prompt": a.prompt,
        "category": category,
        "size": size,
        "prior": prior_name,
        "seed": cfg.seed,
        "iterations": iterations,
        "resolution": cfg.resolution,
        "gaussians": counts,
        "seconds": seconds,
    });
    let path = a.out.join("object.json");
    dreamscene::util::write_atomic(&path, serde_json::to_string_pretty(&json)?.as_bytes())
        .with_context(|| format!("writing {}", path.display()))?;
    let renders = a.out.join("renders");
    write_turntable(
        &ctx,
        &g,
        &frame,
        a.turntable,
        cfg.resolution.min(512),
        &renders,
    )?;
    println!(
        "wrote {} ({} Gaussians, {category}, prior {prior_name}), object.json and {} turntable \
         views in {} ({seconds:.1} s)",
        ply.display(),
        g.len(),
        a.turntable,
        renders.display()
    );
    Ok(())
}

/// Renders `count` turntable views (white background) into `dir`.
pub fn write_turntable(
    ctx: &dreamscene::gpu::Context,
    g: &Gaussians,
    frame: &ObjectFrame,
    count: usize,
    res: u32,
    dir: &Path,
) -> Result<()> {
    if count == 0 {
        return Ok(());
    }
    super::create_dir(dir)?;
    let r = Rasterizer::new(ctx)?;
    let gg = GpuGaussians::upload(ctx, g)?;
    for cam in turntable(frame, count, 75.0, res) {
        let img = r.forward(ctx, &gg, &cam, [1.0; 3])?.read()?;
        super::save_png(&img, &dir.join(format!("{}.png", cam.img_name)))?;
    }
    Ok(())
}

/// The object settings from the CLI's numbers.
#[allow(
    clippy::too_many_arguments,
    reason = "one argument per CLI number, in the order of the flags"
)]
pub fn config(
    iterations: u32,
    resolution: u32,
    seed: u64,
    rule: Rule,
    mts_form: MtsRule,
    batch: usize,
    sh_degree: u32,
    filter: Option<FilterConfig>,
    recon_views: usize,
    recon_passes: u32,
    checkpoint_every: u32,
) -> ObjectConfig {
    ObjectConfig {
        iterations,
        batch,
        resolution,
        rule,
        mts_form,
        sh_degree,
        filter,
        recon_views,
        recon_passes,
        checkpoint_every,
        seed,
        ..ObjectConfig::default()
    }
}

#[derive(clap::Args)]
pub struct Args {
    /// What to make, e.g. "a red velvet armchair".
    pub prompt: String,
    /// Output directory.
    #[arg(long)]
    pub out: PathBuf,
    /// Size W,D,H in metres (default: the category's typical size).
    #[arg(long, value_parser = parse_size)]
    pub size: Option<[f64; 3]>,
    /// Stable Diffusion ONNX export (Optimum layout); default $DREAMSCENE_MODELS.
    #[arg(long)]
    pub models: Option<PathBuf>,
    /// ONNX Runtime provider for the models (auto: a GPU provider on a real GPU, else the CPU).
    #[arg(long, value_enum, default_value = "auto")]
    pub provider: Provider,
    /// auto (sd when models are found, else shape), sd, shape, or oracle:REF.ply.
    #[arg(long, default_value = "auto", value_parser = parse_prior)]
    pub prior: PriorChoice,
    /// Start from this PLY instead of the shape prior.
    #[arg(long)]
    pub init: Option<PathBuf>,
    /// Formation (MTS) iterations.
    #[arg(long, default_value_t = 1500, value_parser = clap::value_parser!(u32).range(1..))]
    pub iterations: u32,
    /// Render size in pixels (square).
    #[arg(long, default_value_t = 512, value_parser = clap::value_parser!(u32).range(16..=2048))]
    pub resolution: u32,
    /// Views per iteration.
    #[arg(long, default_value_t = 4, value_parser = clap::value_parser!(u64).range(1..=16))]
    pub batch: u64,
    /// Guidance rule of the formation stage: mts, sds, ism, dreamtime.
    #[arg(long, default_value = "mts", value_parser = parse_rule)]
    pub rule: dreamscene::diffusion::target::Rule,
    /// Use the authors' code form of MTS (random jumps, CFG 7.5, averaged) instead of the
    /// paper's (m intervals).
    #[arg(long)]
    pub mts_code_form: bool,
    /// Final SH degree (raised one degree every 500 iterations).
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u32).range(0..=3))]
    pub sh_degree: u32,
    /// Turn off 3D Gaussian filtering.
    #[arg(long)]
    pub no_filter: bool,
    /// Fraction of the Gaussians filtering removes.
    #[arg(long, default_value_t = 0.6)]
    pub filter_fraction: f64,
    /// Filtering score: paper or code.
    #[arg(long, default_value = "paper")]
    pub filter_rule: String,
    /// Reconstruction views (0 turns reconstructive generation off).
    #[arg(long, default_value_t = 20)]
    pub recon_views: usize,
    /// Passes of the reconstruction fit over its views.
    #[arg(long, default_value_t = 40)]
    pub recon_passes: u32,
    /// Checkpoint every N iterations (0: only between stages).
    #[arg(long, default_value_t = 100)]
    pub checkpoint_every: u32,
    /// Turntable views written to renders/.
    #[arg(long, default_value_t = 8)]
    pub turntable: usize,
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Continue an interrupted run from <out>/checkpoints (same prompt, prior and settings).
    #[arg(long)]
    pub resume: bool,
}

pub fn run(a: Args) -> Result<()> {
    let filter = filter_config(a.no_filter, a.filter_fraction, &a.filter_rule)?;
    let form = if a.mts_code_form {
        dreamscene::diffusion::guidance::MtsRule::Code
    } else {
        dreamscene::diffusion::guidance::MtsRule::Paper
    };
    let config = config(
        a.iterations,
        a.resolution,
        a.seed,
        a.rule,
        form,
        a.batch as usize,
        a.sh_degree,
        filter,
        a.recon_views,
        a.recon_passes,
        a.checkpoint_every,
    );
    run_with(ObjectArgs {
        prompt: a.prompt,
        out: a.out,
        size: a.size,
        models: a.models,
        provider: a.provider,
        prior: a.prior,
        init: a.init,
        config,
        resume: a.resume,
        turntable: a.turntable,
    })
}

#[cfg(test)]
mod tests {
    use super::{find_category, shape_description};

    #[test]
    fn a_word_of_the_things_name_is_not_its_material() {
        // the stove of "a wood stove" is cast iron; a colour said besides stays
        let d = shape_description("a red wood stove");
        assert!(d.contains("cast-iron") && d.contains("red"), "{d}");
        assert!(!d.split_whitespace().any(|w| w == "wood"), "{d}");
        // a material said of the thing stays ("a stone bench" is stone)
        let d = shape_description("a stone bench");
        assert!(d.contains("stone"), "{d}");
        // no known thing: the prompt as said
        assert_eq!(shape_description("a zorbulator"), "a zorbulator");
    }

    #[test]
    fn names_with_hyphens_are_found_in_a_prompt() {
        for (prompt, category) in [
            ("an x-ray machine", "x-ray machine"),
            ("a tall full-length mirror in oak", "full length mirror"),
            ("a white two-step stool", "step stool"),
        ] {
            let got = find_category(prompt).map(|(c, _)| c);
            assert_eq!(got.as_deref(), Some(category), "{prompt}");
        }
    }
}
