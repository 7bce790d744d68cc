//! Reading a scene request: noun phrases (a category with its own adjectives, never a verb or a
//! function word), counts (digits, number words, "a pair of", "a dozen"; 0 and "no" mean none),
//! negation ("no", "without", "except", carried over "or"), sizes with units (see `units`),
//! relation phrases ("faces", "around", "on either side of", "at the foot of", ...), anchor
//! phrases ("against the wall", "in the corner") and "for N students". Pure text processing:
//! what the words mean for a scene is decided by the offline planner.
use super::kb::KnowledgeBase;
use super::spec::{Anchor, RelationKind};
use super::units::{find_dims, Dims};

mod contents;
mod counts;
mod described;
mod lining;
mod mentions;
mod objects;
mod place;
mod placements;
mod restate;
mod room;
mod scene;
mod setting;
mod spelling;
mod words;
use counts::read_counts;
use placements::read_placements;
use regex::Regex;
use words::not_objects;
pub use words::{
    alternation, counts_whole, is_adjective, is_building, is_function_word, is_generic_seat,
    is_ground, is_indoor_place, is_known_word, is_open_air, is_outdoor_place, is_remover, is_seat,
    is_specialised, is_verb, kind_of_compound, normalise, number, object_footprint, object_height,
    object_length, object_scale, part_owners, plural_means_one, plurals, potted, singular,
};
use words::{number_of, quantities, word_list, words_in, NEGATORS};

/// An object the text names.
#[derive(Debug, Clone, PartialEq)]
pub struct Mention {
    pub start: usize,
    pub end: usize,
    /// The knowledge-base category, or the phrase itself for an unknown object.
    pub category: String,
    /// False for an unknown object (not in the knowledge base).
    pub known: bool,
    /// The matched words ("couches").
    pub text: String,
    pub count: Option<u32>,
    pub plural: bool,
    pub adjectives: Vec<String>,
    /// "the sofa": a reference to an object named before.
    pub definite: bool,
    pub negated: bool,
    /// Width, depth, height stated for it (metres; zero where not stated).
    pub size: [f64; 3],
    /// "each umbrella", "every desk": the object named before, not a new one.
    pub reference: bool,
    /// "two chairs at each table": the mention whose every instance gets `count` of these.
    pub each_of: Option<usize>,
    /// "a bench down each side of every table": parts of each instance (2 sides); 1 otherwise.
    pub parts: u32,
    /// "in four rows of six": the number of rows (0 when not in rows).
    pub rows: u32,
    /// "rows of chairs": set out in rows the text does not count (`rows` stays 0).
    pub in_rows: bool,
    /// "the invigilator's desk": the owner a particular object is named after.
    pub owner: Option<String>,
    /// The kind the text named when the reading put another kind of it in its place ("a reading
    /// lamp on the desk" is a table lamp, said as a reading lamp): it fills that kind's role too.
    pub said_as: Option<String>,
}

/// What a request says.
#[derive(Debug, Clone, Default)]
pub struct Reading {
    /// Lower-case normalised text the spans refer to.
    pub text: String,
    /// Scene index into the knowledge base and the span of its name.
    pub scene: Option<(usize, usize, usize)>,
    pub mentions: Vec<Mention>,
    /// Room floor [W, D] and height, metres.
    pub room: Option<[f64; 2]>,
    pub room_height: Option<f64>,
    /// The room's size was given without a unit and read as metres.
    pub room_unitless: bool,
    /// (subject mention, relation, object mention) indices into `mentions`.
    pub relations: Vec<(usize, RelationKind, usize)>,
    /// Anchors the text gives (mention index).
    pub anchors: Vec<(usize, Anchor)>,
    /// "for 24 students".
    pub people: Option<u32>,
    /// "just a bed and a chest, nothing else": only what the text names.
    pub exclusive: bool,
    /// "a table for six": (table mention, seats at each of its instances).
    pub seats_for: Vec<(usize, u32)>,
    /// "small" / "large" said of the scene.
    pub scale: f64,
    /// "long", "narrow" said of the scene: a room drawn out along one side.
    pub long: bool,
    /// The place is named by a compound head that makes it a large one ("a dance hall", "a
    /// convention hall"): its floor is grown as a "large" one's unless the text sizes it.
    pub large_place: bool,
    /// Nothing in the text looks like English.
    pub not_english: bool,
    /// The word that makes the scene's place not the template's own ("a haunted ballroom", "a
    /// pirate ship's hold", "a space station galley"): the template lends only its generic
    /// furniture.
    pub not_literal: Option<String>,
    /// "a reading nook by the window": where the text puts the place itself, said right after
    /// its name (the planner gives it to the place's main piece, its seat).
    pub place_anchor: Option<Anchor>,
    /// "six chairs along the wall", "two bookcases against the back wall": mentions asked to
    /// stand along one wall (a run there), not spread over the walls ("lining the walls").
    pub one_wall: Vec<usize>,
    /// "a guitar hanging on the wall", "a neon sign on the wall": mentions the text hangs on a
    /// wall (the planner hangs those that can hang and that their kind stands on the floor).
    pub hung: Vec<usize>,
    /// "bookcases along every wall", "lined with lockers on both sides": (mention index, walls
    /// it lines: 1, 2, or 0 for every wall), a plural the room's walls count.
    pub lining: Vec<(usize, u32)>,
    /// Plurals the text gave no number for, counted by the parts of the room a phrase names
    /// ("lockers down both sides": 2), which a lining may raise.
    pub parts_counted: Vec<usize>,
    /// "a bookcase full of books": (mention index, what it holds as said, the span of those words).
    pub contents: Vec<(usize, String, usize, usize)>,
    /// "a picnic spot in a park": spans naming the place the scene is in (no object of it).
    pub settings: Vec<(usize, usize)>,
    /// "the armchair is red", "a sofa in navy blue": spans of colour words said after an
    /// object's name (read into its adjectives).
    pub described: Vec<(usize, usize)>,
}

fn re(p: &str) -> Regex {
    Regex::new(p).expect("valid regex")
}

/// Reads `text`.
pub fn read(kb: &KnowledgeBase, text: &str) -> Reading {
    let t = words::on_top_of_it(&words::spelled_sizes(&words::compound_numbers(&normalise(
        text,
    ))));
    let t = spelling::mend_place_names(kb, &t);
    let t = spelling::mend_object_words(kb, &t);
    let mut r = Reading {
        text: t.clone(),
        scale: 1.0,
        ..Default::default()
    };
    // Spans already explained (sizes, scene name), so that their words are neither counts
    // nor adjectives.
    let mut masked: Vec<(usize, usize)> = vec![];
    let dims: Vec<Dims> = find_dims(&t);
    scene::read_scene(kb, &t, &mut r, &mut masked);
    setting::read_settings(kb, &t, &mut r, &mut masked);
    let mut raw = objects::object_spans(kb, &t, r.scene, &masked, &dims);
    raw.retain(|s| !objects::names_a_person(kb, &t, s));
    mentions::read_mentions(kb, &t, &mut r, &raw, &mut masked, &dims);
    described::read_described(&t, &mut r);
    mentions::place_names(&mut r);
    room::read_room(&t, &mut r, &masked, &dims);
    mentions::for_whom(kb, &mut r);
    read_counts(&mut r);
    restate::restated_counts(&mut r);
    restate::answered_questions(&mut r);
    read_placements(&mut r);
    lining::read_lining(&mut r);
    placements::supports_hold(kb, &mut r);
    placements::surface_kinds(kb, &mut r);
    contents::read_contents(&mut r);
    r.not_english = words::not_english(kb, text, &t);
    r
}
