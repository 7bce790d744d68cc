//! The offline planner: free text to a SceneSpec from the built-in knowledge base. The text is
//! read by `lang` (noun phrases, counts, negation, sizes, placement phrases); the scene type's
//! default furniture fills in the rest, scaled to the counts the text gives ("a classroom with
//! 12 desks" gets 12 chairs); functional groups (`groups`) relate seats, tables, beds and
//! lamps; `capacity` trims default furniture to the room and refuses what cannot fit. A text in
//! which nothing is recognised is an error, not a generic room.
//!
//! Stages, in order (each a submodule working on one `Draft`): `roles` (the scene's defaults
//! and the category each mention means), `sizing` (sizes the text gives), `counts` (counts),
//! `seats` (seats at tables, "a table for six"), `companions` (what the counts set), `roles`
//! again (what negation and named roles take away), `purpose` (seats for someone; after `companions`, seats for the
//! people the place is for), `describe` (styles and descriptions),
//! `relations` (anchors and relations), `sizing` (the room), `describe` (what was understood).
use super::capacity::fit;
use super::kb::{KnowledgeBase, SceneKind};
use super::lang::{self, Reading};
use super::spec::{ObjectSpec, SceneSpec, SceneType};
use std::collections::{BTreeMap, BTreeSet};

mod audience;
mod companions;
mod counts;
mod describe;
mod filled;
mod goods;
mod hung;
mod lining;
mod outdoors;
mod parts;
mod placeable;
mod purpose;
mod relations;
mod roles;
mod rowed;
mod seats;
mod sizing;
mod supports;
use describe::describe;
pub use describe::style_word;

