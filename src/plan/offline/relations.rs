//! The relations stage of the offline planner: anchors (the category's, the scene's, then the
//! text's) and relations (the text's, spread over the instances; the scene's defaults, held by
//! what fills a replaced default's role; then the functional groups, the text's own kept).
use super::Draft;
use crate::plan::spec::{Anchor, Relation, RelationKind, SceneSpec, SceneType};
use std::collections::{BTreeMap, BTreeSet};

/// The category mention `i` means: a reference ("the table" after a round table, "each
/// umbrella") means what the object it refers to was planned as.
fn meant<'a>(d: &'a Draft, i: usize) -> &'a String {
    let ms = &d.r.mentions;
    let m = &ms[i];
    let first = ms
        .iter()
        .position(|o| !o.reference && !o.negated && o.category == m.category)
        .filter(|_| m.reference && !d.counts.contains_key(&d.cats[i]));
    &d.cats[first.unwrap_or(i)]
}

/// The mentions the text gives one of the anchors `kinds`.
fn anchored(r: &crate::plan::lang::Reading, kinds: &[Anchor]) -> BTreeSet<usize> {
    r.anchors
        .iter()
        .filter(|(_, a)| kinds.contains(a))
        .map(|&(mi, _)| mi)
        .collect()
}

/// Each category's anchor: the category's, the scene's, then the text's.
pub(super) fn anchors(d: &Draft) -> BTreeMap<String, Anchor> {
    let Draft {
        kb,
        r,
        scene,
        scene_type,
        counts,
        ..
    } = d;
    let scene_type = *scene_type;
    let mut anchors: BTreeMap<String, Anchor> = BTreeMap::new();
    for c in counts.keys() {
        let a = kb.object(c).map(|o| o.anchor).unwrap_or(Anchor::Others);
        anchors.insert(c.clone(), a);
    }
    if let Some(s) = scene {
        for (c, a) in &s.anchors {
            if counts.contains_key(c) {
                anchors.insert(c.clone(), *a);
            }
        }
    }
    // a counter staff stand behind (kb/placement.txt: staffed) keeps their room from the wall
    // the scene would put it against; one the text puts at a wall stands there (below)
    let table = crate::plan::gcp::classes::Placements::builtin();
    for (c, a) in anchors.iter_mut() {
        if *a == Anchor::Side && table.staff_depth(c).is_some() {
            *a = Anchor::Others;
        }
    }
    // "in one corner, facing the window": one anchor per object, and the facing is what a
    // position word cannot give back, so it stays
    let facing = anchored(r, &[Anchor::FaceWindow, Anchor::FaceDoor]);
    // "a reading nook by the window": the place's main piece (what it cannot do without, else
    // its first default), or what the text names in that piece's role, is where the place is
    if let (Some(a), Some(s)) = (r.place_anchor, scene) {
        let main = s
            .objects
            .iter()
            .find(|(c, _)| s.essential.contains(c))
            .or(s.objects.first())
            .map(|(c, _)| c.as_str());
        let role = main.and_then(crate::plan::roles::role_of);
        let piece = main.filter(|c| counts.contains_key(*c)).or_else(|| {
            counts
                .keys()
                .find(|k| role.is_some() && crate::plan::roles::role_of(k) == role)
                .map(|k| k.as_str())
        });
        if let Some(c) = piece {
            anchors.insert(c.to_string(), a);
        }
    }
    // "a tree in the corner by the window", "a desk against the wall by the door": the window
    // or door says which corner or wall, so it is the anchor
    let by_opening = anchored(r, &[Anchor::Window, Anchor::Door]);
    for &(mi, a) in &r.anchors {
        let c = meant(d, mi);
        if matches!(a, Anchor::Corner | Anchor::Side) && by_opening.contains(&mi) {
            continue;
        }
        if counts.contains_key(c)
            && (matches!(a, Anchor::FaceWindow | Anchor::FaceDoor) || !facing.contains(&mi))
        {
            anchors.insert(c.clone(), a);
        }
    }
    if scene_type == SceneType::Outdoor {
        for a in anchors.values_mut() {
            if *a == Anchor::Corner {
                *a = Anchor::Side;
            }
        }
    }
    anchors
}

