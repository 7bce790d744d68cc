//! The offline planner: free text to a SceneSpec from the built-in knowledge base. The text is
//! read by `lang` (noun phrases, counts, negation, sizes, placement phrases); the scene type's
//! default furniture fills in the rest, scaled to the counts the text gives ("a classroom with
//! 12 desks" gets 12 chairs); functional groups (`groups`) relate seats, tables, beds and
//! lamps; `capacity` trims default furniture to the room and refuses what cannot fit. A text in
//! which nothing is recognised is an error, not a generic room.
use super::capacity::{fit, room_for};
use super::kb::{KnowledgeBase, ObjectKind};
use super::lang::{self, Reading};
use super::spec::{Anchor, ObjectSpec, Relation, Room, SceneSpec, SceneType, MAX_NUMBER};
use std::collections::{BTreeMap, BTreeSet};

/// Style words carried into every description when the prompt uses them.
const STYLES: &[&str] = &[
    "modern",
    "minimalist",
    "minimal",
    "scandinavian",
    "nordic",
    "rustic",
    "industrial",
    "mid-century",
    "bohemian",
    "boho",
    "vintage",
    "retro",
    "cozy",
    "cosy",
    "luxurious",
    "luxury",
    "japanese",
    "zen",
    "victorian",
    "baroque",
    "gothic",
    "medieval",
    "futuristic",
    "sci-fi",
    "cyberpunk",
    "art deco",
    "coastal",
    "tropical",
    "farmhouse",
    "traditional",
    "contemporary",
    "elegant",
    "colorful",
    "colourful",
    "pastel",
    "dark",
    "bright",
    "sunny",
    "wooden",
    "classic",
    "mediterranean",
    "moroccan",
    "french",
    "english",
    "cottage",
    "steampunk",
    "fantasy",
    "festive",
];

/// The style word `w` is (or starts), if any.
pub fn style_word(w: &str) -> Option<&'static str> {
    STYLES.iter().copied().find(|s| *s == w)
}

fn article(s: &str) -> &'static str {
    match s.chars().next() {
        Some('a' | 'e' | 'i' | 'o' | 'u') => "an",
        _ => "a",
    }
}

fn describe(o: &ObjectKind, adjectives: &[String], styles: &[String]) -> String {
    let mut words: Vec<String> = styles.to_vec();
    if adjectives.is_empty() {
        words.push(o.description.clone());
    } else {
        words.extend(adjectives.iter().cloned());
        words.push(o.category.clone());
    }
    let body = words.join(" ");
    format!("A DSLR photo of {} {body}", article(&body))
}

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
                description: describe(o, &[], &[]),
                rows: 0,
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

/// The scene's default category that the text's noun `m` means: "desks" in a classroom are
/// school desks, "chairs" in a cafe are cafe chairs (the default sharing the head noun, the
/// most numerous first).
fn in_scene(kb: &KnowledgeBase, scene: Option<&super::kb::SceneKind>, m: &lang::Mention) -> String {
    let Some(s) = scene else {
        return m.category.clone();
    };
    if m.owner.is_some() || s.objects.iter().any(|(c, _)| *c == m.category) {
        return m.category.clone();
    }
    let head = lang::singular(m.text.rsplit(' ').next().unwrap_or(""));
    let same_head = |c: &&(String, u32)| c.0.rsplit(' ').next() == Some(head.as_str());
    if !m.known {
        // "three sonar consoles" on a bridge: its consoles, described by the text's words
        return s
            .objects
            .iter()
            .filter(same_head)
            .max_by_key(|(_, n)| *n)
            .map(|(c, _)| c.clone())
            .unwrap_or_else(|| m.category.clone());
    }
    // Only what scenes specialise (`kb/words.txt`: specialised); a lamp stays a lamp.
    if !lang::is_specialised(&head) {
        return m.category.clone();
    }
    let head_cat = kb.object(&head).map(|o| o.category.clone());
    // Only a bare head noun ("desks", "a chair") is re-read; "an office chair" stays.
    let bare = m.text.split(' ').count() == 1 || head_cat.as_deref() == Some(m.category.as_str());
    if !bare {
        return m.category.clone();
    }
    s.objects
        .iter()
        .filter(|(c, _)| {
            c.rsplit(' ').next() == Some(head.as_str())
                || kb.object(&head).is_some_and(|o| o.category == **c)
        })
        .max_by_key(|(_, n)| *n)
        .map(|(c, _)| c.clone())
        .unwrap_or_else(|| m.category.clone())
}

/// Height below which a thing is at floor level (metres): see [`small_room`].
const LOW: f64 = 0.3;

