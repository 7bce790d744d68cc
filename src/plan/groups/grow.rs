//! Hosts and supports grow to what a scene asks of them: a table or counter to seat its share
//! of the seats, a bench or counter to hold what stands on it side by side.
use super::{capacity, group_of, rules};
use crate::plan::gcp::classes::{Class, Placements};
use crate::plan::spec::{RelationKind, SceneSpec};
use std::collections::BTreeMap;

/// The most a host or support grows, as a multiple of its own width.
const MOST_GROWTH: f64 = 3.0;

/// Tables and counters grow to seat what the scene asks of them (ten round tables with eight
/// chairs each, eight bar stools at one bar): a seats rule's subjects spread over its hosts,
/// and a host that seats fewer than its share grows along its width (a square table stays
/// square), by 0.1 m steps up to [`MOST_GROWTH`] times its width.
pub(super) fn grow_hosts(spec: &mut SceneSpec) {
    for rule in rules().iter().filter(|r| r.per_object.is_none()) {
        let present = rule.present(spec);
        let hosts: u32 = present.iter().map(|c| spec.objects[c].number).sum();
        let seats: u32 = spec
            .objects
            .iter()
            .filter(|(c, o)| {
                o.number > 0
                    && group_of(spec, c)
                        .is_some_and(|(rel, obj)| rel == rule.relation && present.contains(&obj))
            })
            .map(|(_, o)| o.number)
            .sum();
        if hosts == 0 {
            continue;
        }
        let share = seats.div_ceil(hosts);
        for c in &present {
            // tables laid each for its own seats keep their sizes
            let Some(o) = spec.objects.get_mut(c).filter(|o| o.sizes.is_empty()) else {
                continue;
            };
            let [w, d, _] = o.size;
            let square = (w - d).abs() < 0.15;
            let mut size = o.size;
            while capacity(rule, size) < share && size[0] < MOST_GROWTH * w {
                size[0] += 0.1;
                if square {
                    size[1] = size[0];
                }
            }
            if capacity(rule, size) >= share {
                o.size = size.map(|v| (v * 100.0).round() / 100.0);
            }
        }
    }
}

/// A support grows to hold what stands on it side by side (ten computers on three benches):
/// the widest load of its instances, each thing's width and 5 cm between and at the ends, up
/// to [`MOST_GROWTH`] times its width. A single thing never grows its support, nor does one
/// that the placement table does not set on surfaces (`kb/placement.txt`'s on_surface):
/// shelves over a washer and a dryer hang on the wall above them, a load on no top.
pub(super) fn grow_supports(spec: &mut SceneSpec) {
    let table = Placements::builtin();
    let kb = crate::plan::kb::KnowledgeBase::builtin();
    let base = |id: &str| {
        id.trim_end_matches(|c: char| c.is_ascii_digit())
            .to_string()
    };
    let mut load: BTreeMap<String, (f64, u32)> = BTreeMap::new();
    for r in spec
        .relations
        .iter()
        .filter(|r| r.relation == RelationKind::Over)
    {
        let subject = base(&r.subject);
        let Some(o) = spec.objects.get(&subject) else {
            continue;
        };
        // a thing the knowledge base does not know ("a cake on the counter") is taken at its
        // word, whatever its kind's class
        if kb.object(&subject).is_some() && !matches!(table.class(&subject), Class::OnSurface(_)) {
            continue;
        }
        let e = load.entry(r.object.clone()).or_insert((0.05, 0));
        e.0 += o.size[0] + 0.05;
        e.1 += 1;
    }
    for (id, (width, n)) in load {
        let Some(o) = spec.objects.get_mut(&base(&id)) else {
            continue;
        };
        if n >= 2 && width > o.size[0] {
            o.size[0] = ((width * 10.0).ceil() / 10.0).min(MOST_GROWTH * o.size[0]);
        }
    }
}
