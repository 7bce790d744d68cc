//! The offline parser of plain move and motion commands: "move the sofa back half a metre",
//! "turn the chair to face the tv", "drive forward 3 m then turn left", "walk to the door",
//! "spin twice", "circle around the table", "bounce three times", "grow to twice its size".
//!
//! The objects a sentence names are found among the scene's instances (ids such as `chair2`,
//! category names and their knowledge-base synonyms, singular or plural); the first one is what
//! moves unless the caller names it. The sentence is cut into steps at "then", "and then",
//! "after that", ";" and "," (and at "and" before a new verb); each step reads its direction,
//! distance, angle, count, factor and duration. Directions are in the moving object's own frame
//! (forward is where it faces, left is forward turned +90°); angles are counter-clockwise seen
//! from above ("right" and "clockwise" turn negative). Host-only.
use crate::plan::kb::KnowledgeBase;
use crate::plan::spec::RelationKind;
use regex::Regex;
use std::sync::OnceLock;

/// One step of a command.
#[derive(Debug, Clone, PartialEq)]
pub enum Step {
    /// Shift in the object's frame: metres forward and to its left.
    Shift { forward: f64, left: f64 },
    /// Toward another instance: by `distance`, or (None) until next to it.
    Approach {
        target: String,
        distance: Option<f64>,
    },
    /// Away from another instance.
    Retreat { target: String, distance: f64 },
    /// Beside another instance in a relation (NEXT, FRONT, BEHIND, LEFT, RIGHT).
    Place {
        target: String,
        relation: RelationKind,
    },
    /// To the room's centre.
    Centre,
    /// Turn by degrees (counter-clockwise positive).
    Turn { degrees: f64 },
    /// Turn to face another instance (or turn its back to it).
    Face { target: String, away: bool },
    /// Multiply the scale.
    Scale { factor: f64 },
    /// Go round another instance, keeping the distance (counter-clockwise positive turns).
    Circle { target: String, turns: f64 },
    /// Hop up and down in place.
    Bounce { height: f64, times: u32 },
    /// To and fro `times` over (back and forth, side to side): out by the shift in the object's
    /// frame and back each time; `across` goes as far the other way too before coming back.
    Sway {
        forward: f64,
        left: f64,
        times: u32,
        across: bool,
    },
    /// Stay still.
    Pause,
}

/// A parsed command: who moves and the steps, each with the seconds it was given.
#[derive(Debug, Clone, PartialEq)]
pub struct Command {
    pub subject: Option<String>,
    pub steps: Vec<(Step, Option<f64>)>,
    /// What the sentence says that no step reads ("three times" of a slide), for one line.
    pub unread: Vec<String>,
}

/// Default distance of a move that gives none, and of "a bit", "slightly".
pub const DEFAULT_DISTANCE: f64 = 0.5;
pub const SMALL_DISTANCE: f64 = 0.2;

struct Mention {
    start: usize,
    end: usize,
    id: String,
}

fn re(p: &str) -> Regex {
    Regex::new(p).expect("valid pattern")
}

const NUM: &str = r"(?:\d+(?:\.\d+)?|an?|one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|half an?|a half|one and a half|two and a half|a couple of|a few)";

/// A repeat count: "three times", "twice".
fn times_re() -> &'static Regex {
    static R: OnceLock<Regex> = OnceLock::new();
    R.get_or_init(|| re(&format!(r"\b({NUM})\s+times\b|\b(twice|thrice|once)\b")))
}

fn number(s: &str) -> Option<f64> {
    let s = s.trim();
    if let Ok(v) = s.parse::<f64>() {
        return Some(v);
    }
    Some(match s {
        "a" | "an" | "one" => 1.0,
        "two" | "a couple of" | "twice" => 2.0,
        "three" | "thrice" | "a few" => 3.0,
        "four" => 4.0,
        "five" => 5.0,
        "six" => 6.0,
        "seven" => 7.0,
        "eight" => 8.0,
        "nine" => 9.0,
        "ten" => 10.0,
        "eleven" => 11.0,
        "twelve" => 12.0,
        "half a" | "half an" | "a half" => 0.5,
        "one and a half" => 1.5,
        "two and a half" => 2.5,
        "once" => 1.0,
        _ => return None,
    })
}