/// Floor of a room the text calls small or tiny: what the named objects need in use (their
/// footprints with room to use them at half the floor, a little more when tiny; the longest
/// with a walkway), or with nothing named the scene's furniture room scaled by `scale`; never
/// below a small room's side. The defaults are then trimmed to fit by `capacity::fit`.
fn small_room(
    spec: &SceneSpec,
    named: &BTreeSet<String>,
    full: [f64; 3],
    scale: f64,
    scene_type: SceneType,
) -> [f64; 3] {
    let named_inst: Vec<_> = spec
        .instances()
        .into_iter()
        .filter(|i| named.contains(&i.category))
        .collect();
    let margin = super::capacity::USE_MARGIN;
    // The share of the floor the named furniture may take: more in a room called tiny.
    let occupancy = if scale < 0.45 { 0.6 } else { 0.5 };
    // Only what stands on the floor takes floor (a mirror on the wall, a lamp on a table no).
    let on_floor = |c: &str| {
        use super::gcp::classes::{effective_class, Class};
        matches!(effective_class(spec, c), Class::Floor | Class::AgainstWall)
    };
    // A chair at a desk uses the desk's own room in front of it.
    let tucked = |c: &str| {
        use super::groups::{group_of, seats_per};
        matches!(group_of(spec, c), Some((super::spec::RelationKind::At | super::spec::RelationKind::AtBack, t)) if seats_per(spec, c, &t) == Some(1))
    };
    // A thing at floor level (a floor cushion, a mattress on the floor) is stepped onto: its
    // footprint is all it takes.
    let room_to_use = |h: f64| if h < LOW { 0.0 } else { margin };
    let need: f64 = named_inst
        .iter()
        .filter(|i| i.size[2] >= 0.05 && on_floor(&i.category) && !tucked(&i.category))
        .map(|i| (i.size[0] + room_to_use(i.size[2])) * (i.size[1] + room_to_use(i.size[2])))
        .sum::<f64>()
        / occupancy;
    let longest = spec
        .instances()
        .iter()
        .filter(|i| named.contains(&i.category))
        .map(|i| i.size[0].max(i.size[1]))
        .fold(0.0, f64::max);
    let base_side: f64 = match scene_type {
        SceneType::Indoor if scale < 0.45 => 1.8,
        SceneType::Indoor => 2.2,
        SceneType::Outdoor => 6.0,
    };
    let min_side = base_side.max(longest + 0.4);
    // What the text names sets the floor; with nothing named, the scene's furniture scaled.
    let area = if named_inst.is_empty() {
        full[0] * full[1] * scale
    } else {
        need.min(full[0] * full[1])
    };
    let w = (area * 1.25).sqrt().max(min_side);
    let d = (area / w).max(min_side);
    let r = |v: f64| (v * 10.0).ceil() / 10.0;
    [r(w), r(d), full[2]]
}

/// The seat category that goes round `table`: one the plan already has, else the first of the
/// usual seats that the functional groups put at such a table.
fn seat_for(table: &str, counts: &BTreeMap<String, u32>) -> Option<String> {
    const USUAL: &[&str] = &[
        "dining chair",
        "cafe chair",
        "patio chair",
        "office chair",
        "bar stool",
    ];
    let probe = |seat: &str| {
        let mut objects = BTreeMap::new();
        for c in [table, seat] {
            objects.insert(
                c.to_string(),
                ObjectSpec {
                    number: 1,
                    size: [1.0, 1.0, 1.0],
                    description: String::new(),
                    rows: 0,
                },
            );
        }
        let spec = SceneSpec {
            scene_type: SceneType::Indoor,
            scene_text: String::new(),
            room: None,
            objects,
            anchors: BTreeMap::new(),
            relations: vec![],
        };
        super::groups::group_of(&spec, seat).is_some_and(|(_, t)| t == table)
    };
    counts
        .keys()
        .map(String::as_str)
        .chain(USUAL.iter().copied())
        .find(|s| *s != table && probe(s))
        .map(str::to_string)
}

/// How many scene types a category is a default of: furniture of at least
/// [`GENERIC_SCENES`] is generic (chairs, shelves, rugs), the rest belongs to its places.
fn scenes_with(kb: &KnowledgeBase, category: &str) -> usize {
    kb.scenes
        .iter()
        .filter(|s| s.objects.iter().any(|(c, _)| c == category))
        .count()
}

/// See [`scenes_with`].
const GENERIC_SCENES: usize = 3;

