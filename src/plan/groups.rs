//! Functional groups, the way furnishers place things (Holodeck's `around` + `face to`,
//! Infinigen's seat and nightstand relations): chairs around a table spread over its sides by
//! its size, a desk's chair at its front, bar stools in a row at a counter, nightstands flanking
//! the head of a bed, seats round a fire, desks in rows facing a board, a lamp on a nightstand
//! or desk, the TV across from the sofa with the coffee table between, a rug under the group.
//! They become relations of the spec (AROUND, AT, AT_BACK, FLANK, CIRCLE, ROW and the plain kinds) that
//! the GCP layout satisfies (sun loungers in pairs beneath a parasol); offline and LLM plans both go through [`apply`].
use super::spec::{Relation, RelationKind, SceneSpec};
use std::collections::{BTreeMap, BTreeSet};

/// One rule: every instance of a subject category relates to an instance of the first object
/// category present, spread over the object instances by their capacity.
struct Rule {
    subjects: &'static [&'static str],
    relation: RelationKind,
    objects: &'static [&'static str],
    /// Subject instances one object instance takes (`None`: by the object's size, seats round
    /// a table; `Some(k)`: k).
    per_object: Option<u32>,
}

const DINING_SEATS: &[&str] = &[
    "dining chair",
    "cafe chair",
    "patio chair",
    "wooden chair",
    "upholstered chair",
    "restaurant chair",
    "stacking chair",
    "kids chair",
    "stool",
    "dining bench",
    "banquet bench",
    "beer bench",
];
const TABLES: &[&str] = &[
    "dining table",
    "round table",
    "cafe table",
    "patio table",
    "kitchen table",
    "reading table",
    "conference table",
    "card table",
    "poker table",
    "bistro set table",
    "coffee shop table",
    "chess table",
    "picnic table",
    "craft table",
    "meeting table",
    "kids table",
    "bench table",
];

const RULES: &[Rule] = &[
    Rule {
        subjects: &[
            "campfire log",
            "folding chair",
            "camp chair",
            "log bench",
            "tree stump",
        ],
        relation: RelationKind::Circle,
        objects: &["fire pit", "bonfire", "campfire"],
        per_object: Some(12),
    },
    Rule {
        subjects: &["office chair"],
        relation: RelationKind::Around,
        objects: &["conference table", "meeting table"],
        per_object: None,
    },
    Rule {
        subjects: &["office chair", "gaming chair", "drafting stool"],
        relation: RelationKind::At,
        objects: &[
            "desk",
            "computer desk",
            "standing desk",
            "reception desk",
            "drafting table",
            "gaming desk",
            "spaceship console",
            "mixing desk",
            "sewing machine table",
        ],
        per_object: Some(1),
    },
    Rule {
        // desks turned the way their user looks (to the board, to the class): the seat at
        // the back
        subjects: &["dining chair", "student chair"],
        relation: RelationKind::AtBack,
        objects: &["school desk"],
        per_object: Some(1),
    },
    Rule {
        subjects: &["office chair"],
        relation: RelationKind::AtBack,
        objects: &["teacher desk"],
        per_object: Some(1),
    },
    Rule {
        subjects: DINING_SEATS,
        relation: RelationKind::Around,
        objects: TABLES,
        per_object: None,
    },
    Rule {
        subjects: &["banquet chair"],
        relation: RelationKind::Around,
        objects: &["round banquet table", "banquet table"],
        per_object: None,
    },
    Rule {
        subjects: &["bar stool", "stool"],
        relation: RelationKind::At,
        objects: &[
            "bar counter",
            "kitchen island",
            "counter",
            "breakfast bar",
            "sushi counter",
        ],
        per_object: None,
    },
    Rule {
        subjects: &["vanity stool"],
        relation: RelationKind::At,
        objects: &["vanity table"],
        per_object: Some(1),
    },
    Rule {
        subjects: &["piano bench"],
        relation: RelationKind::At,
        objects: &["piano"],
        per_object: Some(1),
    },
    Rule {
        subjects: &["nightstand"],
        relation: RelationKind::Flank,
        objects: &[
            "bed",
            "single bed",
            "hospital bed",
            "bunk bed",
            "canopy bed",
            "daybed",
        ],
        per_object: Some(2),
    },
    Rule {
        subjects: &["school desk"],
        relation: RelationKind::Row,
        objects: &["blackboard", "whiteboard", "smartboard"],
        per_object: Some(40),
    },
    Rule {
        subjects: &["table lamp"],
        relation: RelationKind::Over,
        objects: &[
            "nightstand",
            "desk",
            "side table",
            "dresser",
            "console table",
            "sideboard",
        ],
        per_object: Some(1),
    },
    Rule {
        subjects: &["computer", "laptop"],
        relation: RelationKind::Over,
        objects: &["desk", "computer desk", "standing desk", "office desk"],
        per_object: Some(1),
    },
    Rule {
        subjects: &["tv"],
        relation: RelationKind::Over,
        objects: &["tv stand"],
        per_object: Some(1),
    },
    Rule {
        subjects: &["cash register", "coffee machine"],
        relation: RelationKind::Over,
        objects: &["counter", "bar counter", "kitchen counter"],
        per_object: Some(1),
    },
    Rule {
        subjects: &["coffee table"],
        relation: RelationKind::Front,
        objects: &["sofa", "loveseat", "sectional sofa"],
        per_object: Some(1),
    },
    Rule {
        subjects: &["tv stand"],
        relation: RelationKind::Opposite,
        objects: &["sofa", "loveseat", "sectional sofa"],
        per_object: Some(1),
    },
    Rule {
        subjects: &["lounge chair", "pool lounger"],
        relation: RelationKind::Under,
        objects: &["beach umbrella"],
        per_object: Some(2),
    },
    Rule {
        // a bridge crosses its pond: the water lies under it
        subjects: &["pond", "koi pond"],
        relation: RelationKind::Under,
        objects: &["wooden bridge"],
        per_object: Some(1),
    },
    Rule {
        subjects: &["rug"],
        relation: RelationKind::Under,
        objects: &["coffee table", "dining table", "round table", "bed", "desk"],
        per_object: Some(1),
    },
];

