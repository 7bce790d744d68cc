//! The describe stage of the offline planner: style words, each object's text-to-3D
//! description and size in the spec, and what the planner understood (each object's count and
//! why, the words not used).
use super::Draft;
use crate::plan::finish::{place_finish, refinish, Finish};
use crate::plan::gcp::classes::Placements;
use crate::plan::kb::ObjectKind;
use crate::plan::spec::{ObjectSpec, SceneSpec, SceneType};
use std::collections::BTreeMap;

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

pub(super) fn article(s: &str) -> &'static str {
    match s.chars().next() {
        Some('a' | 'e' | 'i' | 'o' | 'u') => "an",
        _ => "a",
    }
}

/// The description of `o` with the text's `adjectives` for it and the scene's `styles`; an
/// object the text does not describe takes the knowledge base's description, in the place's
/// `finish` where it has one (a clinic's cabinet is white steel).
pub(super) fn describe(
    o: &ObjectKind,
    adjectives: &[String],
    styles: &[String],
    finish: Option<&Finish>,
) -> String {
    let mut words: Vec<String> = styles.to_vec();
    if adjectives.is_empty() {
        words.push(match finish {
            Some(f) => refinish(&o.description, f),
            None => o.description.clone(),
        });
    } else {
        // an adjective the name already says ("a potted plant" said as "a potted palm") once
        let named: Vec<&str> = o.category.split_whitespace().collect();
        words.extend(
            adjectives
                .iter()
                .filter(|a| !named.contains(&a.as_str()))
                .cloned(),
        );
        words.push(o.category.clone());
    }
    let body = words.join(" ");
    format!("A DSLR photo of {} {body}", article(&body))
}

/// "a bookcase full of books": what the text says a category holds ends its description,
/// unless the description already says it (a bookshelf is drawn filled with books); "a fridge
/// of drinks" is a fridge full of drinks.
fn with_contents(d: &Draft, category: &str, description: String) -> String {
    let said =
        d.r.contents
            .iter()
            .find(|(i, ..)| d.cats.get(*i).is_some_and(|c| c == category));
    match said {
        Some((_, what, ..))
            if !what
                .rsplit(' ')
                .next()
                .is_some_and(|w| description.contains(w)) =>
        {
            // one filling: what the drawn one holds ("filled with books", "with boxes") gives
            // way to what the text says
            let body = [" filled with ", " full of ", " with "]
                .iter()
                .filter_map(|f| description.find(f))
                .min()
                .map_or(description.as_str(), |i| &description[..i]);
            match what.strip_prefix("of ") {
                Some(x) => format!("{body} full of {x}"),
                None => format!("{body} {what}"),
            }
        }
        Some(_) => description,
        // what the place shows in it (a bookshop's display case is full of books)
        None => match place_holds(d.scene.map(|s| s.name.as_str()), category) {
            Some(x) if !description.contains(x) => format!("{description} full of {x}"),
            _ => description,
        },
    }
}

/// What `category` holds in the place `scene` when the text says nothing of it
/// (`kb/holds.txt`: a bookshop's display case, books; a museum's, artefacts).
fn place_holds(scene: Option<&str>, category: &str) -> Option<&'static str> {
    let scene = scene?;
    include_str!("../kb/holds.txt")
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .find_map(|l| {
            let f: Vec<&str> = l.split('|').map(str::trim).collect();
            (f.len() == 3 && f[0] == scene && f[1].split(',').any(|c| c.trim() == category))
                .then_some(f[2])
        })
}

/// Style words describe the whole scene unless they are one object's adjectives or part of an
/// object's name ("a little wooden bridge" names a wooden bridge: the park is not wooden).
pub(super) fn styles(d: &Draft) -> Vec<String> {
    let Draft { r, adjectives, .. } = d;
    let local = |w: &str| adjectives.values().any(|a| a.iter().any(|x| x == w));
    let named = |s: usize, e: usize| {
        r.mentions
            .iter()
            .any(|m| m.known && m.start <= s && e <= m.end)
    };
    let mut v: Vec<String> = vec![];
    for w in r.text.split(|c: char| !c.is_alphanumeric() && c != '-') {
        let at = w.as_ptr() as usize - r.text.as_ptr() as usize;
        let is_style = style_word(w).is_some()
            || ["-inspired", "-style", "-styled", "-themed"]
                .iter()
                .any(|s| w.ends_with(s) && w.len() > s.len());
        if is_style && !local(w) && !named(at, at + w.len()) && !v.iter().any(|x| x == w) {
            v.push(w.to_string());
        }
    }
    if r.text.contains("art deco") && !v.iter().any(|x| x == "art deco") {
        v.push("art deco".into());
    }
    v
}