/// Size of an object the knowledge base lacks: from its head noun's category when it has one,
/// else from a size class named by its words.
fn unknown_size(kb: &KnowledgeBase, name: &str) -> ([f64; 3], String) {
    let words: Vec<&str> = name.split(' ').collect();
    for k in (0..words.len()).rev() {
        if let Some(o) = kb.object(words[k]) {
            return (o.size, format!("sized as a {}", o.category));
        }
    }
    // WordNet: "a divan" is a kind of sofa, "an owl" a small thing
    let head = words.last().copied().unwrap_or("");
    let kind = super::lexicon::kind(head);
    if let Some(super::lexicon::Kind::Category(c)) = kind {
        if let Some(o) = kb.object(c) {
            return (o.size, format!("sized as a {c}, its kind in WordNet"));
        }
    }
    let wn_class = match kind {
        Some(super::lexicon::Kind::Size(class)) => class,
        _ => "",
    };
    let has = |ws: &[&str]| words.iter().any(|w| ws.contains(w));
    let (size, class) = if has(&["small", "tiny", "little", "mini", "miniature"]) {
        ([0.35, 0.35, 0.4], "small")
    } else if has(&[
        "large", "big", "huge", "giant", "enormous", "massive", "tall",
    ]) {
        ([1.5, 1.0, 1.6], "large")
    } else if wn_class == "small" {
        ([0.35, 0.35, 0.4], "small")
    } else if wn_class == "large" {
        ([1.5, 1.0, 1.6], "large")
    } else {
        ([0.7, 0.6, 0.9], "medium")
    };
    (
        size,
        format!("sized as a {class} object {}", fmt_size(size)),
    )
}