/// Seats round a table `size` wide and deep: each side takes one per 0.55 m (a chair's width
/// plus elbow room), at least one a side (Infinigen's and furnishers' rule of thumb).
pub fn table_seats(size: [f64; 3]) -> u32 {
    let side = |l: f64| ((l + 0.1) / 0.55).floor().max(1.0) as u32;
    if size[0].max(size[1]) < 0.5 {
        return 2;
    }
    2 * side(size[0]) + 2 * side(size[1])
}

/// Stools along a counter's front.
fn counter_seats(size: [f64; 3]) -> u32 {
    ((size[0] + 0.1) / 0.55).floor().max(1.0) as u32
}

/// How many subjects of `rule` one instance of `object` (of this size) takes.
fn capacity(rule: &Rule, size: [f64; 3]) -> u32 {
    match (rule.per_object, rule.relation) {
        (Some(k), _) => k,
        (None, RelationKind::At) => counter_seats(size),
        (None, _) => table_seats(size),
    }
}

/// The group relation and the object category of `subject` in `spec`, if a rule applies.
pub fn group_of(spec: &SceneSpec, subject: &str) -> Option<(RelationKind, String)> {
    RULES.iter().find_map(|r| {
        if !r.subjects.contains(&subject) {
            return None;
        }
        r.objects
            .iter()
            .find(|o| spec.objects.contains_key(**o))
            .map(|o| (r.relation, o.to_string()))
    })
}

/// The group relation a `subject` category takes to an `object` category (a cafe chair to a
/// cafe table: AROUND; an office chair to a desk: AT), if they form a group.
pub fn relation_between(subject: &str, object: &str) -> Option<RelationKind> {
    RULES
        .iter()
        .find(|r| r.subjects.contains(&subject) && r.objects.contains(&object))
        .map(|r| r.relation)
}

/// Whether `subject` forms a group with some category (a bar stool with a counter).
pub fn group_of_category(subject: &str) -> Option<&'static [&'static str]> {
    RULES
        .iter()
        .find(|r| r.subjects.contains(&subject))
        .map(|r| r.objects)
}

/// Every object category `subject` forms a group with, over all the rules (a dining chair goes
/// with a school desk and with the dining tables).
pub fn partners_of(subject: &str) -> Vec<&'static str> {
    RULES
        .iter()
        .filter(|r| r.subjects.contains(&subject))
        .flat_map(|r| r.objects.iter().copied())
        .collect()
}