/// The spec's objects: each category's count, size and description; a category in rows keeps
/// the most rows any mention of it asks.
pub(super) fn objects(d: &Draft, styles: &[String]) -> BTreeMap<String, ObjectSpec> {
    let Draft {
        kb,
        r,
        cats,
        counts,
        sizes,
        unknown,
        adjectives,
        laid,
        ..
    } = d;
    let mut rows: BTreeMap<String, u32> = BTreeMap::new();
    for (m, c) in r.mentions.iter().zip(cats.iter()) {
        if m.rows > 0 && !m.negated && !super::relations::hung(c) {
            let e = rows.entry(c.clone()).or_insert(0);
            *e = (*e).max(m.rows);
        }
    }
    let finish = place_finish(d.scene.map(|s| s.name.as_str()), &r.text);
    let mut objects = BTreeMap::new();
    for (c, n) in counts.iter() {
        let (size, description) = match kb.object(c) {
            Some(o) => (
                sizes.get(c).copied().unwrap_or_else(|| {
                    // a thing of outdoor scale takes its indoor size in a room
                    let indoor = (d.scene_type == SceneType::Indoor)
                        .then(|| Placements::builtin().indoor_size(c))
                        .flatten();
                    indoor.unwrap_or(o.size)
                }),
                describe(
                    o,
                    adjectives.get(c).map(Vec::as_slice).unwrap_or(&[]),
                    styles,
                    finish.as_ref(),
                ),
            ),
            None => {
                let size = sizes
                    .get(c)
                    .copied()
                    .or_else(|| unknown.get(c).copied())
                    .unwrap_or([0.7, 0.6, 0.9]);
                let mut words = styles.to_vec();
                words.extend(adjectives.get(c).cloned().unwrap_or_default());
                words.push(c.clone());
                let body = words.join(" ");
                (size, format!("A DSLR photo of {} {body}", article(&body)))
            }
        };
        let description = with_contents(d, c, description);
        objects.insert(
            c.clone(),
            ObjectSpec {
                number: *n,
                size,
                description,
                rows: rows.get(c).copied().unwrap_or(0).min(*n),
                // tables laid for different numbers: each its own size
                sizes: laid
                    .get(c)
                    .filter(|(_, each)| each.len() == *n as usize)
                    .map(|(_, each)| each.iter().map(|&(_, s)| s).collect())
                    .unwrap_or_default(),
                on_wall: None,
            },
        );
    }
    objects
}

/// `why` with what the text says `category` holds ("named, full of paint cans"): the words
/// of its contents are planned into its description, and said back where the user sees them.
fn held(d: &Draft, category: &str, why: String) -> String {
    let said =
        d.r.contents
            .iter()
            .find(|(i, ..)| d.cats.get(*i).is_some_and(|c| c == category));
    match said {
        Some((_, what, ..)) => match what.strip_prefix("of ") {
            Some(x) => format!("{why}, full of {x}"),
            None => format!("{why}, {what}"),
        },
        None => why,
    }
}

/// Each object's count and why it is there, and the words not used.
pub(super) fn understood(
    d: &Draft,
    spec: &SceneSpec,
    styles: &[String],
) -> crate::plan::understood::Understood {
    let Draft {
        r,
        scene,
        named,
        defaults,
        inferred,
        ..
    } = d;
    // "a dentist waiting room": the words naming the place's finish are used (its furniture is
    // described in that finish)
    let mut used = styles.to_vec();
    if let Some(f) = place_finish(scene.map(|s| s.name.as_str()), &r.text) {
        used.extend(f.words.iter().map(|w| w.to_string()));
    }
    crate::plan::understood::Understood {
        objects: spec
            .objects
            .iter()
            .map(|(c, o)| crate::plan::understood::Because {
                category: c.clone(),
                count: o.number,
                why: held(
                    d,
                    c,
                    crate::plan::understood::why(
                        c,
                        inferred,
                        named,
                        scene.map(|s| s.name.as_str()),
                        defaults.contains_key(c),
                    ),
                ),
            })
            .collect(),
        unused: crate::plan::understood::unused_words(r, &used),
    }
}

#[cfg(test)]
mod tests {
    use crate::plan::kb::KnowledgeBase;

    /// Every line of `kb/holds.txt` names a place of `kb/scenes.txt` and categories of
    /// `kb/objects.txt` (a misspelt one would silently show nothing), and says what they hold.
    #[test]
    fn the_places_holdings_name_known_places_and_categories() {
        let kb = KnowledgeBase::builtin();
        let mut lines = 0;
        for l in include_str!("../kb/holds.txt")
            .lines()
            .map(str::trim)
            .filter(|l| !l.is_empty() && !l.starts_with('#'))
        {
            let f: Vec<&str> = l.split('|').map(str::trim).collect();
            assert_eq!(f.len(), 3, "holds.txt: {l}");
            assert!(
                kb.scenes.iter().any(|s| s.name == f[0]),
                "holds.txt: no place `{}`",
                f[0]
            );
            for c in f[1].split(',').map(str::trim) {
                assert!(
                    kb.object(c).is_some_and(|o| o.category == c),
                    "holds.txt: `{c}` is no category"
                );
            }
            assert!(!f[2].is_empty(), "holds.txt: {l}");
            lines += 1;
        }
        assert!(lines > 0);
    }
}