fn fmt_size(s: [f64; 3]) -> String {
    format!("{} x {} x {} m", s[0], s[1], s[2])
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
    let scene_type = scene.map(|s| s.scene_type).filter(|_| !inside).unwrap_or_else(|| {
        let outdoor = regex::Regex::new(
            r"\b(outdoor|outdoors|outside|open air|garden|yard|field|forest|street|beach|park|meadow|lawn)\b",
        )
        .expect("valid regex");
        if outdoor.is_match(&r.text) && !inside {
            SceneType::Outdoor
        } else {
            SceneType::Indoor
        }
    });
    let mut notes: Vec<String> = vec![];

    // Defaults of the scene, then what the text names.
    let mut counts: BTreeMap<String, u32> = BTreeMap::new();
    if let Some(s) = scene {
        for (c, n) in &s.objects {
            // "a haunted ballroom": another place than the template's lends only its generic
            // furniture (what several scene types have), not its DJ booth
            if let Some(w) = r.not_literal.as_deref() {
                if scenes_with(kb, c) < GENERIC_SCENES && !s.own.contains(c) {
                    notes.push(format!(
                        "default `{c}` of a {} left out: the \"{w}\" place is not the template's own",
                        s.name
                    ));
                    continue;
                }
            }
            counts.insert(c.clone(), *n);
        }
    }
    if r.not_literal.is_some() {
        // the seats of a table left out go with it (the reading chairs of a haunted library)
        let lone: Vec<String> = counts
            .keys()
            .filter(|c| {
                let objs = super::groups::partners_of(c);
                scene.is_some_and(|s| s.objects.iter().any(|(o, _)| objs.contains(&o.as_str())))
                    && !objs.iter().any(|o| counts.contains_key(*o))
            })
            .cloned()
            .collect();
        for c in lone {
            counts.remove(&c);
            notes.push(format!(
                "default `{c}` left out: what it goes with is left out"
            ));
        }
    }
    let defaults = counts.clone();
    let mut named: BTreeSet<String> = BTreeSet::new();
    let mut negated: BTreeSet<String> = BTreeSet::new();
    let mut adjectives: BTreeMap<String, Vec<String>> = BTreeMap::new();
    let mut sizes: BTreeMap<String, [f64; 3]> = BTreeMap::new();
    let mut unknown: BTreeMap<String, [f64; 3]> = BTreeMap::new();
    let mut explicit: BTreeMap<String, u32> = BTreeMap::new();
    let mut cats: Vec<String> = r.mentions.iter().map(|m| in_scene(kb, scene, m)).collect();
    // "ten round tables ... and a top table": an unknown kind of a noun of which the text
    // already names a kind is another object, not more of the scene's (it is sized as them).
    for i in 0..cats.len() {
        let m = &r.mentions[i];
        if m.known || m.reference || cats[i] == m.category {
            continue;
        }
        let head = m.category.rsplit(' ').next();
        let named_elsewhere = r.mentions.iter().zip(&cats).any(|(o, c)| {
            (*c == cats[i] || c.rsplit(' ').next() == head) && o.known && !o.reference && !o.negated
        });
        if named_elsewhere {
            cats[i] = m.category.clone();
        }
    }
    // "seven tables, four stools apiece" in a bar: stools said per table are not the scene's
    // stools of another group it has (its bar stools at the counter); they keep their plain kind.
    for (i, m) in r.mentions.iter().enumerate() {
        let Some(t) = m.each_of else { continue };
        let (Some(c), Some(tc)) = (cats.get(i), cats.get(t)) else {
            continue;
        };
        let grouped_elsewhere = super::groups::group_of_category(c).is_some_and(|objs| {
            scene.is_some_and(|s| s.objects.iter().any(|(o, _)| objs.contains(&o.as_str())))
        });
        if *c != m.category && grouped_elsewhere && super::groups::relation_between(c, tc).is_none()
        {
            cats[i] = m.category.clone();
        }
    }
    // "a kids' table with four little chairs": bare seats said with a table are that table's
    // seats, not the scene's usual seat kind (the office chairs of its desks).
    let scene_seats: BTreeMap<String, u32> = scene
        .map(|s| s.objects.iter().cloned().collect())
        .unwrap_or_default();
    for i in 1..r.mentions.len() {
        let (m, prev) = (&r.mentions[i], &r.mentions[i - 1]);
        let between = &r.text[prev.end..m.start];
        if cats[i] == m.category
            || !between.trim_start().starts_with("with ")
            || between.contains([',', ';', '.'])
        {
            continue;
        }
        let head = lang::singular(m.text.rsplit(' ').next().unwrap_or(""));
        // the scene's seats of that noun first, then any kind of it ("kids chair")
        let same_head: BTreeMap<String, u32> = scene_seats
            .iter()
            .map(|(c, n)| (c.clone(), *n))
            .chain(kb.objects.iter().map(|o| (o.category.clone(), 0)))
            .filter(|(c, _)| c.rsplit(' ').next() == Some(head.as_str()))
            .collect();
        if let Some(seat) = seat_for(&cats[i - 1], &same_head) {
            if seat.rsplit(' ').next() == Some(head.as_str()) {
                cats[i] = seat;
            }
        }
    }
    // "three little tables with two chairs per table": tables said with their seats are
    // tables to sit at, not the scene's side tables.
    for (i, pair) in r.mentions.windows(2).enumerate() {
        let (m, next) = (&pair[0], &pair[1]);
        let with = r.text[m.end..next.start].trim_start().starts_with("with ");
        if cats[i] == m.category || !(with || next.each_of == Some(i)) {
            continue;
        }
        let seat: BTreeMap<String, u32> = [(next.category.clone(), 0)].into();
        let sits = |t: &str| seat_for(t, &seat).as_deref() == Some(next.category.as_str());
        if !sits(&cats[i]) && sits(&m.category) {
            cats[i] = m.category.clone();
        }
    }
    // "three consoles, each with a seat in front of it": a seat said of each of them is
    // their usual seat (the console's office chair), whatever its kind.
    for i in 0..r.mentions.len() {
        let m = &r.mentions[i];
        let head = lang::singular(m.text.rsplit(' ').next().unwrap_or(""));
        let (Some(x), "seat") = (m.each_of, head.as_str()) else {
            continue;
        };
        let seats: BTreeMap<String, u32> = scene_seats.clone();
        if let Some(seat) = seat_for(&cats[x], &seats) {
            cats[i] = seat;
        }
    }
    // "a bench on each long side" of a table, "a bench down each side of every table": a seat
    // said of each side of a table is the kind of it that table takes (a dining bench, not the
    // hall's bench), and so is every other mention of it.
    for i in 0..r.mentions.len() {
        let (Some(x), true) = (r.mentions[i].each_of, r.mentions[i].parts > 1) else {
            continue;
        };
        let (c, t) = (cats[i].clone(), cats[x].clone());
        if super::groups::relation_between(&c, &t).is_some() {
            continue;
        }
        let head = lang::singular(r.mentions[i].text.rsplit(' ').next().unwrap_or(""));
        // of the kinds that table takes, the one nearest its length
        let length = kb.object(&t).map_or(0.0, |o| o.size[0]);
        let Some(seat) = kb
            .objects
            .iter()
            .filter(|o| o.category.rsplit(' ').next() == Some(head.as_str()))
            .filter(|o| {
                let one: BTreeMap<String, u32> = [(o.category.clone(), 0)].into();
                seat_for(&t, &one).as_deref() == Some(o.category.as_str())
            })
            .min_by(|a, b| {
                (a.size[0] - length)
                    .abs()
                    .total_cmp(&(b.size[0] - length).abs())
            })
            .map(|o| o.category.clone())
        else {
            continue;
        };
        for (j, cj) in cats.iter_mut().enumerate() {
            if *cj == c && !r.mentions[j].negated {
                *cj = seat.clone();
            }
        }
    }
    // "a big potted palm": a plant that grows to full size outdoors, in a pot, is a potted plant
    for (i, m) in r.mentions.iter().enumerate() {
        let Some(o) = kb.object(&cats[i]) else {
            continue;
        };
        if let Some(c) = m
            .adjectives
            .iter()
            .find_map(|a| lang::potted(a, &o.archetype))
        {
            if kb.object(&c).is_some() {
                cats[i] = c;
            }
        }
    }
    // "two chairs at each table": (category, per instance, category of the distributor).
    let mut distributed: Vec<(String, u32, String)> = vec![];
    let mut others: BTreeSet<String> = BTreeSet::new();
    // Counts that a phrase implies rather than names: category -> the phrase.
    let mut inferred: BTreeMap<String, String> = BTreeMap::new();
    let first_mention = |c: &str| cats.iter().position(|x| x == c);
    for (mi, (m, cat)) in r.mentions.iter().zip(&cats).enumerate() {
        if m.negated {
            if m.adjectives.iter().any(|a| a == "other") {
                // "no other beds": no default of that kind or role, the named ones stay
                others.insert(cat.clone());
            } else {
                negated.insert(cat.clone());
            }
            continue;
        }
        if m.reference {
            // "each umbrella": the umbrellas named before
            continue;
        }
        if !m.known && !unknown.contains_key(cat) {
            // "the instructor's mat" in a yoga studio: sized as the scene's own mats
            let own = scene.and_then(|s| {
                let head = cat.rsplit(' ').next()?;
                let (c, _) = s
                    .objects
                    .iter()
                    .find(|(c, _)| c.rsplit(' ').next() == Some(head))?;
                Some((kb.object(c)?.size, format!("sized as a {c}")))
            });
            let (size, how) = own.unwrap_or_else(|| unknown_size(kb, cat));
            notes.push(format!("`{cat}` is not in the knowledge base: kept, {how}"));
            unknown.insert(cat.clone(), size);
        }
        named.insert(cat.clone());
        if !m.adjectives.is_empty() {
            adjectives.insert(cat.clone(), m.adjectives.clone());
        }
        let base = kb.object(cat).map(|o| o.size).or(unknown.get(cat).copied());
        if let Some(mut size) = base {
            if m.size != [0.0; 3] {
                // A stated width keeps the shape's proportions in depth only when both are given.
                for (v, stated) in size.iter_mut().zip(m.size) {
                    if stated > 0.0 {
                        *v = stated;
                    }
                }
                sizes.insert(cat.clone(), size);
            } else if m.known {
                // "a huge viewscreen", "a tiny desk": the size words of kb/words.txt scale it.
                let f: f64 = m
                    .adjectives
                    .iter()
                    .filter_map(|a| lang::object_scale(a))
                    .product();
                // a word the category's own description has ("small round cafe table") is
                // already in its size
                let described = kb.object(cat).map(|o| o.description.as_str()).unwrap_or("");
                let g: f64 = m
                    .adjectives
                    .iter()
                    .filter(|a| !described.split(' ').any(|w| w == a.as_str()))
                    .filter_map(|a| lang::object_footprint(a))
                    .product();
                if f != 1.0 || g != 1.0 {
                    for (k, v) in size.iter_mut().enumerate() {
                        let s = if k < 2 { f * g } else { f };
                        *v = (*v * s * 100.0).round() / 100.0;
                    }
                    sizes.insert(cat.clone(), size);
                }
            }
        }
        if let Some(x) = m.each_of {
            inferred
                .entry(cat.clone())
                .or_insert_with(|| super::understood::span_phrase(&r, mi, x));
            distributed.push((cat.clone(), m.count.unwrap_or(1) * m.parts, cats[x].clone()));
            continue;
        }
        match m.count {
            Some(n) => {
                *explicit.entry(cat.clone()).or_default() += n;
            }
            None if m.definite => {
                counts.entry(cat.clone()).or_insert(1);
            }
            None if m.plural => {
                if !explicit.contains_key(cat) {
                    let d = defaults.get(cat).copied().unwrap_or(0).max(2);
                    counts.insert(cat.clone(), d);
                }
            }
            None => {
                *explicit.entry(cat.clone()).or_default() += 1;
            }
        }
    }
    for (c, n) in &explicit {
        counts.insert(c.clone(), *n);
    }
    // Distributive counts multiply by the instances of what they distribute over.
    let mut spread: BTreeMap<String, u32> = BTreeMap::new();
    for (c, per, x) in &distributed {
        let over = counts.get(x).copied().unwrap_or(1).max(1);
        *spread.entry(c.clone()).or_default() += per * over;
    }
    for (c, n) in spread {
        let total = explicit.get(&c).copied().unwrap_or(0) + n;
        explicit.insert(c.clone(), total);
        counts.insert(c, total);
    }
    // "A table for six": that many seats at each of those tables.
    let mut seated = false;
    for &(ti, per) in &r.seats_for {
        let table = &cats[ti];
        let Some(&tables) = counts.get(table) else {
            continue;
        };
        let Some(seat) = seat_for(table, &counts) else {
            continue;
        };
        seated = true;
        inferred
            .entry(seat.clone())
            .or_insert_with(|| super::understood::seats_phrase(&r, ti));
        let n = per * tables.max(1);
        let total = if explicit.contains_key(&seat) && !defaults.contains_key(&seat) {
            explicit[&seat].max(n)
        } else {
            n
        };
        explicit.insert(seat.clone(), total);
        named.insert(seat.clone());
        counts.insert(seat, total);
    }
    let people = if seated { None } else { r.people };
    // Negation removes the category, defaults included.
    for c in &negated {
        counts.remove(c);
        named.remove(c);
    }
    // Named objects fill the roles of the defaults they replace.
    notes.extend(super::roles::apply(&mut counts, &named, r.exclusive));
    // "the invigilator's desk": a particular one takes the place of the scene's single
    // default of its kind (the teacher's desk).
    for (m, cat) in r.mentions.iter().zip(&cats) {
        let Some(head) = m.owner.as_ref().and(cat.rsplit(' ').next()) else {
            continue;
        };
        if m.negated {
            continue;
        }
        let gone: Vec<String> = defaults
            .iter()
            .filter(|(c, n)| **n == 1 && !named.contains(*c) && c.rsplit(' ').next() == Some(head))
            .map(|(c, _)| c.clone())
            .collect();
        for c in gone {
            if counts.remove(&c).is_some() {
                notes.push(format!(
                    "default {c} left out: the named {cat} takes its place"
                ));
            }
        }
    }
    for c in &others {
        if !named.contains(c) {
            counts.remove(c);
        }
    }
    // A negated role takes its defaults with it ("no bath": no bathtub of any kind).
    for c in negated.iter().chain(&others) {
        if let Some(role) = super::roles::role_of(c) {
            counts.retain(|k, _| named.contains(k) || super::roles::role_of(k) != Some(role));
        }
    }

    // Companions follow what the text sets: "12 desks" get 12 chairs, "for 24 students" 24
    // seats, "20 chairs" the tables they need.
    let probe = SceneSpec {
        scene_type,
        scene_text: String::new(),
        room: None,
        objects: counts
            .iter()
            .map(|(c, n)| {
                let size = sizes
                    .get(c)
                    .copied()
                    .or_else(|| kb.object(c).map(|o| o.size))
                    .or_else(|| unknown.get(c).copied())
                    .unwrap_or([0.7, 0.6, 0.9]);
                (
                    c.clone(),
                    ObjectSpec {
                        number: *n,
                        size,
                        description: String::new(),
                        rows: 0,
                    },
                )
            })
            .collect(),
        anchors: BTreeMap::new(),
        relations: vec![],
    };
    let cats_now: Vec<String> = counts.keys().cloned().collect();
    let default_probe = SceneSpec {
        objects: defaults
            .iter()
            .map(|(c, n)| {
                let size = kb.object(c).map(|o| o.size).unwrap_or([0.7, 0.6, 0.9]);
                let o = ObjectSpec {
                    number: *n,
                    size,
                    description: String::new(),
                    rows: 0,
                };
                (c.clone(), o)
            })
            .collect(),
        ..probe.clone()
    };
    for seat in &cats_now {
        // A rug under a table or a coffee table before a sofa is no companion to count by.
        use super::spec::RelationKind::{Front, Opposite, Under};
        let Some((kind, table)) = super::groups::group_of(&probe, seat) else {
            continue;
        };
        if matches!(kind, Under | Front | Opposite) {
            continue;
        }
        // A default seat whose own table is gone (the teacher's chair, once "the invigilator's
        // desk" took the teacher desk's place) is no seat of the others.
        if defaults.contains_key(seat) && !explicit.contains_key(seat) {
            let was = super::groups::group_of(&default_probe, seat).map(|g| g.1);
            if was.is_some_and(|w| w != table) {
                continue;
            }
        }
        let Some(per) = super::groups::seats_per(&probe, seat, &table) else {
            continue;
        };
        let seat_named = explicit.contains_key(seat);
        let table_named = explicit.contains_key(&table);
        // "for 24 students" seats the scene's main seats (its most numerous seat category).
        let main_seat = cats_now
            .iter()
            .filter(|c| {
                use super::spec::RelationKind::{Around, At, AtBack, Circle};
                super::groups::group_of(&probe, c)
                    .is_some_and(|(k, _)| matches!(k, Around | At | AtBack | Circle))
            })
            .max_by_key(|c| {
                (
                    defaults.get(*c).copied().unwrap_or(0),
                    counts.get(*c).copied().unwrap_or(0),
                )
            });
        if let Some(p) = people.filter(|_| main_seat == Some(seat)) {
            let said = super::understood::people_phrase(&r.text, p);
            if !seat_named {
                counts.insert(seat.clone(), p);
                inferred.entry(seat.clone()).or_insert_with(|| said.clone());
            }
            if !table_named {
                counts.insert(table.clone(), p.div_ceil(per.max(1)).max(1));
                inferred.entry(table.clone()).or_insert(said);
            }
            continue;
        }
        if table_named && !seat_named && per < 12 {
            // Seats a table the way the scene's defaults do, within its capacity.
            let (ds, dt) = (defaults.get(seat).copied(), defaults.get(&table).copied());
            let each = match (ds, dt) {
                (Some(s), Some(t)) if t > 0 => s.div_ceil(t).min(per),
                _ => per.min(4),
            };
            counts.insert(seat.clone(), counts[&table] * each);
            if let Some(i) = first_mention(&table).filter(|_| !named.contains(seat)) {
                inferred
                    .entry(seat.clone())
                    .or_insert_with(|| super::understood::phrase(&r, i));
            }
        } else if seat_named && !table_named && per < 12 {
            let need = counts[seat].div_ceil(per.max(1));
            let t = counts.get(&table).copied().unwrap_or(1);
            if need > t {
                counts.insert(table.clone(), need);
                if let Some(i) = first_mention(seat) {
                    inferred
                        .entry(table.clone())
                        .or_insert_with(|| super::understood::phrase(&r, i));
                }
            }
        }
    }
    if people.is_some()
        && !counts
            .keys()
            .any(|c| super::groups::group_of(&probe, c).is_some())
    {
        notes.push("\"for N people\": this scene has no seats to scale; counts kept".into());
    }

    // Clamp counts (a warning names each).
    for (c, n) in counts.iter_mut() {
        if *n > MAX_NUMBER {
            notes.push(format!(
                "{n} {c}: more than {MAX_NUMBER} of one category is not planned; using {MAX_NUMBER}"
            ));
            *n = MAX_NUMBER;
        }
    }
    counts.retain(|_, n| *n > 0);
    if counts.is_empty() {
        return Err(PlanError::NothingRecognised(prompt.trim().to_string()));
    }

    // Style words describe the whole scene unless they are one object's adjectives.
    let styles: Vec<String> = {
        let local = |w: &str| adjectives.values().any(|a| a.iter().any(|x| x == w));
        let mut v: Vec<String> = vec![];
        for w in r.text.split(|c: char| !c.is_alphanumeric() && c != '-') {
            let is_style = style_word(w).is_some()
                || ["-inspired", "-style", "-styled", "-themed"]
                    .iter()
                    .any(|s| w.ends_with(s) && w.len() > s.len());
            if is_style && !local(w) && !v.iter().any(|x| x == w) {
                v.push(w.to_string());
            }
        }
        if r.text.contains("art deco") && !v.iter().any(|x| x == "art deco") {
            v.push("art deco".into());
        }
        v
    };

    // Anchors: the category's, the scene's, then the text's.
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
    // "in one corner, facing the window": one anchor per object, and the facing is what a
    // position word cannot give back, so it stays
    let facing: BTreeSet<usize> = r
        .anchors
        .iter()
        .filter(|(_, a)| *a == Anchor::FaceWindow)
        .map(|&(mi, _)| mi)
        .collect();
    for &(mi, a) in &r.anchors {
        let c = &cats[mi];
        if counts.contains_key(c) && (a == Anchor::FaceWindow || !facing.contains(&mi)) {
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

    // The spec; a category in rows keeps the most rows any mention of it asks.
    let mut rows: BTreeMap<String, u32> = BTreeMap::new();
    for (m, c) in r.mentions.iter().zip(&cats) {
        if m.rows > 0 && !m.negated {
            let e = rows.entry(c.clone()).or_insert(0);
            *e = (*e).max(m.rows);
        }
    }
    let mut objects = BTreeMap::new();
    for (c, n) in &counts {
        let (size, description) = match kb.object(c) {
            Some(o) => (
                sizes.get(c).copied().unwrap_or(o.size),
                describe(
                    o,
                    adjectives.get(c).map(Vec::as_slice).unwrap_or(&[]),
                    &styles,
                ),
            ),
            None => {
                let size = sizes
                    .get(c)
                    .copied()
                    .or_else(|| unknown.get(c).copied())
                    .unwrap_or([0.7, 0.6, 0.9]);
                let mut words = styles.clone();
                words.extend(adjectives.get(c).cloned().unwrap_or_default());
                words.push(c.clone());
                let body = words.join(" ");
                (size, format!("A DSLR photo of {} {body}", article(&body)))
            }
        };
        objects.insert(
            c.clone(),
            ObjectSpec {
                number: *n,
                size,
                description,
                rows: rows.get(c).copied().unwrap_or(0).min(*n),
            },
        );
    }
    let mut spec = SceneSpec {
        scene_type,
        scene_text: prompt.trim().to_string(),
        room: None,
        objects,
        anchors: BTreeMap::new(),
        relations: vec![],
    };
    for (c, n) in &counts {
        for k in 1..=*n {
            spec.anchors.insert(format!("{c}{k}"), anchors[c]);
        }
    }

    // Relations: the text's (every instance of a plural subject), then the scene's defaults,
    // then the functional groups (the text's own stay).
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
        let (sc, oc) = (&cats[si], &cats[oi]);
        let (Some(&ns), Some(_)) = (counts.get(sc), counts.get(oc)) else {
            continue;
        };
        // A seat "around" or "at" its table is the group's relation, whatever the phrase.
        let rel = match super::groups::group_of(&spec, sc) {
            Some((g, t))
                if t == *oc
                    && matches!(
                        rel,
                        super::spec::RelationKind::Around
                            | super::spec::RelationKind::At
                            | super::spec::RelationKind::AtBack
                            | super::spec::RelationKind::Next
                            | super::spec::RelationKind::Flank
                    ) =>
            {
                g
            }
            _ => rel,
        };
        // "a bench on each side of every table": every bench, spread over the tables
        let every = r.mentions[si].plural
            || r.mentions[si].count.unwrap_or(1) > 1
            || r.mentions[si].each_of == Some(oi);
        let n = if every { ns } else { 1 };
        if rel == super::spec::RelationKind::Around
            || rel == super::spec::RelationKind::Flank
            || rel == super::spec::RelationKind::At
            || rel == super::spec::RelationKind::AtBack
        {
            // groups spread them over the object's instances
            if super::groups::group_of(&spec, sc).is_some_and(|(_, t)| t == *oc) {
                continue;
            }
        }
        // "a lamp on each nightstand", "chairs in front of the sofas": the subjects spread
        // over the object's instances, one relation per item; "the nightstand" is one
        let no = counts.get(oc).copied().unwrap_or(1).max(1);
        let om = &r.mentions[oi];
        let spread = om.reference || om.plural || om.count.is_some_and(|c| c > 1);
        let n = if spread && no > 1 {
            n.max(ns.min(no))
        } else {
            n
        };
        for k in 1..=n {
            let ko = if spread { (k - 1) % no + 1 } else { 1 };
            push(
                &mut spec,
                format!("{sc}{k}"),
                rel,
                format!("{oc}{ko}"),
                true,
            );
        }
    }
    if let Some(sc) = scene {
        // a scene's relation of a default that a named thing of its role replaced holds for
        // that thing (the teacher's desk before the whiteboard that replaced the blackboard)
        let filling = |c: &str| -> Option<String> {
            if counts.contains_key(c) {
                return Some(c.to_string());
            }
            let role = super::roles::role_of(c)?;
            counts
                .keys()
                .find(|k| super::roles::role_of(k) == Some(role))
                .cloned()
        };
        for rel in &sc.relations {
            let (Some(subject), Some(object)) = (filling(&rel.subject), filling(&rel.object))
            else {
                continue;
            };
            let (ns, no) = (counts[&subject], counts[&object]);
            let n = if rel.every { ns } else { 1 };
            for k in 1..=n {
                // every one of them spread over the objects ("beer bench* NEXT bench table")
                let ko = if rel.every {
                    (k - 1) % no.max(1) + 1
                } else {
                    1
                };
                push(
                    &mut spec,
                    format!("{subject}{k}"),
                    rel.relation,
                    format!("{object}{ko}"),
                    false,
                );
            }
        }
    }
    super::groups::apply_named(&mut spec, &keep, &named);

    // Room: as stated, else chosen to fit (scaled by "small" / "large").
    let height: f64 = match scene_type {
        SceneType::Indoor => 2.8,
        SceneType::Outdoor => 10.0,
    };
    let stated = r.room;
    let room = match stated {
        Some([w, d]) => {
            let tallest = spec
                .instances()
                .iter()
                .map(|i| i.size[2])
                .fold(0.0, f64::max);
            let h = r.room_height.unwrap_or(height.max(tallest + 0.3));
            Room {
                size: [
                    super::units::cm(w),
                    super::units::cm(d),
                    super::units::cm(h),
                ],
            }
        }
        None => {
            let mut room = room_for(&spec.instances(), scene_type);
            if r.scale < 1.0 {
                room.size = small_room(&spec, &named, room.size, r.scale, scene_type);
            } else if r.scale > 1.0 {
                let s = r.scale.sqrt();
                for k in 0..2 {
                    room.size[k] = (room.size[k] * s * 10.0).ceil() / 10.0;
                }
            }
            // things asked in rows: wide and deep enough for the block and its front
            let need = super::gcp::rows::room_for_rows(&spec);
            for (v, n) in room.size.iter_mut().zip(need) {
                *v = v.max((n * 10.0).ceil() / 10.0);
            }
            room
        }
    };
    spec.room = Some(room);
    if r.room_unitless {
        notes.push(format!(
            "room size {} x {} has no unit: read as metres",
            room.size[0], room.size[1]
        ));
    }
    let fitted = fit(&mut spec, &named, stated.is_some() || r.scale < 1.0)?;
    notes.extend(fitted);
    let understood = super::understood::Understood {
        objects: spec
            .objects
            .iter()
            .map(|(c, o)| super::understood::Because {
                category: c.clone(),
                count: o.number,
                why: super::understood::why(
                    c,
                    &inferred,
                    &named,
                    scene.map(|s| s.name.as_str()),
                    defaults.contains_key(c),
                ),
            })
            .collect(),
        unused: super::understood::unused_words(&r, &styles),
    };
    Ok(Plan {
        spec,
        named,
        notes,
        understood,
        negated,
        exclusive: r.exclusive,
    })
}
