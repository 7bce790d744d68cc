//! Functional groups, the way furnishers place things (Holodeck's `around` + `face to`,
//! Infinigen's seat and nightstand relations): chairs around a table spread over its sides by
//! its size, a desk's chair at its front, bar stools in a row at a counter, nightstands flanking
//! the head of a bed, seats round a fire, desks in rows facing a board, a lamp on a nightstand
//! or desk, the TV across from the sofa with the coffee table between, a rug under the group.
//! They become relations of the spec (AROUND, AT, AT_BACK, FLANK, CIRCLE, ROW and the plain kinds) that
//! the GCP layout satisfies (sun loungers in pairs beneath a parasol); offline and LLM plans both go through [`apply`].
use super::spec::{Relation, RelationKind, SceneSpec};
use std::collections::{BTreeMap, BTreeSet};
use std::sync::OnceLock;

mod grow;
use grow::{grow_hosts, grow_supports};

/// One rule of kb/groups.txt: every instance of a subject category relates to an instance of
/// the first object category present (seats: of every present one), spread over the object
/// instances by what one takes.
struct Rule {
    subjects: Vec<&'static str>,
    relation: RelationKind,
    objects: Vec<&'static str>,
    /// Subject instances one object instance takes (`None`: by the object's size, seats round
    /// a table or along a counter; `Some(k)`: k).
    per_object: Option<u32>,
}

/// The rules of kb/groups.txt, in its order (a line that does not read is left out; the
/// table's test reads every line).
fn rules() -> &'static [Rule] {
    static RULES: OnceLock<Vec<Rule>> = OnceLock::new();
    RULES.get_or_init(|| {
        include_str!("kb/groups.txt")
            .lines()
            .filter_map(parse_rule)
            .collect()
    })
}

/// One line of kb/groups.txt (`None` for comments, blank lines and lines that do not read).
fn parse_rule(line: &'static str) -> Option<Rule> {
    let line = line.trim();
    if line.is_empty() || line.starts_with('#') {
        return None;
    }
    let f: Vec<&'static str> = line.split('|').map(str::trim).collect();
    let [subjects, relation, objects, per] = f[..] else {
        return None;
    };
    let names = |s: &'static str| -> Vec<&'static str> {
        s.split(',')
            .map(str::trim)
            .filter(|x| !x.is_empty())
            .collect()
    };
    Some(Rule {
        subjects: names(subjects),
        relation: super::kb::parse_relation(relation)?,
        objects: names(objects),
        per_object: match per {
            "size" => None,
            k => Some(k.parse().ok()?),
        },
    })
}

/// Whether `category` is what a name of kb/groups.txt says: the name itself, or for `any X`
/// X or any category ending in " X" (a stone bridge is `any bridge`).
fn names(name: &str, category: &str) -> bool {
    match name.strip_prefix("any ") {
        Some(head) => category == head || category.ends_with(&format!(" {head}")),
        None => category == name,
    }
}

impl Rule {
    fn has_subject(&self, category: &str) -> bool {
        self.subjects.iter().any(|n| names(n, category))
    }

    fn has_object(&self, category: &str) -> bool {
        self.objects.iter().any(|n| names(n, category))
    }

    /// The object categories of this rule that `spec` holds, in the rule's order.
    fn present(&self, spec: &SceneSpec) -> Vec<String> {
        let mut out: Vec<String> = vec![];
        for n in &self.objects {
            for (c, o) in &spec.objects {
                if o.number > 0 && names(n, c) && !out.contains(c) {
                    out.push(c.clone());
                }
            }
        }
        out
    }
}

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
    rules().iter().find_map(|r| {
        if !r.has_subject(subject) {
            return None;
        }
        r.present(spec).into_iter().next().map(|o| (r.relation, o))
    })
}

/// The group relation a `subject` category takes to an `object` category (a cafe chair to a
/// cafe table: AROUND; an office chair to a desk: AT), if they form a group.
pub fn relation_between(subject: &str, object: &str) -> Option<RelationKind> {
    rules()
        .iter()
        .find(|r| r.has_subject(subject) && r.has_object(object))
        .map(|r| r.relation)
}

