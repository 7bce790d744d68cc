//! Placement classes (kb/placement.txt): where a category stands. `floor` and `against_wall`
//! things have a floor footprint of their own; `on_wall` things hang on a wall at a mounting
//! height; `on_surface` things rest on the top of a support (OVER); `ceiling` things hang from
//! the ceiling. [`apply`] turns the classes into the spec's own terms (a SIDE anchor, an OVER
//! relation to a support) before the search, and [`Mounts`] gives the search the heights.
use crate::plan::spec::{Anchor, Relation, RelationKind, SceneSpec, SceneType};
use std::collections::BTreeMap;
use std::sync::OnceLock;

mod flank;
mod support;
use flank::flank_with_support;
pub use support::{support_in, supports_in};

/// Where a category stands.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Class {
    Floor,
    AgainstWall,
    /// Hung on a wall, its bottom face at this height (m).
    OnWall(f64),
    /// On one of the supports; hung on a wall at this height when the scene has none.
    OnSurface(Option<f64>),
    Ceiling,
}

/// One line of the table.
#[derive(Debug, Clone, PartialEq)]
pub struct Placement {
    pub class: Class,
    /// Categories that can hold it (on_surface), most fitting first.
    pub supports: Vec<String>,
    /// Depth kept free before its front (m): a door or drawer that opens there, a person who
    /// stands there to use it (a stove, a fridge, a wardrobe); `None` when the table gives none.
    pub front: Option<f64>,
}

/// The placement table by category.
#[derive(Debug, Clone, Default)]
pub struct Placements {
    by_category: BTreeMap<String, Placement>,
    /// (seats, screens) pairs of `faces` lines: what a seat of the list is turned toward.
    pub faces: Vec<(Vec<String>, Vec<String>)>,
    /// `indoors` lines: the size of a thing of outdoor scale when it stands in a room.
    indoors: BTreeMap<String, [f64; 3]>,
    /// `staffed` lines: the counters staff stand behind, and the depth kept for them there.
    staffed: BTreeMap<String, f64>,
    /// `spans` lines: what runs the whole length of one side of an outdoor ground (the sea).
    spans: Vec<String>,
}

