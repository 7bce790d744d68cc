//! `dreamscene layout`: graph-based constraint placement of a SceneSpec.
use super::create_parent;
use anyhow::{Context as _, Result};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::spec::{PlacedBy, SceneSpec};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// SceneSpec (spec.json, as `plan` writes it).
    #[arg(long)]
    pub spec: PathBuf,
    /// Seed: different seeds give different valid layouts.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Output layout.json.
    #[arg(long)]
    pub out: PathBuf,
}

pub fn run(a: Args) -> Result<()> {
    let spec = SceneSpec::read(&a.spec)?;
    let l = layout(&spec, LayoutOptions::seeded(a.seed))?;
    create_parent(&a.out)?;
    l.write(&a.out)
        .with_context(|| format!("writing {}", a.out.display()))?;
    let fallback = l
        .objects
        .iter()
        .filter(|o| o.placed_by == PlacedBy::Fallback)
        .count();
    println!(
        "wrote {}: {} objects in a {:.1} x {:.1} x {:.1} m room, {} of {} relations satisfied, {} fallback placements",
        a.out.display(),
        l.objects.len(),
        l.room.size[0],
        l.room.size[1],
        l.room.size[2],
        spec.relations.len() - l.unsatisfied.len(),
        spec.relations.len(),
        fallback
    );
    for r in &l.unsatisfied {
        println!("  unsatisfied: {} {:?} {}", r.subject, r.relation, r.object);
    }
    Ok(())
}