/// Whether `subject` forms a group with some category (a bar stool with a counter): the object
/// names of its first rule.
pub fn group_of_category(subject: &str) -> Option<&'static [&'static str]> {
    rules()
        .iter()
        .find(|r| r.has_subject(subject))
        .map(|r| r.objects.as_slice())
}

/// Every object category `subject` forms a group with, over all the rules (a dining chair goes
/// with a school desk and with the dining tables).
pub fn partners_of(subject: &str) -> Vec<&'static str> {
    rules()
        .iter()
        .filter(|r| r.has_subject(subject))
        .flat_map(|r| r.objects.iter().copied())
        .collect()
}

/// How many subjects one `object` instance seats in its group with `subject` (the table's
/// seats, a desk's one chair), if they form a group.
pub fn seats_per(spec: &SceneSpec, subject: &str, object: &str) -> Option<u32> {
    let rule = rules()
        .iter()
        .find(|r| r.has_subject(subject) && r.has_object(object))?;
    let size = spec.objects.get(object)?.size;
    Some(capacity(rule, size))
}

/// Whether things "around" `category` stand in a ring round it, facing it (a fire): the objects
/// of the CIRCLE rules.
pub fn ring_centre(category: &str) -> bool {
    rules()
        .iter()
        .any(|r| r.relation == RelationKind::Circle && r.has_object(category))
}

/// Adds the group relations of `spec`. Relations in `keep` (the user's own, by instance pair)
/// stay; other relations between a grouped subject and its group's object category are
/// replaced. Subjects beyond every object's capacity are left free. Seats spread over every
/// table category the scene holds (a top table and the round tables of a reception); a
/// sentence's "around" a ring centre (tents around a campfire) becomes a ring.
pub fn apply(spec: &mut SceneSpec, keep: &BTreeSet<(String, String)>) {
    apply_named(spec, keep, &BTreeSet::new());
}