impl Placements {
    /// Parses the table; errors name the line.
    pub fn parse(text: &str) -> Result<Placements, String> {
        let mut by_category = BTreeMap::new();
        let mut faces = vec![];
        let mut indoors = BTreeMap::new();
        let mut staffed = BTreeMap::new();
        let mut spans = vec![];
        let list =
            |v: &str| -> Vec<String> { v.split(',').map(|s| s.trim().to_string()).collect() };
        for (n, line) in text.lines().enumerate() {
            let line = line.trim();
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            let err = |m: &str| format!("placement.txt line {}: {m}", n + 1);
            let f: Vec<&str> = line.split('|').map(str::trim).collect();
            if f[0] == "faces" {
                if f.len() != 3 || f[1].is_empty() || f[2].is_empty() {
                    return Err(err("needs 3 fields: faces | seats | screens"));
                }
                faces.push((list(f[1]), list(f[2])));
                continue;
            }
            if f[0] == "staffed" {
                let depth = f.get(2).and_then(|v| v.parse::<f64>().ok());
                let Some(depth) = depth.filter(|d| f.len() == 3 && *d > 0.0 && *d <= 2.0) else {
                    return Err(err(
                        "needs 3 fields: staffed | categories | depth (up to 2 m)",
                    ));
                };
                for c in list(f[1]) {
                    staffed.insert(c, depth);
                }
                continue;
            }
            if f[0] == "spans" {
                if f.len() != 2 || f[1].is_empty() {
                    return Err(err("needs 2 fields: spans | categories"));
                }
                spans.extend(list(f[1]));
                continue;
            }
            if f[0] == "indoors" {
                let size: Vec<f64> = f
                    .get(2)
                    .map(|v| {
                        v.split_whitespace()
                            .filter_map(|x| x.parse().ok())
                            .collect()
                    })
                    .unwrap_or_default();
                if f.len() != 3 || size.len() != 3 || size.iter().any(|v| !(*v > 0.0 && *v < 2.8)) {
                    return Err(err(
                        "needs 3 fields: indoors | category | W D H (under 2.8 m)",
                    ));
                }
                indoors.insert(f[1].to_string(), [size[0], size[1], size[2]]);
                continue;
            }
            if f.len() != 4 && f.len() != 5 {
                return Err(err(
                    "needs 4 or 5 fields: category | class | height | supports [| front clearance]",
                ));
            }
            let front = match f.get(4) {
                None => None,
                Some(v) => Some(
                    v.parse::<f64>()
                        .ok()
                        .filter(|v| v.is_finite() && *v > 0.0 && *v <= 2.0)
                        .ok_or_else(|| err(&format!("front clearance `{v}`")))?,
                ),
            };
            let height = match f[2] {
                "-" => None,
                h => Some(
                    h.parse::<f64>()
                        .ok()
                        .filter(|v| v.is_finite() && *v >= 0.0 && *v < 10.0)
                        .ok_or_else(|| err(&format!("height `{h}`")))?,
                ),
            };
            let class = match (f[1], height) {
                ("floor", None) => Class::Floor,
                ("against_wall", None) => Class::AgainstWall,
                ("on_wall", Some(h)) => Class::OnWall(h),
                ("on_surface", h) => Class::OnSurface(h),
                ("ceiling", None) => Class::Ceiling,
                (c, _) => return Err(err(&format!("class `{c}` with height `{}`", f[2]))),
            };
            let supports: Vec<String> = if f[3] == "-" { vec![] } else { list(f[3]) };
            if matches!(class, Class::OnSurface(_)) == supports.is_empty() {
                return Err(err("on_surface, and only it, names its supports"));
            }
            if by_category
                .insert(
                    f[0].to_string(),
                    Placement {
                        class,
                        supports,
                        front,
                    },
                )
                .is_some()
            {
                return Err(err(&format!("`{}` listed twice", f[0])));
            }
        }
        Ok(Placements {
            by_category,
            faces,
            indoors,
            staffed,
            spans,
        })
    }

    /// The size `category` has standing in a room, when the table gives one (a flagpole is an
    /// indoor flag stand, a tree a tree in a tub): things of outdoor scale never set a room's
    /// ceiling.
    pub fn indoor_size(&self, category: &str) -> Option<[f64; 3]> {
        self.indoors.get(category).copied()
    }

    /// The depth (m) kept behind `category` for the staff who stand there (a reception desk,
    /// a checkout), if the table names it.
    pub fn staff_depth(&self, category: &str) -> Option<f64> {
        self.staffed.get(category).copied().or_else(|| {
            let kb = crate::plan::kb::KnowledgeBase::builtin().object(category)?;
            self.staffed.get(&kb.category).copied()
        })
    }

    /// Whether `category` (or the knowledge-base category it names) runs the whole length of
    /// one side of an outdoor ground, out past it (the sea along a beach).
    pub fn spans_side(&self, category: &str) -> bool {
        let kb = crate::plan::kb::KnowledgeBase::builtin().object(category);
        let cat = kb.map_or(category, |o| o.category.as_str());
        self.spans.iter().any(|s| s == category || s == cat)
    }

    /// The built-in table.
    pub fn builtin() -> &'static Placements {
        static P: OnceLock<Placements> = OnceLock::new();
        P.get_or_init(|| {
            Placements::parse(include_str!("../kb/placement.txt"))
                .expect("the built-in placement table is valid (tested)")
        })
    }

    /// The placement of `category` (or of the knowledge-base category it is a synonym of),
    /// if the table has it.
    pub fn get(&self, category: &str) -> Option<&Placement> {
        self.by_category
            .get(category)
            .or_else(|| {
                let kb = crate::plan::kb::KnowledgeBase::builtin().object(category)?;
                self.by_category.get(&kb.category)
            })
            // a noun the knowledge base lacks is placed as its kind ("an escritoire" as a desk)
            .or_else(|| {
                self.by_category
                    .get(crate::plan::lexicon::kind_category(category)?)
            })
    }

    /// Whether `category` holds things (a support of some on_surface category): a desk, a
    /// counter, a table, used from its front.
    pub fn is_support(&self, category: &str) -> bool {
        self.by_category
            .values()
            .any(|p| p.supports.iter().any(|s| s == category))
    }

    /// The depth `category` keeps free before its front, if the table gives one.
    pub fn front_clearance(&self, category: &str) -> Option<f64> {
        self.get(category).and_then(|p| p.front)
    }

    /// The class of `category` (floor when the table does not name it).
    pub fn class(&self, category: &str) -> Class {
        self.get(category).map_or(Class::Floor, |p| p.class)
    }
}