/// The spec's relations: the text's (every instance of a plural subject), then the scene's
/// defaults, then the functional groups (the text's own stay).
pub(super) fn relations(d: &Draft, spec: &mut SceneSpec) {
    let Draft {
        r, scene, counts, ..
    } = d;
    let mut keep: BTreeSet<(String, String)> = BTreeSet::new();
    let mut pairs: BTreeSet<(String, String)> = BTreeSet::new();
    let mut push = |spec: &mut SceneSpec, s: String, rel, o: String, user: bool| {
        if s == o {
            return;
        }
        let key = (s.clone().min(o.clone()), s.clone().max(o.clone()));
        if pairs.insert(key) {
            if user {
                keep.insert((s.clone(), o.clone()));
            }
            spec.relations.push(Relation {
                subject: s,
                relation: rel,
                object: o,
            });
        }
    };
    for &(si, rel, oi) in &r.relations {
        let (sc, oc) = (meant(d, si), meant(d, oi));
        let (Some(&ns), Some(_)) = (counts.get(sc), counts.get(oc)) else {
            continue;
        };
        // "two sofas facing each other": the second of the pair faces the first (a pair of
        // seats at a table faces across it as the group has them)
        if si == oi {
            if rel == crate::plan::spec::RelationKind::Opposite
                && ns == 2
                && crate::plan::groups::group_of(spec, sc).is_none()
            {
                push(spec, format!("{sc}2"), rel, format!("{sc}1"), true);
            }
            continue;
        }
        // A seat "around" or "at" its table is the group's relation, whatever the phrase.
        let rel = match crate::plan::groups::group_of(spec, sc) {
            Some((g, t))
                if t == *oc
                    && matches!(
                        rel,
                        crate::plan::spec::RelationKind::Around
                            | crate::plan::spec::RelationKind::At
                            | crate::plan::spec::RelationKind::AtBack
                            | crate::plan::spec::RelationKind::Next
                            | crate::plan::spec::RelationKind::Flank
                    ) =>
            {
                g
            }
            _ => rel,
        };
        // "40 seats facing a screen" in a lecture hall: its seats face the screen in rows
        use crate::plan::spec::RelationKind::{Opposite, Row};
        // and so do things the text sets out in rows ("twelve mats in three rows of four, all
        // facing the instructor's mat"): each row faces it, not each thing its narrow front
        let in_rows = r.mentions[si].rows > 0 || r.mentions[si].in_rows;
        let rel = match scene {
            _ if rel == Opposite && in_rows => Row,
            Some(s)
                if rel == Opposite
                    && s.relations
                        .iter()
                        .any(|k| k.relation == Row && k.subject == *sc && k.object == *oc) =>
            {
                Row
            }
            _ => rel,
        };
        // "a bench on each side of every table": every bench, spread over the tables
        let every = r.mentions[si].plural
            || r.mentions[si].count.unwrap_or(1) > 1
            || r.mentions[si].each_of == Some(oi);
        let n = if every { ns } else { 1 };
        if rel == crate::plan::spec::RelationKind::Around
            || rel == crate::plan::spec::RelationKind::Flank
            || rel == crate::plan::spec::RelationKind::At
            || rel == crate::plan::spec::RelationKind::AtBack
        {
            // groups spread them over the object's instances
            if crate::plan::groups::group_of(spec, sc).is_some_and(|(_, t)| t == *oc) {
                continue;
            }
        }
        // "a lamp on each nightstand", "chairs in front of the sofas": the subjects spread
        // over the object's instances, one relation per item; "the nightstand" is one
        let no = counts.get(oc).copied().unwrap_or(1).max(1);
        let om = &r.mentions[oi];
        // "three tables, each under a parasol": a parasol of its own for each table
        let spread =
            om.reference || om.plural || om.count.is_some_and(|c| c > 1) || om.each_of == Some(si);
        let n = if spread && no > 1 {
            n.max(ns.min(no))
        } else {
            n
        };
        for k in 1..=n {
            let ko = if spread { (k - 1) % no + 1 } else { 1 };
            push(spec, format!("{sc}{k}"), rel, format!("{oc}{ko}"), true);
        }
    }
    // tables laid for different numbers: the seats said for each table at it
    for (table, (seat, each)) in &d.laid {
        let (Some(&nt), Some(&ns)) = (counts.get(table), counts.get(seat)) else {
            continue;
        };
        let rel = crate::plan::groups::relation_between(seat, table)
            .unwrap_or(crate::plan::spec::RelationKind::Around);
        let mut k = 0;
        for (t, &(per, _)) in each.iter().enumerate().take(nt as usize) {
            for _ in 0..per {
                if k < ns {
                    k += 1;
                    push(
                        spec,
                        format!("{seat}{k}"),
                        rel,
                        format!("{table}{}", t + 1),
                        true,
                    );
                }
            }
        }
    }
    seats_said_per_host(d, spec, &mut push);
    if let Some(sc) = scene {
        // a scene's relation of a default that a named thing of its role replaced holds for
        // that thing (the teacher's desk before the whiteboard that replaced the blackboard)
        let filling = |c: &str| -> Option<String> {
            if counts.contains_key(c) {
                return Some(c.to_string());
            }
            let role = crate::plan::roles::role_of(c)?;
            counts
                .keys()
                .find(|k| crate::plan::roles::role_of(k) == Some(role))
                .cloned()
        };
        // where the text puts a thing ("chairs stacked against the back wall") beats where
        // the scene would have it (in rows before the stage)
        // (unless the other stands at that kind of place too: a dryer said against the wall
        // still stands beside the washing machine there)
        let placed: BTreeMap<&String, Anchor> =
            r.anchors.iter().map(|&(mi, a)| (meant(d, mi), a)).collect();
        for rel in &sc.relations {
            let (Some(subject), Some(object)) = (filling(&rel.subject), filling(&rel.object))
            else {
                continue;
            };
            if placed.get(&subject).is_some_and(|a| {
                rel.relation != RelationKind::Next
                    || spec.anchors.get(&format!("{object}1")) != Some(a)
            }) {
                continue;
            }
            let (ns, no) = (counts[&subject], counts[&object]);
            if rel.every && subject == object {
                // a run ("washing machine* NEXT washing machine"): each beside the one before
                for k in 2..=ns {
                    push(
                        spec,
                        format!("{subject}{k}"),
                        rel.relation,
                        format!("{object}{}", k - 1),
                        false,
                    );
                }
                continue;
            }
            let n = if rel.every { ns } else { 1 };
            for k in 1..=n {
                // every one of them spread over the objects ("beer bench* NEXT bench table")
                let ko = if rel.every {
                    (k - 1) % no.max(1) + 1
                } else {
                    1
                };
                push(
                    spec,
                    format!("{subject}{k}"),
                    rel.relation,
                    format!("{object}{ko}"),
                    false,
                );
            }
        }
    }
    // things hung on a wall asked in a row ("four posters in a row on the wall"): a run along
    // one wall, each beside the one before, never rows standing on the floor
    for (i, m) in r.mentions.iter().enumerate() {
        let c = meant(d, i);
        let n = counts.get(c).copied().unwrap_or(0);
        if m.negated || !(m.in_rows || m.rows > 0) || n < 2 || !on_wall(c) {
            continue;
        }
        let width = spec.objects.get(c).map_or(f64::INFINITY, |o| o.size[0]);
        if n as f64 * width > RUN_ON_A_WALL {
            // too long a run for one wall of a room: spread over the walls
            continue;
        }
        for k in 2..=n {
            push(
                spec,
                format!("{c}{k}"),
                RelationKind::Next,
                format!("{c}{}", k - 1),
                true,
            );
        }
    }
    // things standing on the floor asked along one wall ("six chairs along the wall"): a run
    // there, each beside the one before (the layout stands the run along one wall)
    for &mi in &r.one_wall {
        let c = meant(d, mi);
        let n = counts.get(c).copied().unwrap_or(0);
        if r.mentions[mi].negated || n < 2 || !stands_on_floor(c) {
            continue;
        }
        for k in 2..=n {
            push(
                spec,
                format!("{c}{k}"),
                RelationKind::Next,
                format!("{c}{}", k - 1),
                true,
            );
        }
    }
    crate::plan::groups::apply_named(spec, &keep, &d.named);
}