/// [`apply`], binding seats first to the tables and counters the sentence `named` (the six
/// tables of "six tables with four chairs around each" take the chairs, not a classroom's
/// default desks), then as the rules' order says.
pub fn apply_named(
    spec: &mut SceneSpec,
    keep: &BTreeSet<(String, String)>,
    named: &BTreeSet<String>,
) {
    grow_hosts(spec);
    let count = |c: &str| spec.objects.get(c).map(|o| o.number).unwrap_or(0);
    let mut added: Vec<Relation> = vec![];
    let mut grouped: BTreeMap<String, Vec<String>> = BTreeMap::new();
    let mut used: BTreeMap<String, u32> = BTreeMap::new();
    let mut passes: Vec<(&Rule, Vec<String>)> = vec![];
    for only_named in [true, false] {
        for rule in rules() {
            let mut present = rule.present(spec);
            if only_named {
                // seats by size: the tables and counters named
                present.retain(|c| rule.per_object.is_none() && named.contains(c));
            }
            if !present.is_empty() {
                passes.push((rule, present));
            }
        }
    }
    for (rule, present) in passes {
        // the object instances, the first category's first, with what each takes
        let seats = rule.per_object.is_none();
        let objects: Vec<(String, u32)> = present
            .iter()
            .take(if seats { present.len() } else { 1 })
            .flat_map(|c| {
                let cap = capacity(rule, spec.objects[c].size);
                (1..=count(c)).map(move |m| (format!("{c}{m}"), cap))
            })
            .collect();
        if objects.is_empty() {
            continue;
        }
        // the subject categories in the rule's order
        let mut subjects: Vec<(String, u32)> = vec![];
        for n in &rule.subjects {
            for (c, o) in &spec.objects {
                if o.number > 0 && names(n, c) && !subjects.iter().any(|s| s.0 == *c) {
                    subjects.push((c.clone(), o.number));
                }
            }
        }
        // fewer flankers than beds (one nightstand for twin beds): each stands between two
        if rule.relation == RelationKind::Flank {
            let free: Vec<String> = subjects
                .iter()
                .flat_map(|(c, n)| (1..=*n).map(move |k| format!("{c}{k}")))
                .filter(|sid| !grouped.contains_key(sid) && !keep.iter().any(|(s, _)| s == sid))
                .collect();
            if free.len() < objects.len() && objects.len() >= 2 {
                for (sid, pair) in free.iter().zip(objects.chunks(2)) {
                    for (oid, _) in pair {
                        *used.entry(oid.clone()).or_default() += 1;
                        added.push(Relation {
                            subject: sid.clone(),
                            relation: rule.relation,
                            object: oid.clone(),
                        });
                    }
                    grouped.insert(sid.clone(), present.clone());
                }
                continue;
            }
        }
        for (subj, n) in subjects {
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
                let best = objects
                    .iter()
                    .filter(|(oid, cap)| used.get(oid).copied().unwrap_or(0) < *cap)
                    .min_by_key(|(oid, _)| used.get(oid).copied().unwrap_or(0));
                let Some((oid, _)) = best else { break };
                *used.entry(oid.clone()).or_default() += 1;
                grouped.insert(sid.clone(), present.clone());
                added.push(Relation {
                    subject: sid,
                    relation: rule.relation,
                    object: oid.clone(),
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
        let replaced = |s: &str, o: &str| grouped.get(s).is_some_and(|c| c.contains(&base(o)));
        // A grouped subject keeps no other relation that would pull it away from its group
        // (stacked pairs excepted: a lamp on the nightstand stays).
        let pulls = |s: &str| {
            grouped.contains_key(s)
                && !matches!(r.relation, RelationKind::Over | RelationKind::Under)
        };
        !(replaced(&r.subject, &r.object) || replaced(&r.object, &r.subject) || pulls(&r.subject))
    });
    spec.relations.extend(added);
    // a seat the sentence puts in front of a desk-like thing it goes with ("three consoles,
    // each with a seat in front of it", "four bar stools in front of the bar") sits at it, while
    // it has places left
    let at = |spec: &SceneSpec, o: &str| {
        spec.relations
            .iter()
            .filter(|r| r.relation == RelationKind::At && r.object == o)
            .count() as u32
    };
    let places = |spec: &SceneSpec, s: &str, o: &str| {
        let size = spec.objects.get(&base(o)).map(|x| x.size)?;
        rules()
            .iter()
            .find(|q| q.has_subject(&base(s)) && q.has_object(&base(o)))
            .filter(|q| q.relation == RelationKind::At)
            .map(|q| capacity(q, size))
    };
    for k in 0..spec.relations.len() {
        let r = &spec.relations[k];
        if r.relation == RelationKind::Front
            && places(spec, &r.subject, &r.object).is_some_and(|n| at(spec, &r.object) < n)
        {
            spec.relations[k].relation = RelationKind::At;
        }
    }
    for r in spec.relations.iter_mut() {
        if r.relation == RelationKind::Around && ring_centre(&base(&r.object)) {
            r.relation = RelationKind::Circle;
        }
    }
    shelter_group(spec);
    grow_supports(spec);
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

#[cfg(test)]
mod tests {
    use super::*;

    fn spec(objects: &[(&str, u32, [f64; 3])], relations: &[(&str, &str, &str)]) -> SceneSpec {
        let objects: Vec<String> = objects
            .iter()
            .map(|(c, n, s)| format!(r#""{c}":{{"number":{n},"size":{s:?},"description":"d"}}"#))
            .collect();
        let relations: Vec<String> = relations
            .iter()
            .map(|(s, r, o)| format!(r#"{{"subject":"{s}","relation":"{r}","object":"{o}"}}"#))
            .collect();
        let text = format!(
            r#"{{"scene_type":"outdoor","scene_text":"t","objects":{{{}}},"relations":[{}]}}"#,
            objects.join(","),
            relations.join(",")
        );
        serde_json::from_str(&text).expect("spec")
    }

    /// Every relation of `s` as the text's own (kept by `apply`).
    fn user_pairs(s: &SceneSpec) -> BTreeSet<(String, String)> {
        s.relations
            .iter()
            .map(|r| (r.subject.clone(), r.object.clone()))
            .collect()
    }

    fn has(spec: &SceneSpec, s: &str, rel: RelationKind, o: &str) -> bool {
        spec.relations
            .iter()
            .any(|r| r.subject == s && r.relation == rel && r.object == o)
    }

    #[test]
    fn every_line_of_the_groups_table_reads() {
        let lines = include_str!("kb/groups.txt")
            .lines()
            .filter(|l| !l.trim().is_empty() && !l.trim_start().starts_with('#'))
            .count();
        assert_eq!(
            rules().len(),
            lines,
            "a line of kb/groups.txt does not read"
        );
        let kb = super::super::kb::KnowledgeBase::builtin();
        for r in rules() {
            let known = |ns: &[&str]| {
                ns.iter()
                    .any(|n| n.starts_with("any ") || kb.object(n).is_some())
            };
            assert!(
                known(&r.subjects) && known(&r.objects),
                "{:?} {:?}",
                r.subjects,
                r.objects
            );
        }
    }

    #[test]
    fn any_kind_of_bridge_crosses_the_pond() {
        for bridge in ["wooden bridge", "bridge", "stone bridge"] {
            let mut s = spec(
                &[("pond", 1, [3.0, 2.0, 0.3]), (bridge, 1, [1.2, 3.5, 1.0])],
                &[],
            );
            apply(&mut s, &BTreeSet::new());
            assert!(
                has(&s, "pond1", RelationKind::Under, &format!("{bridge}1")),
                "{bridge}: {:?}",
                s.relations
            );
        }
        let mut s = spec(
            &[
                ("pond", 1, [3.0, 2.0, 0.3]),
                ("bridge table", 1, [1.0, 1.0, 1.0]),
            ],
            &[],
        );
        apply(&mut s, &BTreeSet::new());
        assert!(
            s.relations.is_empty(),
            "a bridge table is no bridge: {:?}",
            s.relations
        );
    }

    #[test]
    fn things_around_a_fire_form_a_ring_and_seats_spread_over_every_table() {
        let mut s = spec(
            &[
                ("tent", 3, [2.5, 2.5, 1.5]),
                ("fire pit", 1, [1.0, 1.0, 0.4]),
            ],
            &[
                ("tent1", "AROUND", "fire pit1"),
                ("tent2", "AROUND", "fire pit1"),
            ],
        );
        let keep = user_pairs(&s);
        apply(&mut s, &keep);
        assert!(
            has(&s, "tent1", RelationKind::Circle, "fire pit1"),
            "{:?}",
            s.relations
        );
        // a table is no ring centre: chairs around it stay at its sides
        let mut s = spec(
            &[
                ("dining chair", 10, [0.45, 0.5, 0.9]),
                ("dining table", 1, [1.8, 0.9, 0.75]),
                ("kitchen table", 1, [1.2, 0.8, 0.75]),
            ],
            &[],
        );
        apply(&mut s, &BTreeSet::new());
        let at = |t: &str| {
            s.relations
                .iter()
                .filter(|r| r.relation == RelationKind::Around && r.object == t)
                .count()
        };
        assert_eq!(
            (at("dining table1"), at("kitchen table1")),
            (5, 5),
            "{:?}",
            s.relations
        );
        // benches down the sides of a table
        let mut s = spec(
            &[
                ("bench", 2, [1.2, 0.4, 0.45]),
                ("dining table", 1, [2.2, 1.0, 0.75]),
            ],
            &[],
        );
        apply(&mut s, &BTreeSet::new());
        assert!(
            has(&s, "bench2", RelationKind::Around, "dining table1"),
            "{:?}",
            s.relations
        );
    }

    #[test]
    fn one_nightstand_for_twin_beds_stands_between_them_and_two_beds_keep_their_own() {
        let beds = |nightstands: u32| {
            let mut s = spec(
                &[
                    ("single bed", 2, [1.0, 2.0, 0.9]),
                    ("nightstand", nightstands, [0.5, 0.4, 0.55]),
                ],
                &[],
            );
            apply(&mut s, &BTreeSet::new());
            s
        };
        let s = beds(1);
        for bed in ["single bed1", "single bed2"] {
            assert!(
                has(&s, "nightstand1", RelationKind::Flank, bed),
                "{bed}: {:?}",
                s.relations
            );
        }
        let s = beds(2);
        assert!(
            has(&s, "nightstand1", RelationKind::Flank, "single bed1")
                && has(&s, "nightstand2", RelationKind::Flank, "single bed2"),
            "{:?}",
            s.relations
        );
        assert_eq!(s.relations.len(), 2, "{:?}", s.relations);
    }

    #[test]
    fn hosts_and_supports_grow_to_what_they_hold_and_no_further() {
        // eight stools at one bar: the bar grows to seat them
        let mut s = spec(
            &[
                ("bar counter", 1, [3.0, 0.7, 1.1]),
                ("bar stool", 8, [0.4, 0.4, 0.75]),
            ],
            &[],
        );
        apply(&mut s, &BTreeSet::new());
        let bar = s.objects["bar counter"].size;
        assert!(counter_seats(bar) >= 8 && bar[0] < 4.5, "{bar:?}");
        // a bar that seats them already keeps its size
        let mut s = spec(
            &[
                ("bar counter", 1, [3.0, 0.7, 1.1]),
                ("bar stool", 4, [0.4, 0.4, 0.75]),
            ],
            &[],
        );
        apply(&mut s, &BTreeSet::new());
        assert_eq!(s.objects["bar counter"].size, [3.0, 0.7, 1.1]);
        // ten round tables for eighty chairs: each seats eight and stays square
        let mut s = spec(
            &[
                ("round table", 10, [1.0, 1.0, 0.75]),
                ("dining chair", 80, [0.45, 0.5, 0.9]),
            ],
            &[],
        );
        apply(&mut s, &BTreeSet::new());
        let t = s.objects["round table"].size;
        assert!(table_seats(t) >= 8 && t[0] == t[1], "{t:?}");
        // four computers on a 1.2 m bench: the bench grows; one monitor on a desk grows nothing
        let mut s = spec(
            &[
                ("science bench", 1, [1.2, 0.8, 0.9]),
                ("computer", 4, [0.6, 0.25, 0.5]),
            ],
            &(1..=4)
                .map(|k| {
                    (
                        ["computer1", "computer2", "computer3", "computer4"][k - 1],
                        "OVER",
                        "science bench1",
                    )
                })
                .collect::<Vec<_>>(),
        );
        apply(&mut s, &BTreeSet::new());
        let b = s.objects["science bench"].size;
        assert!(b[0] >= 4.0 * 0.6 && b[0] <= 3.6 + 1e-9, "{b:?}");
        let mut s = spec(
            &[("tv stand", 1, [1.2, 0.4, 0.5]), ("tv", 1, [1.4, 0.1, 0.8])],
            &[("tv1", "OVER", "tv stand1")],
        );
        apply(&mut s, &BTreeSet::new());
        assert_eq!(s.objects["tv stand"].size[0], 1.2);
    }

    #[test]
    fn seats_bind_to_the_tables_named_before_default_desks() {
        let objects = [
            ("dining chair", 8, [0.45, 0.5, 0.9]),
            ("dining table", 2, [1.8, 0.9, 0.75]),
            ("school desk", 8, [0.7, 0.5, 0.75]),
        ];
        let mut s = spec(&objects, &[]);
        let named: BTreeSet<String> = ["dining chair", "dining table"].map(String::from).into();
        apply_named(&mut s, &BTreeSet::new(), &named);
        let at_tables = s
            .relations
            .iter()
            .filter(|r| r.relation == RelationKind::Around && r.object.starts_with("dining table"))
            .count();
        assert_eq!(at_tables, 8, "{:?}", s.relations);
        // nothing named: the rules' order (a classroom's pupils at their desks)
        let mut s = spec(&objects, &[]);
        apply(&mut s, &BTreeSet::new());
        assert!(
            has(&s, "dining chair1", RelationKind::AtBack, "school desk1"),
            "{:?}",
            s.relations
        );
    }

    #[test]
    fn a_seat_in_front_of_a_console_sits_at_it() {
        let mut s = spec(
            &[
                ("spaceship console", 2, [1.6, 0.8, 1.1]),
                ("office chair", 2, [0.65, 0.65, 1.1]),
            ],
            &[
                ("office chair1", "FRONT", "spaceship console1"),
                ("office chair2", "FRONT", "spaceship console2"),
            ],
        );
        let keep = user_pairs(&s);
        apply(&mut s, &keep);
        assert!(
            has(&s, "office chair1", RelationKind::At, "spaceship console1")
                && has(&s, "office chair2", RelationKind::At, "spaceship console2"),
            "{:?}",
            s.relations
        );
    }
}