/// The class `category` takes in `spec`: an on_surface thing whose scene has none of its
/// supports hangs on the wall when it has a height, else stands on the floor; one with a height
/// that the spec puts against a wall (SIDE: "a TV on the wall") hangs there.
pub fn effective_class(spec: &SceneSpec, category: &str) -> Class {
    let table = Placements::builtin();
    // the text hangs it on a wall (`ObjectSpec::on_wall`)
    if let Some(h) = spec.objects.get(category).and_then(|o| o.on_wall) {
        return Class::OnWall(h);
    }
    let on_wall = spec.objects.get(category).is_some_and(|o| {
        (1..=o.number).any(|k| spec.anchors.get(&format!("{category}{k}")) == Some(&Anchor::Side))
    });
    match table.get(category) {
        Some(Placement {
            class: Class::OnSurface(h),
            ..
        }) => {
            if let (Some(h), true) = (h, on_wall) {
                Class::OnWall(*h)
            } else if support_in(table, category, spec).is_some() {
                Class::OnSurface(*h)
            } else if let Some(h) = h {
                Class::OnWall(*h)
            } else {
                Class::Floor
            }
        }
        Some(p) => p.class,
        None => Class::Floor,
    }
}

/// Heights the search gives instances: wall mounting heights and ceiling things.
#[derive(Debug, Clone, Default)]
pub struct Mounts {
    /// Instance id -> bottom-face height on its wall.
    pub wall: BTreeMap<String, f64>,
    /// Instance ids hung from the ceiling.
    pub ceiling: Vec<String>,
    /// Instance id hung on a wall -> the thing with a floor footprint it hangs above (a shelf
    /// "on the wall above" the desk, or above the monitors on that desk).
    pub above: BTreeMap<String, String>,
    /// Instance id hung from the ceiling -> the thing with a floor footprint it hangs over (a
    /// chandelier "over the table", pendant lights "above the island").
    pub hang_over: BTreeMap<String, String>,
}

/// The share of a support's top that things set on it by their class may fill before the
/// next support of their list takes them.
const FULL_TOP: f64 = 0.8;

