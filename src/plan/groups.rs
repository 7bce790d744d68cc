//! Functional groups, the way furnishers place things (Holodeck's `around` + `face to`,
//! Infinigen's seat and nightstand relations): chairs around a table spread over its sides by
//! its size, a desk's chair at its front, bar stools in a row at a counter, nightstands flanking
//! the head of a bed, seats round a fire, desks in rows facing a board, a lamp on a nightstand
//! or desk, the TV across from the sofa with the coffee table between, a rug under the group.
//! They become relations of the spec (AROUND, AT, AT_BACK, FLANK, CIRCLE, ROW and the plain kinds) that
//! the GCP layout satisfies (sun loungers in pairs beneath a parasol); offline and LLM plans both go through [`apply`].
use super::spec::{Anchor, Relation, RelationKind, SceneSpec};
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

/// The rules of kb/groups.txt, in its order.
fn rules() -> &'static [Rule] {
    static RULES: OnceLock<Vec<Rule>> = OnceLock::new();
    RULES.get_or_init(|| {
        parse(
            include_str!("kb/groups.txt"),
            super::kb::KnowledgeBase::builtin(),
        )
        .expect("the built-in group table is valid (tested)")
    })
}

/// Reads a group table: every line must read and name categories of `kb` (by their own names,
/// not synonyms; `any X` where X or a category ending in " X" is one), or the error names the
/// line and the word.
fn parse(text: &'static str, kb: &super::kb::KnowledgeBase) -> Result<Vec<Rule>, String> {
    let mut rules = vec![];
    for (ln, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let err = |m: String| format!("groups.txt line {}: {m}", ln + 1);
        let f: Vec<&'static str> = line.split('|').map(str::trim).collect();
        let [subjects, relation, objects, per] = f[..] else {
            return Err(err(
                "expected `subjects | RELATION | objects | per object`".into()
            ));
        };
        let names = |s: &'static str| -> Result<Vec<&'static str>, String> {
            s.split(',')
                .map(str::trim)
                .filter(|x| !x.is_empty())
                .map(|n| {
                    let known = match n.strip_prefix("any ") {
                        Some(head) => kb
                            .objects
                            .iter()
                            .any(|o| names(n, &o.category))
                            .then_some(())
                            .ok_or_else(|| format!("no category is `{head}` or ends in it")),
                        None => match kb.object(n) {
                            Some(o) if o.category == n => Ok(()),
                            Some(o) => Err(format!("`{n}` is a name of `{}`", o.category)),
                            None => Err(format!("unknown object `{n}`")),
                        },
                    };
                    known.map(|()| n).map_err(err)
                })
                .collect()
        };
        rules.push(Rule {
            subjects: names(subjects)?,
            relation: super::kb::parse_relation(relation)
                .ok_or_else(|| err(format!("unknown relation `{relation}`")))?,
            objects: names(objects)?,
            per_object: match per {
                "size" => None,
                k => Some(
                    k.parse()
                        .map_err(|_| err(format!("`{k}` is no number nor `size`")))?,
                ),
            },
        });
    }
    Ok(rules)
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
        (None, RelationKind::At | RelationKind::AtBack) => counter_seats(size),
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

/// [`seats_per`] once a counter has grown to seat more along its front: a counter (seats AT it
/// by its width, a bar's stools) is built as long as its stools need, up to twice its own width,
/// before a second one is wanted.
pub fn seats_per_grown(spec: &SceneSpec, subject: &str, object: &str) -> Option<u32> {
    let rule = rules()
        .iter()
        .find(|r| r.has_subject(subject) && r.has_object(object))?;
    let mut size = spec.objects.get(object)?.size;
    if rule.per_object.is_none() && matches!(rule.relation, RelationKind::At | RelationKind::AtBack)
    {
        size[0] *= 2.0;
    }
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
    text_places_first(spec, keep);
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
        // (a shelter the text puts over a table, "a parasol over the table", shelters that
        // table's seats, not the loungers a rule would bring under it)
        let sheltering = |id: &str| {
            rule.relation == RelationKind::Under
                && spec
                    .relations
                    .iter()
                    .any(|r| r.subject == id && r.relation == RelationKind::Over)
        };
        let objects: Vec<(String, u32)> = present
            .iter()
            .take(if seats { present.len() } else { 1 })
            .flat_map(|c| {
                let o = &spec.objects[c];
                (1..=count(c)).map(move |m| (format!("{c}{m}"), capacity(rule, o.size_of(m))))
            })
            .filter(|(id, _)| !sheltering(id))
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
    // each with a seat in front of it", "four bar stools in front of the bar") sits at it,
    // as many as it seats
    let at = |spec: &SceneSpec, o: &str| {
        spec.relations
            .iter()
            .filter(|r| r.relation == RelationKind::At && r.object == o)
            .count() as u32
    };
    for k in 0..spec.relations.len() {
        let r = &spec.relations[k];
        let (s, o) = (base(&r.subject), base(&r.object));
        if r.relation == RelationKind::Front
            && relation_between(&s, &o) == Some(RelationKind::At)
            && at(spec, &r.object) < seats_per(spec, &s, &o).unwrap_or(1)
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
    seats_take_the_wall(spec);
    rows_before_front(spec);
    grow_supports(spec);
}

/// The fewest things of a kind that stand in rows when they all face one front.
const ROWS_FROM: u32 = 5;

/// Many things of a kind all in front of, or across from, one thing that rows face (six pews
/// before the altar, a home cinema's seats across from its screen: kb/fronts.txt), or things
/// asked in rows that all face it, stand in rows facing it: their relation to it becomes ROW
/// (in front of it and turned to it, however far back the row).
fn rows_before_front(spec: &mut SceneSpec) {
    let fronts: Vec<&str> = crate::plan::gcp::rows::fronts().collect();
    for (cat, o) in &spec.objects {
        // (rows asked face their front the same way)
        let enough = o.number >= ROWS_FROM || (o.rows > 0 && o.number >= 2);
        if !enough || fronts.contains(&cat.as_str()) {
            continue;
        }
        let id = |k: u32| format!("{cat}{k}");
        let toward = |k: u32| {
            spec.relations
                .iter()
                .filter(|r| r.subject == id(k))
                .find(|r| matches!(r.relation, RelationKind::Front | RelationKind::Opposite))
                .map(|r| r.object.clone())
        };
        let Some(front) = toward(1) else { continue };
        let base = front.trim_end_matches(|c: char| c.is_ascii_digit());
        if !fronts.contains(&base) || (2..=o.number).any(|k| toward(k).as_ref() != Some(&front)) {
            continue;
        }
        for r in spec.relations.iter_mut() {
            if r.object == front
                && base_of(&r.subject) == cat
                && matches!(r.relation, RelationKind::Front | RelationKind::Opposite)
            {
                r.relation = RelationKind::Row;
            }
        }
    }
}

fn base_of(id: &str) -> &str {
    id.trim_end_matches(|c: char| c.is_ascii_digit())
}

/// A thing the sentence places (an armchair on either side of the fire, a lamp next to the bed)
/// keeps no relation of the scene's defaults that would pull it elsewhere (the living room's
/// armchairs by the coffee table); what stands on or under something keeps that.
fn text_places_first(spec: &mut SceneSpec, keep: &BTreeSet<(String, String)>) {
    let stacked = |r: &Relation| matches!(r.relation, RelationKind::Over | RelationKind::Under);
    let own = |r: &Relation| keep.contains(&(r.subject.clone(), r.object.clone()));
    let placed: BTreeSet<String> = spec
        .relations
        .iter()
        .filter(|r| own(r) && !stacked(r))
        .map(|r| r.subject.clone())
        .collect();
    spec.relations
        .retain(|r| own(r) || stacked(r) || !placed.contains(&r.subject));
}

/// Seats along the back of a thing that stands against a wall (a head table's party) take the
/// wall themselves: their backs to it, the thing before them facing the room with them. The
/// seats are anchored SIDE and the thing is free of the wall (the layout keeps it a seat's depth
/// off the wall, see `gcp::problem`).
fn seats_take_the_wall(spec: &mut SceneSpec) {
    let backed: Vec<(String, String)> = spec
        .relations
        .iter()
        .filter(|r| {
            r.relation == RelationKind::AtBack && spec.anchors.get(&r.object) == Some(&Anchor::Side)
        })
        .map(|r| (r.subject.clone(), r.object.clone()))
        .collect();
    for (seat, table) in backed {
        spec.anchors.insert(seat, Anchor::Side);
        spec.anchors.insert(table, Anchor::Others);
    }
}

/// The seats of a table that stands under a shelter (a table under a gazebo or a parasol)
/// are under it too: they sit inside its footprint, below its roof. A light hung from the
/// ceiling over the table ("a round table under a pendant light") lights the table alone.
fn shelter_group(spec: &mut SceneSpec) {
    use crate::plan::gcp::classes::{Class, Placements};
    let hung = |id: &str| Placements::builtin().class(base_of(id)) == Class::Ceiling;
    // a tall thing set over a table that it is wider than both ways (a parasol through the
    // table's middle) is a roof over that table too, not a thing on it
    let size = |id: &str| spec.objects.get(base_of(id)).map(|o| o.size);
    let canopy = |r: &Relation| {
        r.relation == RelationKind::Over
            && !hung(&r.subject)
            && match (size(&r.subject), size(&r.object)) {
                (Some(a), Some(b)) => {
                    a[0] >= b[0].max(b[1]) && a[1] >= b[0].max(b[1]) && a[2] >= 1.5
                }
                _ => false,
            }
    };
    let roofs: Vec<Relation> = spec
        .relations
        .iter()
        .filter(|r| r.relation == RelationKind::Under && !hung(&r.object))
        .cloned()
        .chain(
            spec.relations
                .iter()
                .filter(|r| canopy(r))
                .map(|r| Relation {
                    subject: r.object.clone(),
                    relation: RelationKind::Under,
                    object: r.subject.clone(),
                }),
        )
        .collect();
    let mut extra: Vec<Relation> = vec![];
    for roof in &roofs {
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
mod tests;