fn distance_re() -> &'static Regex {
    static R: OnceLock<Regex> = OnceLock::new();
    R.get_or_init(|| {
        re(&format!(
            r"\b({NUM})\s*(metres?|meters?|m|centimetres?|centimeters?|cm|millimetres?|millimeters?|mm|feet|foot|ft|inch(?:es)?|in|steps?|paces?)\b(\s+and\s+a\s+half)?"
        ))
    })
}

fn angle_re() -> &'static Regex {
    static R: OnceLock<Regex> = OnceLock::new();
    R.get_or_init(|| {
        re(&format!(
            r"\b({NUM})\s*(?:°|degrees?|degs?\b|(full |complete )?(turns?|rotations?|revolutions?|times|laps?|circles?)\b)|\b(twice|thrice|once)\b|(quarter|half)[ -](?:a )?(?:turn|rotation|circle)\b"
        ))
    })
}

fn seconds_re() -> &'static Regex {
    static R: OnceLock<Regex> = OnceLock::new();
    R.get_or_init(|| {
        re(&format!(
            r"\b(?:in|over|for|during|taking|within)\s+({NUM})\s*(?:seconds?|secs?|s)\b|\b({NUM})\s*(?:-\s*)?(?:seconds?|secs?|s)\s+long\b|\b(?:wait|waits|pause|pauses|stop|stops|stay|stays|rest|rests)\s+({NUM})\s*(?:seconds?|secs?|s)\b"
        ))
    })
}

/// Metres of a distance match.
fn metres(caps: &regex::Captures) -> Option<f64> {
    let mut v = number(caps.get(1)?.as_str())?;
    if caps.get(3).is_some() {
        v += 0.5;
    }
    let unit = caps.get(2)?.as_str();
    let k = if unit.starts_with("cent") || unit == "cm" {
        0.01
    } else if unit.starts_with("milli") || unit == "mm" {
        0.001
    } else if unit.starts_with("f") {
        0.3048
    } else if unit.starts_with("in") {
        0.0254
    } else if unit.starts_with("step") || unit.starts_with("pace") {
        0.75
    } else {
        1.0
    };
    Some(v * k)
}

/// Degrees of an angle match (turns counted as 360°).
fn degrees(caps: &regex::Captures) -> Option<f64> {
    if let Some(w) = caps.get(4) {
        return number(w.as_str()).map(|n| 360.0 * n);
    }
    if let Some(q) = caps.get(5) {
        return Some(if q.as_str() == "quarter" { 90.0 } else { 180.0 });
    }
    let n = number(caps.get(1)?.as_str())?;
    Some(if caps.get(3).is_some() { 360.0 * n } else { n })
}

/// The names each instance answers to: its id, its category and the category's synonyms, with
/// plurals.
fn names(objects: &[(String, String)]) -> Vec<(String, String)> {
    let kb = KnowledgeBase::builtin();
    let mut out = vec![];
    let mut cats: Vec<&str> = objects.iter().map(|o| o.1.as_str()).collect();
    cats.dedup();
    for (id, cat) in objects {
        out.push((id.to_lowercase(), id.clone()));
        // The first instance of a category answers to its names.
        if objects.iter().find(|o| &o.1 == cat).map(|o| &o.0) != Some(id) {
            continue;
        }
        let mut words = vec![cat.to_lowercase()];
        if let Some(k) = kb.object(cat) {
            words.extend(k.synonyms.iter().map(|s| s.to_lowercase()));
        }
        for (n, kind) in kb.names() {
            if kind.category == *cat {
                words.push(n.to_string());
            }
        }
        for w in words {
            out.push((format!("{w}s"), id.clone()));
            out.push((format!("{w}es"), id.clone()));
            out.push((w, id.clone()));
        }
    }
    out
}

/// Instance mentions in `t` (lower case), longest names first, without overlaps.
fn mentions(t: &str, objects: &[(String, String)]) -> Vec<Mention> {
    let mut ns = names(objects);
    ns.sort_by_key(|n| std::cmp::Reverse(n.0.len()));
    let mut taken = vec![false; t.len()];
    let mut out = vec![];
    let bytes = t.as_bytes();
    for (name, id) in ns {
        if name.is_empty() {
            continue;
        }
        let mut from = 0;
        while let Some(k) = t[from..].find(&name) {
            let (s, e) = (from + k, from + k + name.len());
            from = e;
            let left_ok = s == 0 || !bytes[s - 1].is_ascii_alphanumeric();
            let right_ok = e == t.len() || !bytes[e].is_ascii_alphanumeric();
            if left_ok && right_ok && !taken[s..e].iter().any(|x| *x) {
                taken[s..e].iter_mut().for_each(|x| *x = true);
                out.push(Mention {
                    start: s,
                    end: e,
                    id: id.clone(),
                });
            }
        }
    }
    out.sort_by_key(|m| m.start);
    out
}