/// Puts the placement classes into `spec`'s own terms: against_wall and on_wall things without
/// an anchor of the user's take SIDE (indoor); an on_surface thing with no OVER/UNDER relation
/// of its own goes OVER a support instance (the first support category present, spread over
/// its instances by their top area); things a support's width cannot take side by side go to
/// another instance of it. Returns the wall heights and ceiling things.
pub fn apply(spec: &mut SceneSpec) -> Mounts {
    one_support(spec);
    super::pairs::to_named_neighbour(spec);
    super::pairs::face_screens(spec);
    let mut mounts = Mounts::default();
    let indoor = spec.scene_type == SceneType::Indoor;
    let mut load: BTreeMap<String, f64> = BTreeMap::new();
    for r in &spec.relations {
        if r.relation == RelationKind::Over {
            let a = spec
                .objects
                .get(base(&r.subject))
                .map_or(0.0, |o| o.size[0] * o.size[1]);
            *load.entry(r.object.clone()).or_default() += a;
        }
    }
    let mut added = vec![];
    // (thing, the support it rests on)
    let mut carried: Vec<(String, String)> = vec![];
    let mut unstack: Vec<String> = vec![];
    let cats: Vec<(String, u32, [f64; 3])> = spec
        .objects
        .iter()
        .map(|(c, o)| (c.clone(), o.number, o.size))
        .collect();
    for (cat, n, size) in cats {
        let class = effective_class(spec, &cat);
        for k in 1..=n {
            let id = format!("{cat}{k}");
            match class {
                Class::AgainstWall | Class::OnWall(_) if indoor => {
                    // (a counter staff stand behind keeps their room from the wall, and a thing
                    // the text stands on another stands where that one does)
                    let staffed = Placements::builtin().staff_depth(&cat).is_some();
                    let on_another = matches!(class, Class::AgainstWall)
                        && spec
                            .relations
                            .iter()
                            .any(|r| r.subject == id && r.relation == RelationKind::Over);
                    let a = spec.anchors.entry(id.clone()).or_insert(Anchor::Side);
                    // (a thing the text stands in the middle stands there: "a workbench in
                    // the middle"; no default puts an against-wall kind there)
                    let hung = matches!(class, Class::OnWall(_));
                    if (*a == Anchor::Others && !staffed && !on_another)
                        || (*a == Anchor::Center && hung)
                    {
                        *a = Anchor::Side;
                    }
                    if let Class::OnWall(h) = class {
                        // hung on the wall, it rests on nothing
                        unstack.push(id.clone());
                        mounts.wall.insert(id, h);
                    }
                }
                Class::OnWall(h) => {
                    // outdoors there is no wall: it stands where it is put, at its height
                    mounts.wall.insert(id, h);
                }
                Class::Ceiling if indoor => {
                    // hung from the ceiling, it rests on nothing
                    unstack.push(id.clone());
                    mounts.ceiling.push(id);
                }
                Class::OnSurface(_) => {
                    let has_own = spec.relations.iter().any(|r| {
                        r.subject == id
                            && matches!(r.relation, RelationKind::Over | RelationKind::Under)
                    });
                    if has_own {
                        // a thing on a support keeps no anchor of its own
                        spec.anchors.remove(&id);
                        if let Some(r) = spec
                            .relations
                            .iter()
                            .find(|r| r.subject == id && r.relation == RelationKind::Over)
                        {
                            carried.push((id.clone(), r.object.clone()));
                        }
                        continue;
                    }
                    let sups: Vec<String> = supports_in(Placements::builtin(), &cat, spec)
                        .into_iter()
                        .map(str::to_string)
                        .collect();
                    // the least loaded instance of each support, by the share of its top used
                    let least = |sup: &String| {
                        let so = &spec.objects[sup];
                        let top = (so.size[0] * so.size[1]).max(1e-6);
                        (1..=so.number)
                            .map(|m| {
                                let id = format!("{sup}{m}");
                                let share = (load.get(&id).copied().unwrap_or(0.0)
                                    + size[0] * size[1])
                                    / top;
                                (id, share)
                            })
                            .min_by(|a, b| a.1.total_cmp(&b.1))
                    };
                    // the first support in the table's order with room left on a top (what the
                    // text put on a small side table keeps it: the default globe goes on the
                    // reading table), else the first
                    // ("a printer against the wall": on a support that stands there, the
                    // filing cabinet against it rather than a desk in the room)
                    let want = spec.anchors.get(&id).copied().filter(|a| {
                        matches!(
                            a,
                            Anchor::Side | Anchor::Window | Anchor::Corner | Anchor::Door
                        )
                    });
                    // (things set out in rows stand in the room, whatever their kind)
                    // (nor what is placed beside another: a filing cabinet by its desk)
                    let free = |sup: &String| {
                        !spec.relations.iter().any(|r| {
                            r.subject
                                .strip_prefix(sup.as_str())
                                .is_some_and(|k| k.parse::<u32>().is_ok())
                                && r.relation != RelationKind::Over
                        })
                    };
                    let there = |sup: &String| {
                        spec.objects.get(sup).is_some_and(|o| o.rows == 0)
                            && free(sup)
                            && want.is_some_and(|a| {
                                spec.anchors.get(&format!("{sup}1")) == Some(&a)
                                    || (a == Anchor::Side
                                        && effective_class(spec, sup) == Class::AgainstWall
                                        && !matches!(
                                            spec.anchors.get(&format!("{sup}1")),
                                            Some(Anchor::Center | Anchor::Others)
                                        ))
                            })
                    };
                    let best = sups
                        .iter()
                        .filter(|s| there(s))
                        .filter_map(least)
                        .find(|(_, share)| *share <= 1.0)
                        .or_else(|| {
                            sups.iter()
                                .filter_map(least)
                                .find(|(_, share)| *share <= FULL_TOP)
                        })
                        .or_else(|| sups.first().and_then(least))
                        .map(|(id, _)| id);
                    if let Some(oid) = best {
                        *load.entry(oid.clone()).or_default() += size[0] * size[1];
                        // a thing on a support keeps no anchor of its own
                        spec.anchors.remove(&id);
                        carried.push((id.clone(), oid.clone()));
                        added.push(Relation {
                            subject: id,
                            relation: RelationKind::Over,
                            object: oid,
                        });
                    }
                }
                _ => {}
            }
        }
    }
    let over: Vec<(String, String)> = spec
        .relations
        .iter()
        .filter(|r| unstack.contains(&r.subject) && r.relation == RelationKind::Over)
        .map(|r| (r.subject.clone(), r.object.clone()))
        .collect();
    // "a table under the chandelier": the chandelier hangs over the table
    let under: Vec<(String, String)> = spec
        .relations
        .iter()
        .filter(|r| mounts.ceiling.contains(&r.object) && r.relation == RelationKind::Under)
        .map(|r| (r.object.clone(), r.subject.clone()))
        .collect();
    spec.relations.retain(|r| {
        let stacked = unstack.contains(&r.subject)
            && matches!(r.relation, RelationKind::Over | RelationKind::Under);
        let under_hung = mounts.ceiling.contains(&r.object) && r.relation == RelationKind::Under;
        !(stacked || under_hung)
    });
    // A desk, table or counter "facing the window" (a support: used from its front) is used
    // facing it: its back to the window, and the seats at it face the window.
    let facing: Vec<String> = spec
        .anchors
        .iter()
        .filter(|(_, a)| **a == Anchor::FaceWindow)
        .map(|(id, _)| id.clone())
        .collect();
    for id in facing {
        let seats: Vec<String> = spec
            .relations
            .iter()
            .filter(|r| r.object == id && r.relation == RelationKind::At)
            .map(|r| r.subject.clone())
            .collect();
        let cat = base(&id).to_string();
        if !seats.is_empty() || Placements::builtin().is_support(&cat) {
            spec.anchors.insert(id, Anchor::Window);
            for s in seats {
                spec.anchors.insert(s, Anchor::FaceWindow);
            }
        }
    }
    // One "facing the door" with seats at it is used facing it: the seats face the door
    // across it (it stands before them, its back to the door: `Problem::seat_faces_door`).
    let facing: Vec<String> = spec
        .anchors
        .iter()
        .filter(|(_, a)| **a == Anchor::FaceDoor)
        .map(|(id, _)| id.clone())
        .collect();
    for id in facing {
        let seats: Vec<String> = spec
            .relations
            .iter()
            .filter(|r| r.object == id && r.relation == RelationKind::At)
            .map(|r| r.subject.clone())
            .collect();
        if !seats.is_empty() {
            spec.anchors.insert(id, Anchor::Others);
            for s in seats {
                spec.anchors.insert(s, Anchor::FaceDoor);
            }
        }
    }
    spec.relations.extend(added);
    flank_with_support(spec, &carried);
    for (id, target) in over.into_iter().chain(under) {
        if let Some(below) = footprint_below(spec, &target) {
            let to = if mounts.ceiling.contains(&id) {
                &mut mounts.hang_over
            } else {
                &mut mounts.above
            };
            to.entry(id).or_insert(below);
        }
    }
    give_up_middle(spec);
    spread_overflow(spec);
    mounts
}