/// "six lab benches, each with two stools", "manicure tables each with a chair on both sides":
/// seats the text gives each of a thing sit at that thing, as many at each as said: as the
/// functional group seats them there, else at its front (on both sides: around it), beside a
/// bed or another seat. Seats the text already relates stay where it puts them.
fn seats_said_per_host(
    d: &Draft,
    spec: &mut SceneSpec,
    push: &mut impl FnMut(&mut SceneSpec, String, RelationKind, String, bool),
) {
    use crate::plan::lang::is_seat;
    let mut taken: BTreeMap<String, u32> = BTreeMap::new();
    for (i, m) in d.r.mentions.iter().enumerate() {
        let Some(x) = m.each_of.filter(|_| !m.negated) else {
            continue;
        };
        let (c, h) = (meant(d, i).clone(), meant(d, x).clone());
        let (Some(&ns), Some(&nh)) = (d.counts.get(&c), d.counts.get(&h)) else {
            continue;
        };
        if c == h || !is_seat(&c) || !stands_on_floor(&h) {
            continue;
        }
        let per = m.count.unwrap_or(1) * m.parts;
        // (a bench things stand on is a work top, not a seat)
        let top = crate::plan::gcp::classes::Placements::builtin().is_support(&h);
        let lies =
            !top && (is_seat(&h) || matches!(h.rsplit(' ').next(), Some("bed" | "cot" | "bunk")));
        let rel = if let Some(g) = crate::plan::groups::relation_between(&c, &h) {
            // the group's way of seating them, as many at each as the text says
            g
        } else if lies {
            RelationKind::Next
        } else if m.parts > 1 || per >= 3 {
            RelationKind::Around
        } else {
            RelationKind::At
        };
        let related = |spec: &SceneSpec, id: &str| spec.relations.iter().any(|r| r.subject == id);
        let mut k = taken.get(&c).copied().unwrap_or(0);
        for host in 1..=nh {
            for _ in 0..per {
                // the next seat the text has not put anywhere yet
                while k < ns && related(spec, &format!("{c}{}", k + 1)) {
                    k += 1;
                }
                if k >= ns {
                    break;
                }
                k += 1;
                push(spec, format!("{c}{k}"), rel, format!("{h}{host}"), true);
            }
        }
        taken.insert(c, k);
    }
}

/// Whether a category stands on the floor (its own footprint, not hung nor on a support).
fn stands_on_floor(category: &str) -> bool {
    use crate::plan::gcp::classes::Class;
    matches!(class(category), Class::Floor | Class::AgainstWall)
}

/// The longest run of things hung side by side on one wall (metres of their widths).
const RUN_ON_A_WALL: f64 = 4.5;

fn class(category: &str) -> crate::plan::gcp::classes::Class {
    crate::plan::gcp::classes::Placements::builtin().class(category)
}

/// Whether a category hangs on a wall: asked "in a row", it stands in a run there.
fn on_wall(category: &str) -> bool {
    matches!(class(category), crate::plan::gcp::classes::Class::OnWall(_))
}

/// Whether a category hangs on a wall or from the ceiling: asked "in a row", it never stands
/// in rows on the floor.
pub(super) fn hung(category: &str) -> bool {
    use crate::plan::gcp::classes::Class;
    matches!(class(category), Class::OnWall(_) | Class::Ceiling)
}