/// The first instance `text` names (what moves in a sentence that names no other subject).
pub fn subject(text: &str, objects: &[(String, String)]) -> Option<String> {
    let lower = text.to_lowercase().replace(['’', '\''], "");
    mentions(&lower, objects).first().map(|m| m.id.clone())
}

/// Parses `text` against the scene's instances `(id, category)`. `default` is the instance the
/// caller named (what "it" is, and what moves when the sentence names none).
pub fn parse(
    text: &str,
    objects: &[(String, String)],
    default: Option<&str>,
) -> Result<Command, String> {
    let lower = text.to_lowercase().replace(['’', '\''], "");
    let found = mentions(&lower, objects);
    // Replace each mention by a placeholder `@k` so the step patterns read plain words.
    let mut t = String::new();
    let mut ids = vec![];
    let mut last = 0;
    for m in &found {
        t.push_str(&lower[last..m.start]);
        t.push_str(&format!("@{}", ids.len()));
        ids.push(m.id.clone());
        last = m.end;
    }
    t.push_str(&lower[last..]);
    // The subject: the caller's, else the first mention; its own first mention is no target
    // ("move @0 back" reads "move it back").
    let subject = default.map(str::to_string).or_else(|| ids.first().cloned());
    let t = match ids.first() {
        Some(first) if Some(first) == subject.as_ref() => t.replacen("@0", "it", 1),
        _ => t,
    };
    let target = |tag: &str| -> Option<String> {
        let k: usize = tag.trim_start_matches('@').parse().ok()?;
        ids.get(k).cloned()
    };
    let mut steps = vec![];
    let mut unread = vec![];
    for clause in split_clauses(&t) {
        if let Some(s) = step(&clause, &target)? {
            // a count only a repeated motion reads
            let repeats = matches!(s.0, Step::Bounce { .. } | Step::Sway { .. });
            if let Some(k) = times_re().find(&clause).filter(|_| !repeats) {
                unread.push(k.as_str().to_string());
            }
            steps.push(s);
        }
    }
    if steps.is_empty() {
        return Err(format!(
            "\"{text}\": no motion understood (say e.g. \"forward 1 m\", \"turn left 90 degrees\", \"to face the tv\", \"next to the sofa\")"
        ));
    }
    if let Some(s) = &subject {
        for (st, _) in &steps {
            let tg = match st {
                Step::Approach { target, .. }
                | Step::Retreat { target, .. }
                | Step::Place { target, .. }
                | Step::Face { target, .. }
                | Step::Circle { target, .. } => Some(target),
                _ => None,
            };
            if tg == Some(s) {
                return Err(format!("\"{text}\": {s} cannot move relative to itself"));
            }
        }
    }
    Ok(Command {
        subject,
        steps,
        unread,
    })
}

fn split_clauses(t: &str) -> Vec<String> {
    static SEP: OnceLock<Regex> = OnceLock::new();
    static AND_VERB: OnceLock<Regex> = OnceLock::new();
    let sep = SEP.get_or_init(|| {
        re(r"\s*(?:,\s*and then|,\s*then|\band then\b|\bthen\b|\bafter that\b|\bafterwards\b|\bfinally\b|;|,|\.\s)\s*")
    });
    let and_verb = AND_VERB.get_or_init(|| {
        re(r"\band\s+(?:(?:then|also)\s+)?(move|go|walk|run|drive|roll|slide|push|pull|turn|rotate|spin|face|circle|orbit|bounce|jump|hop|grow|shrink|come|head|back|wait|pause|stop|make|scale)\b")
    });
    let t = and_verb.replace_all(t, "; $1");
    sep.split(&t)
        .map(|s| s.trim().trim_end_matches('.').to_string())
        .filter(|s| !s.is_empty())
        .collect()
}

