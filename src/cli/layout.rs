//! `dreamscene layout`: graph-based constraint placement of a SceneSpec.
use super::{create_parent, write_png};
use anyhow::{Context as _, Result};
use dreamscene::plan::check::walk;
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::spec::SceneSpec;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// SceneSpec (spec.json, as `plan` writes it).
    #[arg(long)]
    pub spec: PathBuf,
    /// Seed: different seeds give different valid layouts.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Output layout.json; its top-down picture goes beside it (same name, .png).
    #[arg(long)]
    pub out: PathBuf,
}

pub fn run(a: Args) -> Result<()> {
    let spec = SceneSpec::read(&a.spec)?;
    let l = layout(&spec, LayoutOptions::seeded(a.seed))?;
    create_parent(&a.out)?;
    l.write(&a.out)
        .with_context(|| format!("writing {}", a.out.display()))?;
    // Written to a device such as /dev/stdout: no picture beside it, and the summary goes to
    // stderr to keep the JSON clean.
    if dreamscene::util::is_special(&a.out) {
        eprintln!("wrote {}: {}", a.out.display(), l.summary(&spec));
        for r in &l.unsatisfied {
            eprintln!("  unsatisfied: {r}");
        }
        for id in walk::unreachable(&l) {
            eprintln!("  out of reach: no way from the door to where {id} is used");
        }
        return Ok(());
    }
    let png = a.out.with_extension("png");
    write_png(&dreamscene::plan::draw::draw_layout(&l), &png)?;
    println!(
        "wrote {} and {}: {}",
        a.out.display(),
        png.display(),
        l.summary(&spec)
    );
    for r in &l.unsatisfied {
        println!("  unsatisfied: {r}");
    }
    for id in walk::unreachable(&l) {
        println!("  out of reach: no way from the door to where {id} is used");
    }
    Ok(())
}