/// The thing with a floor footprint of its own that `id` is, or stands on (the desk under the
/// monitor), if any.
fn footprint_below(spec: &SceneSpec, id: &str) -> Option<String> {
    let mut at = id.to_string();
    for _ in 0..=spec.relations.len() {
        match effective_class(spec, base(&at)) {
            Class::Floor | Class::AgainstWall => return Some(at),
            Class::OnWall(_) | Class::Ceiling => return None,
            Class::OnSurface(_) => {
                let r = spec
                    .relations
                    .iter()
                    .find(|r| r.subject == at && r.relation == RelationKind::Over)?;
                at = r.object.clone();
            }
        }
    }
    None
}

/// A thing OVER several supports rests on one: those its placement class names are kept when
/// it names any of them ("a counter and a coffee machine on it" said after the tables).
fn one_support(spec: &mut SceneSpec) {
    let table = Placements::builtin();
    let named = |r: &Relation| {
        table
            .get(base(&r.subject))
            .is_some_and(|p| p.supports.iter().any(|s| s == base(&r.object)))
    };
    let mut drop: Vec<usize> = vec![];
    for (k, r) in spec.relations.iter().enumerate() {
        if r.relation != RelationKind::Over || named(r) {
            continue;
        }
        let other_named = spec
            .relations
            .iter()
            .any(|q| q.relation == RelationKind::Over && q.subject == r.subject && named(q));
        if other_named {
            drop.push(k);
        }
    }
    let mut k = 0;
    spec.relations.retain(|_| {
        k += 1;
        !drop.contains(&(k - 1))
    });
}

