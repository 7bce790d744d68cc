//! Pieces: an object together with what rests on it (a TV on its stand, a lamp on a
//! nightstand, a vase on a sideboard) is one piece of furniture in a picture. A view of a TV on
//! its stand shows one thing, not two, and the share of the frame the piece fills is the sum of
//! its parts'. Judged from the layout boxes alone. Host-only.
use super::super::views::FLAT;
use super::super::{ObjectBox, SceneBox};

/// A piece counts as in a view when the centre of one of its objects stands inside the frame
/// narrowed by this share of its width at each side: a plant or a floor lamp cut in half by
/// the frame's side beside a TV on its stand is no second piece, the picture is of the TV.
pub(super) const SIDE_INSET: f64 = 0.05;
/// How far (metres) an object's bottom may stand from a support's top and still rest on it.
const REST: f64 = 0.05;

/// True when `o` rests on `s`: its bottom on `s`'s top and its centre over `s`'s footprint.
fn rests_on(o: &ObjectBox, s: &ObjectBox) -> bool {
    let top = s.position[2] + s.size[2];
    let above = [o.position[0], o.position[1], top];
    o.position[2] > REST && (o.position[2] - top).abs() <= REST && s.contains(above, 0.0)
}

/// For each object of `scene`, the index of the piece it belongs to: the lowest object of the
/// stack it rests in (itself when it rests on nothing).
pub(super) fn piece_of(scene: &SceneBox) -> Vec<usize> {
    let objs = &scene.objects;
    let support: Vec<Option<usize>> = objs
        .iter()
        .enumerate()
        .map(|(i, o)| {
            (0..objs.len()).find(|&j| j != i && objs[j].size[2] > FLAT && rests_on(o, &objs[j]))
        })
        .collect();
    (0..objs.len())
        .map(|i| {
            let mut k = i;
            // A chain is at most as long as the scene (a cycle of bad boxes stops there).
            for _ in 0..objs.len() {
                match support[k] {
                    Some(s) => k = s,
                    None => break,
                }
            }
            k
        })
        .collect()
}

/// The pieces a view shows: how many have an object in frame (`shown`), and the largest share
/// of the frame one (non-flat) piece covers, from each object's share.
pub(super) fn pieces_in_view(
    scene: &SceneBox,
    piece: &[usize],
    shown: &[bool],
    shares: &[f64],
) -> (usize, f64) {
    let n = scene.objects.len();
    let mut sum = vec![0.0; n];
    let mut seen = vec![false; n];
    for k in 0..n {
        if scene.objects[k].size[2] > FLAT {
            sum[piece[k]] += shares[k];
        }
        seen[piece[k]] |= shown[k];
    }
    (
        seen.iter().filter(|s| **s).count(),
        sum.into_iter().fold(0.0, f64::max),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera::scene::views::tests::boxed;
    use crate::plan::spec::SceneType;

    #[test]
    fn what_rests_on_a_piece_is_part_of_it() {
        let on = |id: &str, x: f64, y: f64, z: f64, size: [f64; 3]| ObjectBox {
            position: [x, y, z],
            ..boxed(id, x, y, size)
        };
        let scene = SceneBox {
            scene_type: SceneType::Indoor,
            room: [5.0, 4.0, 2.8],
            openings: vec![],
            objects: vec![
                boxed("tv stand1", 0.0, 1.7, [1.6, 0.45, 0.5]),
                on("tv1", 0.0, 1.75, 0.5, [1.3, 0.08, 0.75]),
                boxed("nightstand1", -2.0, -1.0, [0.5, 0.4, 0.55]),
                on("table lamp1", -2.0, -1.0, 0.55, [0.3, 0.3, 0.5]),
                // A wall shelf over the stand's end, not resting on it.
                on("shelf1", 0.6, 1.8, 1.4, [0.8, 0.25, 0.3]),
                boxed("rug1", 0.0, 0.0, [2.0, 1.4, 0.01]),
                on("coffee table1", 0.0, 0.0, 0.01, [1.0, 0.6, 0.45]),
            ],
        };
        assert_eq!(piece_of(&scene), vec![0, 0, 2, 2, 4, 5, 6]);
        let shown = [true, true, false, false, false, false, false];
        let shares = [0.25, 0.2, 0.0, 0.0, 0.0, 0.0, 0.0];
        let (n, largest) = pieces_in_view(&scene, &piece_of(&scene), &shown, &shares);
        assert_eq!(n, 1, "a TV on its stand is one piece");
        assert!((largest - 0.45).abs() < 1e-9, "{largest}");
    }
}