/// Why a prompt could not be planned.
#[derive(Debug, thiserror::Error)]
pub enum PlanError {
    #[error("nothing in \"{0}\" names a scene or an object the offline planner knows; describe it in English (e.g. \"a living room with a grey sofa\") or plan with a language model (--llm-url URL)")]
    NothingRecognised(String),
    #[error("\"{0}\" does not look like English, the only language the offline planner reads; write it in English or plan with a language model (--llm-url URL)")]
    NotEnglish(String),
    #[error(transparent)]
    Spec(#[from] super::spec::SpecError),
}

/// A plan and what the planner had to say about it.
#[derive(Debug, Clone)]
pub struct Plan {
    pub spec: SceneSpec,
    /// Categories the text names (never dropped).
    pub named: BTreeSet<String>,
    /// One line each: clamped counts, unknown objects, trimmed default furniture.
    pub notes: Vec<String>,
    /// Each object's count and reason, and the words not used.
    pub understood: super::understood::Understood,
    /// Categories the text excludes ("no TV", "a futon instead of a bed").
    pub negated: BTreeSet<String>,
    /// "nothing else", "just ...": only what the text names.
    pub exclusive: bool,
    /// Whether the text states the room's size: a room the planner chose instead may grow
    /// when its layout cannot take everything (`gcp::layout_growing`).
    pub room_stated: bool,
}

/// Room size stated in the text: "4m x 5m", "15 ft x 12 ft", "400cm by 300cm", "20 m²".
pub fn parse_room_size(text: &str) -> Option<[f64; 2]> {
    let r = lang::read(KnowledgeBase::builtin(), text);
    r.room
        .map(|[w, d]| [super::units::cm(w), super::units::cm(d)])
}

/// Plans `prompt` offline; a prompt with nothing recognisable in it gives a generic room (use
/// [`plan_prompt`] to get the error instead).
pub fn plan_offline(prompt: &str) -> SceneSpec {
    match plan_prompt(prompt) {
        Ok(p) => p.spec,
        Err(_) => generic_room(prompt),
    }
}

/// A small room with basic furniture, for callers that need a spec whatever the text.
fn generic_room(prompt: &str) -> SceneSpec {
    let kb = KnowledgeBase::builtin();
    let mut objects = BTreeMap::new();
    let mut anchors = BTreeMap::new();
    for (c, n) in [("dining table", 1), ("dining chair", 2), ("bookshelf", 1)] {
        let o = kb
            .object(c)
            .expect("basic categories are in the knowledge base");
        objects.insert(
            c.to_string(),
            ObjectSpec {
                number: n,
                size: o.size,
                description: describe(o, &[], &[], None),
                rows: 0,
                sizes: vec![],
                on_wall: None,
            },
        );
        for k in 1..=n {
            anchors.insert(format!("{c}{k}"), o.anchor);
        }
    }
    let mut spec = SceneSpec {
        scene_type: SceneType::Indoor,
        scene_text: prompt.trim().to_string(),
        room: None,
        objects,
        anchors,
        relations: vec![],
    };
    super::groups::apply(&mut spec, &BTreeSet::new());
    spec.room = Some(super::gcp::choose_room(
        &spec.instances(),
        SceneType::Indoor,
    ));
    spec
}

/// A table category laid for different numbers: its seat category and, per instance in index
/// order, its seats and size.
type Laid = (String, Vec<(u32, [f64; 3])>);

/// What the stages of [`plan_prompt`] build up.
struct Draft<'a> {
    kb: &'a KnowledgeBase,
    r: Reading,
    scene: Option<&'a SceneKind>,
    scene_type: SceneType,
    /// One line each: clamped counts, unknown objects, trimmed default furniture.
    notes: Vec<String>,
    /// Category to count.
    counts: BTreeMap<String, u32>,
    /// The scene's default counts.
    defaults: BTreeMap<String, u32>,
    /// The category each mention means.
    cats: Vec<String>,
    /// Categories the text names.
    named: BTreeSet<String>,
    /// Categories the text excludes.
    negated: BTreeSet<String>,
    /// "no other beds": no default of that kind or role besides the named ones.
    others: BTreeSet<String>,
    /// Each named category's adjectives.
    adjectives: BTreeMap<String, Vec<String>>,
    /// Sizes the text gives or scales.
    sizes: BTreeMap<String, [f64; 3]>,
    /// Sizes of objects the knowledge base lacks.
    unknown: BTreeMap<String, [f64; 3]>,
    /// Counts the text gives.
    explicit: BTreeMap<String, u32>,
    /// Counts that a phrase implies rather than names: category -> the phrase.
    inferred: BTreeMap<String, String>,
    /// Tables laid for different numbers ("six tables for two and two tables for six"): the
    /// table category -> its seat category and, per instance in index order, its seats and size.
    laid: BTreeMap<String, Laid>,
}

/// The spec of `d`'s counts: objects, anchors, relations, seats at parts, default blocks scaled
/// for a small room, and the room sized for them.
fn build_spec(
    d: &mut Draft,
    styles: &[String],
    essential: &BTreeSet<String>,
    prompt: &str,
) -> SceneSpec {
    let anchors = relations::anchors(d);
    let objects = describe::objects(d, styles);
    let mut spec = SceneSpec {
        scene_type: d.scene_type,
        scene_text: prompt.trim().to_string(),
        room: None,
        objects,
        anchors: BTreeMap::new(),
        relations: vec![],
    };
    for (c, n) in &d.counts {
        for k in 1..=*n {
            spec.anchors.insert(format!("{c}{k}"), anchors[c]);
        }
    }
    relations::relations(d, &mut spec);
    hung::hang(d, &mut spec);
    parts::seats_at_parts(d, &mut spec);
    // a room called small or tiny (no stated size) seats fewer: its default rows and tables
    // shrink with its floor before the room is sized for them
    if d.r.scale < 1.0 && d.r.room.is_none() {
        let cut = crate::plan::capacity::scale_blocks(&mut spec, &d.named, essential, d.r.scale);
        d.notes.extend(cut);
    }
    spec.room = Some(sizing::room(d, &spec));
    spec
}

