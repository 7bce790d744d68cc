//! Repeats: a later render view that adds little to an earlier one looking the same way. Two
//! pictures of the same corner (the door and the bookcase of a living room from two spots a
//! metre apart) are not near copies by their framing, yet a person flicking through the views
//! sees the same thing twice. A later view must add coverage: something the earlier view looking
//! the same way did not show, and a view looking much the same way at the same piece at the back
//! of the picture (its backdrop: the bookcase of that corner) shows the same corner again,
//! whatever stands before it. Judged from the layout boxes alone (occlusion ignored); the
//! render views are scored against it (`choose.rs`) and the framing figure counts it
//! (`faults.rs`). Host-only.
use super::faults::depth;
use super::views::FLAT;
use super::SceneBox;
use crate::camera::Camera;

/// Two views look the same way when their horizontal directions are at most this cosine apart
/// (41°): from further round, the same objects show other sides and stand in other places of
/// the frame, a picture of its own.
pub const REPEAT_COS: f64 = 0.75;
/// A later view looking the same way as an earlier one repeats it when less than this share of
/// what it shows (its objects' shares of the frame, summed) is of objects the earlier one does
/// not show: a quarter of the picture new is the least a person calls another view.
pub const REPEAT_NEW: f64 = 0.25;
/// An earlier view shows an object when it covers more than this share of its frame (a
/// sliver at the frame's side counts: the person saw it there).
pub const REPEAT_SEEN: f64 = 0.01;

/// Two views with the same backdrop ([`backdrop`]) look at the same corner when their
/// directions are at most this cosine apart (66°): the bookcase by the door seen from the
/// window and from the TV. Views of one piece from opposite quarters show other walls behind it.
pub const BACKDROP_COS: f64 = 0.4;
/// A view's backdrop stands at least this share of the way from the camera to the wall (the
/// ground's edge) ahead, along the view's direction.
pub const BACKDROP_FAR: f64 = 0.5;
/// The least share of the frame a backdrop covers.
const BACKDROP_SHARE: f64 = 0.02;

/// What a view is, for telling repeats: its horizontal direction, what it shows (objects as
/// `(index, share of the frame)`, in index order) and its backdrop ([`backdrop`]).
#[derive(Debug, Clone, Copy)]
pub struct Look<'a> {
    pub dir: [f64; 2],
    pub shows: &'a [(usize, f64)],
    pub backdrop: Option<usize>,
}

/// The backdrop of `cam`'s view: of the (upright) objects it shows (`shows`, as in [`Look`])
/// standing at the back of the picture ([`BACKDROP_FAR`]), the one covering the most of the
/// frame; what a person names the view by ("the bookcase corner"). None when that is the
/// room's `focal` object (the board pupils' desks face): the views that look the way the room
/// looks all have it at their back, and a few of them are wanted.
pub fn backdrop(
    scene: &SceneBox,
    cam: &Camera,
    shows: &[(usize, f64)],
    focal: Option<usize>,
) -> Option<usize> {
    let dir = heading(cam);
    let far = BACKDROP_FAR * depth(scene, cam);
    shows
        .iter()
        .filter(|&&(k, s)| {
            let o = &scene.objects[k];
            let along = (o.position[0] - cam.position[0]) * dir[0]
                + (o.position[1] - cam.position[1]) * dir[1];
            s > BACKDROP_SHARE && o.size[2] > FLAT && along >= far
        })
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .map(|s| s.0)
        .filter(|k| Some(*k) != focal)
}

/// The horizontal unit direction `cam` looks in.
pub fn heading(cam: &Camera) -> [f64; 2] {
    let (fx, fy) = (cam.rotation[0][2], cam.rotation[1][2]);
    let n = fx.hypot(fy).max(1e-9);
    [fx / n, fy / n]
}

/// The share of what `later` shows (objects as `(index, share of the frame)`, in index order)
/// that is of objects `earlier` (the same) does not show (see [`REPEAT_SEEN`]); 1 when
/// `later` shows nothing.
pub fn new_share(later: &[(usize, f64)], earlier: &[(usize, f64)]) -> f64 {
    let total: f64 = later.iter().map(|s| s.1).sum();
    if total <= 0.0 {
        return 1.0;
    }
    let mut j = 0;
    let mut old = 0.0;
    for &(k, x) in later {
        while j < earlier.len() && earlier[j].0 < k {
            j += 1;
        }
        if earlier
            .get(j)
            .is_some_and(|s| s.0 == k && s.1 > REPEAT_SEEN)
        {
            old += x;
        }
    }
    (total - old) / total
}

/// True when the view `later` repeats `earlier`: they look the same way ([`REPEAT_COS`]) and
/// `later` adds less than [`REPEAT_NEW`] of new content ([`new_share`]), or they look much the
/// same way ([`BACKDROP_COS`]) at the same backdrop.
pub fn repeats(later: Look, earlier: Look) -> bool {
    let cos = later.dir[0] * earlier.dir[0] + later.dir[1] * earlier.dir[1];
    (cos >= REPEAT_COS && new_share(later.shows, earlier.shows) < REPEAT_NEW)
        || (cos >= BACKDROP_COS && later.backdrop.is_some() && later.backdrop == earlier.backdrop)
}

/// The objects a view shows, `(index, share)` in index order, from each object's share.
pub fn sparse(shares: &[f64]) -> Vec<(usize, f64)> {
    shares
        .iter()
        .copied()
        .enumerate()
        .filter(|s| s.1 > 0.0)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_view_of_what_an_earlier_one_showed_the_same_way_repeats_it() {
        let north = [0.0, 1.0];
        // The door and bookcase corner, then the same corner with an armchair the first view
        // had at its side: nothing new.
        let first = [(0, 0.2), (1, 0.3), (2, 0.05)];
        let again = [(0, 0.15), (1, 0.2), (2, 0.3)];
        assert!(new_share(&again, &first) < 1e-9);
        let look = |dir, shows| Look {
            dir,
            shows,
            backdrop: None,
        };
        assert!(repeats(look(north, &again), look(north, &first)));
        // Turned 60° away, the same objects stand elsewhere in a picture of its own.
        let turned = [60f64.to_radians().sin(), 60f64.to_radians().cos()];
        assert!(!repeats(look(turned, &again), look(north, &first)));
        // A third of the picture is a sofa the first view did not show: a view of its own.
        let more = [(0, 0.1), (1, 0.1), (3, 0.1)];
        assert!((new_share(&more, &first) - 1.0 / 3.0).abs() < 1e-9);
        assert!(!repeats(look(north, &more), look(north, &first)));
        // The same backdrop (object 1) 60° round, a sofa new before it: the same corner.
        let with = |dir, shows| Look {
            backdrop: Some(1),
            ..look(dir, shows)
        };
        assert!(repeats(with(turned, &more), with(north, &first)));
        // From the opposite quarter the same piece stands before another wall.
        let round = [120f64.to_radians().sin(), 120f64.to_radians().cos()];
        assert!(!repeats(with(round, &more), with(north, &first)));
        // A sliver the first view barely showed counts as new.
        let sliver = [(0, 0.2), (1, 0.3), (4, 0.005)];
        let past = [(0, 0.1), (4, 0.4)];
        assert!(new_share(&past, &sliver) > 0.7);
        // An empty view adds nothing, yet it is no repeat by content: it is all new.
        assert_eq!(new_share(&[], &first), 1.0);
    }
}