/// How many subjects one `object` instance seats in its group with `subject` (the table's
/// seats, a desk's one chair), if they form a group.
pub fn seats_per(spec: &SceneSpec, subject: &str, object: &str) -> Option<u32> {
    let rule = RULES
        .iter()
        .find(|r| r.subjects.contains(&subject) && r.objects.contains(&object))?;
    let size = spec.objects.get(object)?.size;
    Some(capacity(rule, size))
}

/// Adds the group relations of `spec`. Relations in `keep` (the user's own, by instance pair)
/// stay; other relations between a grouped subject and its group's object category are
/// replaced. Subjects beyond every object's capacity are left free.
pub fn apply(spec: &mut SceneSpec, keep: &BTreeSet<(String, String)>) {
    let count = |c: &str| spec.objects.get(c).map(|o| o.number).unwrap_or(0);
    let mut added: Vec<Relation> = vec![];
    let mut grouped: BTreeMap<String, String> = BTreeMap::new();
    let mut used: BTreeMap<String, u32> = BTreeMap::new();
    for rule in RULES {
        for subj in rule.subjects {
            let n = count(subj);
            if n == 0 {
                continue;
            }
            let Some(obj) = rule.objects.iter().find(|o| count(o) > 0) else {
                continue;
            };
            let cap = capacity(rule, spec.objects[*obj].size);
            let n_obj = count(obj);
            for k in 1..=n {
                let sid = format!("{subj}{k}");
                if grouped.contains_key(&sid) {
                    continue;
                }
                // The user's own relation for this subject wins.
                if keep.iter().any(|(s, _)| *s == sid) {
                    continue;
                }
                // Spread over the objects: the object instance with the fewest so far.
                let best = (1..=n_obj)
                    .map(|m| format!("{obj}{m}"))
                    .filter(|oid| used.get(oid).copied().unwrap_or(0) < cap)
                    .min_by_key(|oid| used.get(oid).copied().unwrap_or(0));
                let Some(oid) = best else { break };
                *used.entry(oid.clone()).or_default() += 1;
                grouped.insert(sid.clone(), obj.to_string());
                added.push(Relation {
                    subject: sid,
                    relation: rule.relation,
                    object: oid,
                });
            }
        }
    }
    // Drop relations the groups replace: a grouped subject and any instance of its group's
    // object category, or any pair the groups now relate (either way round).
    let pair = |a: &str, b: &str| (a.min(b).to_string(), a.max(b).to_string());
    let new_pairs: BTreeSet<(String, String)> =
        added.iter().map(|r| pair(&r.subject, &r.object)).collect();
    let base = |id: &str| {
        id.trim_end_matches(|c: char| c.is_ascii_digit())
            .to_string()
    };
    spec.relations.retain(|r| {
        if keep.contains(&(r.subject.clone(), r.object.clone())) {
            return true;
        }
        if new_pairs.contains(&pair(&r.subject, &r.object)) {
            return false;
        }
        let replaced = |s: &str, o: &str| grouped.get(s).is_some_and(|c| *c == base(o));
        // A grouped subject keeps no other relation that would pull it away from its group
        // (stacked pairs excepted: a lamp on the nightstand stays).
        let pulls = |s: &str| {
            grouped.contains_key(s)
                && !matches!(r.relation, RelationKind::Over | RelationKind::Under)
        };
        !(replaced(&r.subject, &r.object) || replaced(&r.object, &r.subject) || pulls(&r.subject))
    });
    spec.relations.extend(added);
    shelter_group(spec);
}

/// The seats of a table that stands under a shelter (a table under a gazebo or a parasol)
/// are under it too: they sit inside its footprint, below its roof.
fn shelter_group(spec: &mut SceneSpec) {
    let mut extra: Vec<Relation> = vec![];
    for roof in spec
        .relations
        .iter()
        .filter(|r| r.relation == RelationKind::Under)
    {
        for seat in spec.relations.iter().filter(|r| {
            r.object == roof.subject
                && matches!(
                    r.relation,
                    RelationKind::Around | RelationKind::At | RelationKind::AtBack
                )
        }) {
            let has = |rs: &[Relation]| {
                rs.iter()
                    .any(|r| r.subject == seat.subject && r.object == roof.object)
            };
            if !has(&spec.relations) && !has(&extra) {
                extra.push(Relation {
                    subject: seat.subject.clone(),
                    relation: RelationKind::Under,
                    object: roof.object.clone(),
                });
            }
        }
    }
    spec.relations.extend(extra);
}