/// Plans `prompt` offline, or says why it cannot.
pub fn plan_prompt(prompt: &str) -> Result<Plan, PlanError> {
    let kb = KnowledgeBase::builtin();
    let r: Reading = lang::read(kb, prompt);
    if r.not_english {
        return Err(PlanError::NotEnglish(prompt.trim().to_string()));
    }
    if r.scene.is_none() && r.mentions.is_empty() {
        return Err(PlanError::NothingRecognised(prompt.trim().to_string()));
    }
    let scene = r.scene.map(|(i, _, _)| &kb.scenes[i]);
    // "a pirate ship's hold": a place inside what the template is the outside of
    let inside = r.not_literal.as_deref().is_some_and(lang::is_indoor_place);
    let scene_type = scene
        .map(
            |s| match outdoors::said_open_air(&r) || outdoors::set_outdoors(&r) {
                true => SceneType::Outdoor,
                false => s.scene_type,
            },
        )
        .filter(|_| !inside)
        .unwrap_or_else(|| match inside {
            true => SceneType::Indoor,
            false => outdoors::unnamed_place_type(kb, &r),
        });
    let mut d = Draft {
        kb,
        r,
        scene,
        scene_type,
        notes: vec![],
        counts: BTreeMap::new(),
        defaults: BTreeMap::new(),
        cats: vec![],
        named: BTreeSet::new(),
        negated: BTreeSet::new(),
        others: BTreeSet::new(),
        adjectives: BTreeMap::new(),
        sizes: BTreeMap::new(),
        unknown: BTreeMap::new(),
        explicit: BTreeMap::new(),
        inferred: BTreeMap::new(),
        laid: BTreeMap::new(),
    };
    roles::scene_defaults(&mut d);
    goods::goods_on_show(&mut d);
    roles::mention_kinds(&mut d);
    roles::definites_as_named(&mut d);
    filled::by_contents(&mut d);
    supports::work_tables(&mut d);
    sizing::mention_sizes(&mut d);
    counts::mention_counts(&mut d);
    supports::plural_supports(&mut d);
    let people = seats::seats_for(&mut d);
    roles::take_away(&mut d);
    audience::named_audience(&mut d);
    rowed::seats_in_rows_leave_their_tables(&mut d);
    purpose::seats_for_someone(&mut d);
    seats::people_at_the_table(&mut d, people);
    companions::companions(&mut d, people);
    purpose::seats_for_all(&mut d, people);
    supports::per_instance(&mut d);
    counts::clamp(&mut d);
    if d.counts.is_empty() {
        return Err(PlanError::NothingRecognised(prompt.trim().to_string()));
    }
    let styles = describe::styles(&d);
    let essential: BTreeSet<String> = d
        .scene
        .map_or(BTreeSet::new(), |s| s.essential.iter().cloned().collect());
    let noted = d.notes.len();
    let mut spec = build_spec(&mut d, &styles, &essential, prompt);
    // things lining the walls are as many as the sized room's walls take: built again for them
    if lining::fill_walls(&mut d, &spec) {
        d.notes.truncate(noted);
        spec = build_spec(&mut d, &styles, &essential, prompt);
    }
    let trim = d.r.room.is_some() || d.r.scale < 1.0;
    let fitted = fit(&mut spec, &d.named, &essential, trim)?;
    d.notes.extend(fitted);
    // a room the text calls tiny (no stated size): defaults its walls cannot take go too
    if d.r.scale < sizing::TINY_SCALE && d.r.room.is_none() {
        let gone = placeable::trim_unplaceable(&mut spec, &d.named, &essential);
        d.notes.extend(gone);
    }
    let understood = describe::understood(&d, &spec, &styles);
    Ok(Plan {
        spec,
        named: d.named,
        notes: d.notes,
        understood,
        negated: d.negated,
        exclusive: d.r.exclusive,
        room_stated: d.r.room.is_some(),
    })
}