/// One clause to a step (None when it says nothing to do, e.g. "please").
fn step(
    c: &str,
    target: &dyn Fn(&str) -> Option<String>,
) -> Result<Option<(Step, Option<f64>)>, String> {
    static TAG: OnceLock<Regex> = OnceLock::new();
    let tag = TAG.get_or_init(|| re(r"@\d+"));
    let has = |w: &str| Regex::new(&format!(r"\b(?:{w})\b")).is_ok_and(|r| r.is_match(c));
    let seconds = seconds_re()
        .captures(c)
        .and_then(|k| number(k.get(1).or(k.get(2)).or(k.get(3))?.as_str()));
    // Remove the duration so its number is not read as a distance or count.
    let c_owned = seconds_re().replace_all(c, " ").to_string();
    let c = c_owned.as_str();
    let tags: Vec<(usize, String)> = tag
        .find_iter(c)
        .filter_map(|m| Some((m.start(), target(m.as_str())?)))
        .collect();
    let first_target = tags.first().map(|t| t.1.clone());
    let dist = distance_re().captures(c).and_then(|k| metres(&k));
    let angle = angle_re().captures(c).and_then(|k| degrees(&k));
    let small = has("a bit|a little|slightly|a touch|an inch|nudge");
    let d = || {
        dist.unwrap_or(if small {
            SMALL_DISTANCE
        } else {
            DEFAULT_DISTANCE
        })
    };
    let before_tag = |words: &str| -> Option<String> {
        let r = Regex::new(&format!(r"\b(?:{words})\s+(?:the\s+|a\s+|an\s+)?(@\d+)")).ok()?;
        r.captures(c).and_then(|k| target(k.get(1)?.as_str()))
    };
    let out = |s: Step| Ok(Some((s, seconds)));

    // Waiting.
    if has("wait|pause|stop|stay|rest|hold still|stand still") && tags.is_empty() {
        return out(Step::Pause);
    }
    // Scale.
    if has("grow|grows|big|bigger|large|larger|enlarge|scale|scaled|shrink|shrinks|small|smaller|double|halve|size") {
        let pct = Regex::new(r"(\d+(?:\.\d+)?)\s*(?:%|percent)")
            .ok()
            .and_then(|r| r.captures(c))
            .and_then(|k| k[1].parse::<f64>().ok());
        let times = Regex::new(&format!(r"\b(?:by|to|x)\s*({NUM})\s*(?:x|times)?\b|\b({NUM})\s*(?:x|times)\b"))
            .ok()
            .and_then(|r| r.captures(c))
            .and_then(|k| number(k.get(1).or(k.get(2))?.as_str()));
        let shrink = has("shrink|shrinks|smaller|halve|reduce");
        let factor = if has("twice|double") {
            2.0
        } else if has("half|halve") {
            0.5
        } else if let Some(p) = pct {
            if shrink {
                1.0 - p / 100.0
            } else {
                1.0 + p / 100.0
            }
        } else if let Some(x) = times.filter(|x| *x > 0.0) {
            x
        } else if shrink {
            0.5
        } else {
            1.5
        };
        if !(factor.is_finite() && factor > 0.0) {
            return Err(format!("\"{c}\": a scale must stay positive"));
        }
        return out(Step::Scale { factor });
    }
    let times = || {
        let n = times_re()
            .captures(c)
            .and_then(|k| number(k.get(1).or(k.get(2))?.as_str()))
            .unwrap_or(1.0);
        (n.round() as u32).max(1)
    };
    // Bounce.
    if has("bounce|bounces|bouncing|jump|jumps|hop|hops") {
        let height = dist.unwrap_or(0.3);
        return out(Step::Bounce {
            height,
            times: times(),
        });
    }
    // To and fro: a motion that comes back, so many times (a rocking chair rocking).
    // ("forward and back" is two clauses: "and back" starts a step of its own)
    if has("back and forth|backward and forward|backwards and forwards|to and fro|forwards and backwards|side to side|left and right|right and left") {
        let m = dist.unwrap_or(SMALL_DISTANCE);
        let sideways = has("side to side|left and right|right and left");
        let first_back = has("back and forth|backward and forward|backwards and forwards");
        let (forward, left) = match (sideways, first_back) {
            (true, _) if has("right and left") => (0.0, -m),
            (true, _) => (0.0, m),
            (false, true) => (-m, 0.0),
            (false, false) => (m, 0.0),
        };
        return out(Step::Sway {
            forward,
            left,
            times: times(),
            across: sideways,
        });
    }
    // Circling another object.
    if let Some(target) = first_target
        .clone()
        .filter(|_| has("circle|circles|circling|orbit|orbits|around|round"))
        .filter(|_| !has("turn around|spin around|turns around"))
    {
        let turns = angle.map_or(1.0, |a| a / 360.0);
        let sign = if has("clockwise")
            && !has("counterclockwise|counter-clockwise|anticlockwise|anti-clockwise")
        {
            -1.0
        } else {
            1.0
        };
        return out(Step::Circle {
            target,
            turns: sign * turns,
        });
    }
    // Facing.
    if let Some(t) = before_tag("face|faces|facing|look at|looks at|looking at|point at|points at|toward|towards")
        .filter(|_| has("turn|turns|rotate|rotates|face|faces|facing|look|looks|looking|point|points|spin"))
        .filter(|_| !has("move|moves|walk|walks|go|goes|drive|drives|come|comes|roll|rolls|slide|slides|push|run|runs"))
    {
        return out(Step::Face { target: t, away: false });
    }
    if let Some(t) = before_tag("away from").filter(|_| has("turn|turns|rotate|rotates|face|faces"))
    {
        return out(Step::Face {
            target: t,
            away: true,
        });
    }
    if has("back to|its back to") && has("turn|turns") {
        if let Some(t) = before_tag("back to") {
            return out(Step::Face {
                target: t,
                away: true,
            });
        }
    }
    // Turning in place.
    if has("turn|turns|rotate|rotates|rotated|spin|spins|spinning|pivot|twist|revolve") {
        let ccw = has("counterclockwise|counter-clockwise|anticlockwise|anti-clockwise|left");
        let cw = !ccw && has("clockwise|right");
        let deg = if has("around|round|about") && angle.is_none() && !has("spin|spins") {
            180.0
        } else if let Some(a) = angle {
            a
        } else if has("spin|spins|spinning|revolve") {
            360.0
        } else if has("slightly|a bit|a little") {
            15.0
        } else {
            90.0
        };
        return out(Step::Turn {
            degrees: if cw { -deg } else { deg },
        });
    }
    // Relative places.
    for (words, rel) in [
        ("next to|beside|alongside|by", RelationKind::Next),
        ("in front of", RelationKind::Front),
        ("behind|in back of", RelationKind::Behind),
        ("to the left of|left of", RelationKind::Left),
        ("to the right of|right of", RelationKind::Right),
    ] {
        if let Some(t) = before_tag(words) {
            return out(Step::Place {
                target: t,
                relation: rel,
            });
        }
    }
    if has("centre|center|middle") && has("room|centre|center|middle") {
        return out(Step::Centre);
    }
    if let Some(t) = before_tag("away from") {
        return out(Step::Retreat {
            target: t,
            distance: d(),
        });
    }
    if let Some(t) =
        before_tag("toward|towards|closer to|nearer to|near|up to|over to|across to|to|into|at")
    {
        return out(Step::Approach {
            target: t,
            distance: if has("closer|nearer|toward|towards") || dist.is_some() {
                Some(d())
            } else {
                None
            },
        });
    }
    // Shifts in the object's frame.
    let fwd = has("forward|forwards|ahead|onward|onwards|straight|advance|advances|front");
    let back = has("back|backward|backwards|backs|reverse|reverses|retreat|retreats");
    let left = has("left|leftward|leftwards");
    let right = has("right|rightward|rightwards");
    if fwd || back || left || right {
        let m = d();
        let f = if fwd {
            m
        } else if back {
            -m
        } else {
            0.0
        };
        let l = if left {
            m
        } else if right {
            -m
        } else {
            0.0
        };
        let n = ((f != 0.0) as u8 + (l != 0.0) as u8) as f64;
        let k = if n > 1.0 {
            std::f64::consts::FRAC_1_SQRT_2
        } else {
            1.0
        };
        return out(Step::Shift {
            forward: f * k,
            left: l * k,
        });
    }
    if has("move|moves|go|goes|walk|walks|drive|drives|roll|rolls|slide|slides|push|run|runs")
        && dist.is_some()
    {
        return out(Step::Shift {
            forward: d(),
            left: 0.0,
        });
    }
    Ok(None)
}

