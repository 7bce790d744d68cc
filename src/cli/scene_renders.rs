//! The views of a generated scene: chosen by what they show, written to `renders/` with their
//! cameras and a contact sheet, and completed when a resumed run finds some missing.
use super::generate::GenerateArgs;
use anyhow::{Context as _, Result};
use dreamscene::camera::scene::{render_views, SceneBox};
use dreamscene::camera::{write_cameras, Camera};
use dreamscene::plan::spec::Layout;
use dreamscene::splat::raster::Rasterizer;
use dreamscene::splat::view::ViewSource;
use dreamscene::splat::Gaussians;
use std::path::Path;

/// The background of the renders: the environment encloses the views, so it barely shows.
const BACKGROUND: [f32; 3] = [0.0; 3];

/// Renders the views `renders/cameras.json` lists that are not there, and the contact sheet
/// when it is missing (all of them, chosen by what they show, when cameras.json itself is
/// missing and views were asked for) from `scene.ply`. Says what it rendered, if anything.
/// Whether the views `renders/cameras.json` lists, or the contact sheet, are missing: a run
/// stopped while it rendered.
pub(super) fn renders_missing(out: &Path) -> bool {
    let dir = out.join("renders");
    let Ok(cams) = dreamscene::camera::read_cameras(&dir.join("cameras.json")) else {
        return false;
    };
    !cams.is_empty()
        && (cams
            .iter()
            .any(|c| !dir.join(format!("{}.png", c.img_name)).is_file())
            || !dir.join(SHEET).is_file())
}

pub(super) fn complete_renders(out: &Path, a: &GenerateArgs) -> Result<Option<String>> {
    let dir = out.join("renders");
    let cams_path = dir.join("cameras.json");
    if !cams_path.is_file() {
        if a.renders == 0 {
            return Ok(None);
        }
        let layout = Layout::read(&out.join("layout.json"))?;
        let g = dreamscene::splat::ply::read_ply(&out.join("scene.ply"))?;
        let n = render_chosen(&g, &layout, a.renders, a.resolution, &dir)?;
        return Ok(Some(format!("the {n} views")));
    }
    let cams = dreamscene::camera::read_cameras(&cams_path)?;
    let view = |c: &Camera| dir.join(format!("{}.png", c.img_name));
    let missing = cams.iter().filter(|c| !view(c).is_file()).count();
    let sheet_missing = !dir.join(SHEET).is_file();
    if missing == 0 && !sheet_missing {
        return Ok(None);
    }
    // Every view is rendered again (deterministic) so the sheet is the one a whole run makes;
    // the views already there are kept as they are.
    let g = dreamscene::splat::ply::read_ply(&out.join("scene.ply"))?;
    render_views_to(&g, &cams, &dir, |c| !view(c).is_file())?;
    let mut said = vec![];
    if missing > 0 {
        said.push(format!("the {missing} missing views"));
    }
    if sheet_missing {
        said.push(format!("renders/{SHEET}"));
    }
    Ok(Some(said.join(" and ")))
}

/// The contact sheet of the views in `renders/`.
const SHEET: &str = "overview.png";

/// Renders up to `count` views chosen by what they show (`camera::scene::render_views`; a room
/// that cannot give that many distinct good pictures gets fewer) into `dir`, with
/// `dir/cameras.json` and the contact sheet `dir/overview.png`. Returns how many it rendered.
pub(super) fn render_chosen(
    g: &Gaussians,
    layout: &Layout,
    count: usize,
    res: u32,
    dir: &Path,
) -> Result<usize> {
    super::create_dir(dir)?;
    let cams = render_views(&SceneBox::from_layout(layout), count, res, res);
    write_cameras(&dir.join("cameras.json"), &cams)
        .with_context(|| format!("writing {}/cameras.json", dir.display()))?;
    render_views_to(g, &cams, dir, |_| true)?;
    Ok(cams.len())
}

/// Renders `cams` of `g`, writes the views `write` picks into `dir` and the contact sheet of all
/// of them (written last: a run killed before it is not complete).
fn render_views_to(
    g: &Gaussians,
    cams: &[Camera],
    dir: &Path,
    write: impl Fn(&Camera) -> bool,
) -> Result<()> {
    let ctx = super::open_device()?;
    let r = Rasterizer::new(&ctx)?;
    let mut source = ViewSource::new(&ctx, g);
    let mut shots = vec![];
    for cam in cams {
        let img = r
            .forward(&ctx, source.for_camera(&ctx, cam)?, cam, BACKGROUND)?
            .read()?;
        if write(cam) {
            super::save_png(&img, &dir.join(format!("{}.png", cam.img_name)))?;
        }
        shots.push(img);
    }
    let tiles: Vec<_> = shots
        .iter()
        .map(|i| (i.width, i.height, i.color.as_slice()))
        .collect();
    let sheet = dreamscene::util::contact_sheet(&tiles, 4, 256);
    super::write_png(&sheet, &dir.join(SHEET))
}