/// A thing in FRONT of or BEHIND a thing anchored at a window or a door (a coffee table before
/// a sofa that faces the window) stands where that partner puts it: its own CENTER anchor gives
/// way, and so does that of a thing UNDER it (its rug).
fn give_up_middle(spec: &mut SceneSpec) {
    let edge = |a: Option<&Anchor>| {
        matches!(
            a,
            Some(Anchor::FaceWindow | Anchor::Window | Anchor::Door | Anchor::FaceDoor)
        )
    };
    let mut moved: Vec<String> = vec![];
    loop {
        let next: Vec<String> = spec
            .relations
            .iter()
            .filter(|r| spec.anchors.get(&r.subject) == Some(&Anchor::Center))
            .filter(|r| match r.relation {
                RelationKind::Front | RelationKind::Behind => {
                    edge(spec.anchors.get(&r.object)) || moved.contains(&r.object)
                }
                RelationKind::Under => moved.contains(&r.object),
                _ => false,
            })
            .map(|r| r.subject.clone())
            .collect();
        if next.is_empty() {
            break;
        }
        for id in next {
            spec.anchors.insert(id.clone(), Anchor::Others);
            moved.push(id);
        }
    }
}

/// Things OVER a support stand side by side along its width; those its width cannot take go
/// to the least loaded instance of the same support category that can ("a lamp on each
/// nightstand" said of one nightstand, four monitors said of one of two desks). When no
/// instance has room they stay where they were put.
fn spread_overflow(spec: &mut SceneSpec) {
    let width = |id: &str| spec.size_of(id).map_or(0.0, |s| s[0]);
    let mut used: BTreeMap<String, f64> = BTreeMap::new();
    let mut moves: Vec<(usize, String)> = vec![];
    for (k, r) in spec.relations.iter().enumerate() {
        if r.relation != RelationKind::Over {
            continue;
        }
        let w = width(&r.subject);
        let fits = |sup: &str, used: &BTreeMap<String, f64>| {
            used.get(sup).copied().unwrap_or(0.0) + w <= width(sup) + 0.01
        };
        if fits(&r.object, &used) {
            *used.entry(r.object.clone()).or_default() += w;
            continue;
        }
        let n = spec.objects.get(base(&r.object)).map_or(0, |o| o.number);
        let other = (1..=n)
            .map(|m| format!("{}{m}", base(&r.object)))
            .filter(|o| *o != r.object && fits(o, &used))
            .min_by(|a, b| {
                let ua = used.get(a).copied().unwrap_or(0.0);
                let ub = used.get(b).copied().unwrap_or(0.0);
                ua.total_cmp(&ub)
            });
        let to = other.unwrap_or_else(|| r.object.clone());
        *used.entry(to.clone()).or_default() += w;
        if to != r.object {
            moves.push((k, to));
        }
    }
    for (k, to) in moves {
        spec.relations[k].object = to;
    }
}

pub(super) fn base(id: &str) -> &str {
    id.trim_end_matches(|c: char| c.is_ascii_digit())
}

#[cfg(test)]
pub(super) mod tests;