/// The instance a name means: an id ("sofa1"), or a category or one of its names with or
/// without an article and adjectives ("sofa", "the chalkboard menu", "the big armchair").
/// Several instances of that name: an error that lists their ids; none: one that lists the
/// scene's ids.
pub fn resolve(name: &str, objects: &[(String, String)]) -> Result<String, String> {
    let t = crate::plan::lang::normalise(name);
    let t = t.trim_matches(|c: char| c == '"' || c == '\'' || c == '.');
    if let Some((id, _)) = objects.iter().find(|o| o.0.eq_ignore_ascii_case(t)) {
        return Ok(id.clone());
    }
    let kb = KnowledgeBase::builtin();
    let mut best = 0usize;
    let mut found: Vec<&str> = vec![];
    for (id, cat) in objects {
        let mut words = vec![cat.to_lowercase()];
        if let Some(k) = kb.object(cat) {
            words.extend(k.synonyms.iter().map(|s| s.to_lowercase()));
        }
        words.extend(
            kb.names()
                .filter(|(_, k)| k.category == *cat)
                .map(|(n, _)| n.to_string()),
        );
        let forms: Vec<String> = words
            .iter()
            .flat_map(|w| std::iter::once(w.clone()).chain(crate::plan::lang::plurals(w)))
            .collect();
        let len = forms
            .iter()
            .filter(|f| t == f.as_str() || t.ends_with(&format!(" {f}")))
            .map(|f| f.len())
            .max()
            .unwrap_or(0);
        if len > best {
            best = len;
            found.clear();
        }
        if len > 0 && len == best {
            found.push(id);
        }
    }
    if found.is_empty() {
        // "the lamp" for a floor lamp: the head noun of a category's name.
        let head = t.rsplit(' ').next().unwrap_or(t);
        let head = crate::plan::lang::singular(head);
        found = objects
            .iter()
            .filter(|(_, cat)| cat.to_lowercase().rsplit(' ').next() == Some(head.as_str()))
            .map(|(id, _)| id.as_str())
            .collect();
    }
    match found.as_slice() {
        [one] => Ok(one.to_string()),
        [] => {
            let ids: Vec<&str> = objects.iter().map(|o| o.0.as_str()).take(24).collect();
            Err(format!(
                "no object called \"{name}\" in the scene; its ids: {}",
                ids.join(", ")
            ))
        }
        many => Err(format!(
            "\"{name}\" could be {}: give one of these ids",
            many.join(", ")
        )),
    }
}

