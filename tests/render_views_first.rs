//! The first render views, the ones a user opens first (`camera::scene::choose`): rooms of our
//! own, planned offline and laid out at seed 0, their eight views measured from the layout boxes
//! as the framing figure measures them (`examples/framing_figure.rs`).
use dreamscene::camera::scene::{render_views, view_faults, SceneBox};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;

/// The views a user opens first.
const FIRST: usize = 4;

#[test]
fn the_first_four_views_show_four_corners_not_one_twice() {
    // Each of these repeated an earlier view among its first four (the same things the same way,
    // or the same corner at the back of the picture: `repeat.rs`), 10 repeats in all, while the
    // scoring charged a repeat only past the fourth view. A repeat now costs a view there too,
    // so another corner is taken first where one frames nearly as well: 1.
    let prompts = [
        "a reading room with two armchairs, a floor lamp, a bookcase and a side table",
        "a teenager's bedroom with a bed, a desk, a gaming chair and a poster",
        "a guest room with a sofa bed, a wardrobe and a mirror",
        "a recording studio with a mixing desk, a chair, two speakers and a piano",
        "a games room with a pool table, a dartboard and a bar stool",
        "a boardroom with a long table, twelve chairs and a screen",
        "a hospital ward with four beds and four chairs",
        "a home cinema with a screen, a projector and three recliners",
        "a wine cellar with racks, a barrel table and two stools",
    ];
    let mut repeats = vec![];
    let mut poor = vec![];
    for prompt in prompts {
        let spec = plan_prompt(prompt).expect("plans").spec;
        let l = layout(&spec, LayoutOptions::seeded(0)).expect("lays out");
        let scene = SceneBox::from_layout(&l);
        let cams = render_views(&scene, 8, 512, 512);
        assert!(cams.len() >= FIRST, "{prompt}: {} views", cams.len());
        let faults = view_faults(&scene, &cams);
        for (v, f) in faults.iter().enumerate().take(FIRST) {
            if f.repeat {
                repeats.push(format!("{prompt}: view {v}"));
            }
            if f.poor() {
                poor.push(format!("{prompt}: view {v} {f:?}"));
            }
        }
    }
    assert!(
        repeats.len() <= 2,
        "repeats among the first four views: {repeats:?}"
    );
    // Avoiding a repeat takes no poorer picture in its place (main: 4, the wine cellar's three
    // objects in a bare room).
    assert!(poor.len() <= 4, "poor views among the first four: {poor:?}");
}