/// Why a sentence names no one instance: the first word of it that names several ("the sofa"
/// in a room of two sofas), as [`resolve`] says it ("\"sofa\" could be sofa1, sofa2: ...").
pub fn ambiguous(text: &str, objects: &[(String, String)]) -> Option<String> {
    text.split(|c: char| !c.is_alphanumeric())
        .filter(|w| w.len() > 2)
        .find_map(|w| resolve(w, objects).err().filter(|e| e.contains("could be")))
}

/// The count a description of new objects starts with and the rest: "two cafe chairs" is
/// (2, "cafe chairs"), "a pair of lamps" (2, "lamps"), "a green armchair" (1, itself).
pub fn count_of(description: &str) -> (u32, String) {
    let t = crate::plan::lang::normalise(description);
    let words: Vec<&str> = t.split(' ').collect();
    let number = |w: &str| crate::plan::lang::number(w).filter(|_| !["a", "an", "no"].contains(&w));
    let (n, skip) = match words.as_slice() {
        [a, b, "of", ..] if ["a", "an"].contains(a) && number(b).is_some() => (number(b), 3),
        [w, "of", ..] if number(w).is_some() => (number(w), 2),
        [a, b, ..] if ["a", "an"].contains(a) && number(b).is_some() => (number(b), 2),
        [w, ..] if number(w).is_some() => (number(w), 1),
        _ => (None, 0),
    };
    match n {
        Some(n) if n >= 1 && words.len() > skip => (n, words[skip..].join(" ")),
        _ => (1, description.trim().to_string()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene() -> Vec<(String, String)> {
        [
            ("sofa1", "sofa"),
            ("tv1", "tv"),
            ("chair1", "chair"),
            ("chair2", "chair"),
            ("coffee_table1", "coffee table"),
        ]
        .iter()
        .map(|(a, b)| (a.to_string(), b.to_string()))
        .collect()
    }

    #[test]
    fn distances_and_units() {
        let c = parse("move the sofa back half a metre", &scene(), None).unwrap();
        assert_eq!(c.subject.as_deref(), Some("sofa1"));
        assert_eq!(
            c.steps,
            vec![(
                Step::Shift {
                    forward: -0.5,
                    left: 0.0
                },
                None
            )]
        );
        let c = parse("move it 30 cm to the left", &scene(), Some("chair2")).unwrap();
        assert_eq!(c.subject.as_deref(), Some("chair2"));
        assert!(matches!(c.steps[0].0, Step::Shift { left, .. } if (left - 0.3).abs() < 1e-12));
    }
}
