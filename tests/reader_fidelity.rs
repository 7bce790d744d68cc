//! The reader against prompts it was not tuned on: `tests/data/fidelity_own.json` (written to
//! break the reader before it was changed) through the offline planner, with the reading rules
//! of the fidelity corpus (count, absent, fails, max_area) checked on the plan the way
//! `shared/tools/check_fidelity.py` checks them; plus the examples of issue 21.
mod reading;
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::SceneSpec;
use reading::plan;
use regex::Regex;
use serde_json::Value;

/// Whether category `c` has one of `words` as a whole word (optional plural "s") and none of
/// `exclude`.
fn matches(c: &str, words: &[String], exclude: &[String]) -> bool {
    let has = |w: &String| {
        Regex::new(&format!(r"\b{}s?\b", regex::escape(w)))
            .map(|r| r.is_match(c))
            .unwrap_or(false)
    };
    words.iter().any(has) && !exclude.iter().any(has)
}

fn strings(v: &Value, key: &str) -> Vec<String> {
    v[key]
        .as_array()
        .map(|a| {
            a.iter()
                .filter_map(|x| x.as_str().map(str::to_string))
                .collect()
        })
        .unwrap_or_default()
}

/// Instances of `spec` whose category matches.
fn count(spec: &SceneSpec, words: &[String], exclude: &[String]) -> u32 {
    spec.objects
        .iter()
        .filter(|(c, _)| matches(c, words, exclude))
        .map(|(_, o)| o.number)
        .sum()
}

/// Whether `rule` holds for the plan of a prompt (`Err`: the planner's error).
fn holds(rule: &Value, plan: &Result<SceneSpec, String>) -> bool {
    let Ok(spec) = plan else { return false };
    let words = strings(rule, "words");
    match rule["rule"].as_str() {
        // no `n`: at least one, as the runner's checker reads it
        Some("count") => {
            let c = count(spec, &words, &strings(rule, "exclude"));
            rule["n"].as_u64().map_or(c >= 1, |n| c == n as u32)
        }
        Some("absent") => count(spec, &words, &[]) == 0,
        Some("max_area") => spec
            .room
            .is_some_and(|r| r.size[0] * r.size[1] <= rule["m2"].as_f64().unwrap_or(0.0) + 1e-9),
        _ => true,
    }
}

#[test]
fn own_prompts_are_read_the_way_people_mean_them() {
    let cases: Vec<Value> = serde_json::from_str(include_str!("data/fidelity_own.json"))
        .expect("fidelity_own.json is JSON");
    assert!(cases.len() >= 60);
    let (mut held, mut total) = (0, 0);
    let mut failed = vec![];
    for case in &cases {
        let prompt = case["prompt"].as_str().unwrap_or("");
        let plan = plan_prompt(prompt)
            .map(|p| p.spec)
            .map_err(|e| e.to_string());
        if case["fails"].as_bool() == Some(true) {
            total += 1;
            if plan.is_err() {
                held += 1;
            } else {
                failed.push(format!("{prompt}: planned, want a refusal"));
            }
        }
        for rule in case["rules"].as_array().into_iter().flatten() {
            total += 1;
            if holds(rule, &plan) {
                held += 1;
            } else {
                failed.push(format!("{prompt}: {rule}"));
            }
        }
    }
    let share = held as f64 / total as f64;
    eprintln!("own set: {held}/{total} rules held\n{}", failed.join("\n"));
    // The level reached (108/120 after the second round, 173/178 after the third with 24
    // more prompts, 221/226 after the fourth with 20 more, 281/287 after the fifth with 21
    // more, 799/814 after the sixth with 42 more); it may only go up.
    assert!(
        share >= 0.97,
        "{held}/{total} rules held:\n{}",
        failed.join("\n")
    );
}

/// The size the plan of `prompt` gives category `c`.
fn size(prompt: &str, c: &str) -> [f64; 3] {
    plan(prompt)
        .objects
        .get(c)
        .unwrap_or_else(|| panic!("{prompt}: no {c}"))
        .size
}

fn n(spec: &SceneSpec, word: &str, exclude: &[&str]) -> u32 {
    let ex: Vec<String> = exclude.iter().map(|s| s.to_string()).collect();
    count(spec, &[word.to_string()], &ex)
}

#[test]
fn issue_21_distributive_counts() {
    let s = plan("4 small tables with 2 chairs each");
    assert_eq!(n(&s, "chair", &["arm", "bar"]), 8, "{:?}", s.objects.keys());
    let s = plan("a beach with 3 umbrellas and 6 sun loungers, two under each umbrella");
    assert_eq!(n(&s, "umbrella", &["stand"]), 3);
    let s = plan("a dining room with a table for six");
    assert_eq!(n(&s, "chair", &["arm", "bar"]), 6);
    let s =
        plan("an office: 6 desks in two rows of three, each with an office chair and a monitor");
    assert_eq!(n(&s, "desk", &[]), 6);
    assert!(n(&s, "row", &[]) == 0);
}

#[test]
fn issue_21_words_that_are_no_objects() {
    let s = plan("a study with a big oak worktable covered in scrolls");
    assert_eq!(n(&s, "covered", &[]), 0);
    let s = plan("an office, 6 desks, two rows");
    assert_eq!(n(&s, "row", &[]), 0);
}

#[test]
fn issue_21_named_objects_fill_roles() {
    let s = plan("a bedroom with a single bed");
    assert_eq!(n(&s, "bed", &["sofa", "dog"]), 1, "{:?}", s.objects.keys());
    let s = plan("a classroom with a whiteboard");
    assert_eq!(n(&s, "blackboard", &[]), 0);
    let s = plan("a living room without a tv");
    assert_eq!(n(&s, "tv", &[]), 0, "{:?}", s.objects.keys());
}

#[test]
fn issue_21_other_languages_are_refused() {
    let e = plan_prompt("un salon acogedor con un sofá")
        .err()
        .map(|e| e.to_string());
    assert!(e.is_some_and(|e| e.contains("--llm-url")));
}

/// A short English prompt with one noun the planner lacks is English (its other words are
/// ones the lexicon knows); short prompts in other languages are still refused.
#[test]
fn short_english_with_an_unknown_noun_is_read() {
    for p in [
        "a huge tesseract",
        "a tiny orrery",
        "two enormous zeppelins",
    ] {
        let s = plan(p);
        assert_eq!(
            s.instances().len(),
            if p.starts_with("two") { 2 } else { 1 },
            "{p}"
        );
    }
    for p in [
        "une chambre avec un grand lit double",
        "uma sala com um sofá e uma mesa",
        "een woonkamer met een bank en een tafel",
    ] {
        let e = plan_prompt(p).err().map(|e| e.to_string());
        assert!(e.is_some_and(|e| e.contains("--llm-url")), "{p}");
    }
}

#[test]
fn issue_21_room_sizes() {
    let area = |p: &str| {
        let r = plan(p).room.expect("a room");
        r.size[0] * r.size[1]
    };
    assert!(area("a small bedroom") < 16.0);
    assert!(area("a bedroom 3 x 3") <= 9.0 + 1e-9);
}

#[test]
fn issue_21_huge_and_tiny_scale_the_object() {
    let plain = size("a games room with a tv and a sofa", "tv");
    let huge = size("a games room with a huge tv and a sofa", "tv");
    assert!(
        huge[0] > plain[0] * 1.3 && huge[2] > plain[2] * 1.3,
        "{huge:?} {plain:?}"
    );
    let plain = size("a study with a desk and a bookshelf", "desk");
    let tiny = size("a study with a tiny desk and a bookshelf", "desk");
    assert!(tiny[0] < plain[0] * 0.8, "{tiny:?} {plain:?}");
}

#[test]
fn small_and_big_scale_the_footprint_not_the_height() {
    let plain = size("a bedroom with a bed and a rug", "rug");
    let big = size("a bedroom with a bed and a big rug", "rug");
    assert!(
        big[0] > plain[0] * 1.15 && big[1] > plain[1] * 1.15,
        "{big:?} {plain:?}"
    );
    let plain = size("a study with an armchair and a table", "dining table");
    let small = size("a study with an armchair and a small table", "dining table");
    assert!(
        small[0] < plain[0] * 0.85 && small[1] < plain[1] * 0.85,
        "{small:?} {plain:?}"
    );
    assert!(
        (small[2] - plain[2]).abs() < 1e-9,
        "a small table keeps its height: {small:?} {plain:?}"
    );
    // a category already described as small is not made smaller again
    let cafe = size(
        "a cafe with a small cafe table and two chairs",
        "cafe table",
    );
    let kind = size("a cafe with a cafe table and two chairs", "cafe table");
    assert_eq!(cafe, kind, "a small cafe table is the cafe table's size");
}

#[test]
fn issue_21_scene_types_never_replace_named_content() {
    // a known template never stands in for the owner's place
    let s = plan("a wizard's laboratory: a cauldron, a stuffed owl and a telescope");
    for absent in ["fume hood", "microscope", "whiteboard"] {
        assert_eq!(n(&s, absent, &[]), 0, "{:?}", s.objects.keys());
    }
    assert_eq!(n(&s, "telescope", &[]), 1);
    // an unknown place is the place, not an object in it
    let s = plan("a mermaid grotto with a giant clam shell and some coral");
    assert_eq!(n(&s, "grotto", &[]), 0, "{:?}", s.objects.keys());
    let s = plan("an elven treehouse with a hammock and two stools");
    assert_eq!(n(&s, "treehouse", &[]), 0, "{:?}", s.objects.keys());
    assert_eq!(n(&s, "stool", &[]), 2);
    let s = plan("the control room of a submarine: a periscope and two consoles");
    assert_eq!(n(&s, "submarine", &[]), 0, "{:?}", s.objects.keys());
    assert_eq!(
        n(&s, "console", &[]),
        2,
        "the named consoles are its consoles"
    );
    // a scene's name said as one of the contents is that object ("... and a bar")
    for p in [
        "a cellar with a wine rack and a bar",
        "a poker room with three card tables, a dozen chairs and a bar",
    ] {
        let s = plan(p);
        assert_eq!(n(&s, "pool table", &[]), 0, "{p}: {:?}", s.objects.keys());
        assert_eq!(n(&s, "bar", &[]), 1, "{p}: {:?}", s.objects.keys());
    }
    // ... but a thing with parts is still the thing
    let s = plan("a harp with gold strings");
    assert_eq!(n(&s, "harp", &[]), 1, "{:?}", s.objects.keys());
    // a size word of the room is not the place's kind ("tiny apartment")
    let s = plan("a tiny bedroom with a single bed");
    assert_eq!(n(&s, "stove", &[]), 0, "{:?}", s.objects.keys());
    let s = plan("the school library with two reading tables");
    assert_eq!(n(&s, "blackboard", &[]), 0, "{:?}", s.objects.keys());
}

#[test]
fn issue_21_what_replaces_or_owns_an_object() {
    // "instead of a X", "rather than the X"
    for p in [
        "a guest room with a futon instead of a bed",
        "a loft with a mattress rather than the bed",
    ] {
        let s = plan(p);
        assert_eq!(
            n(&s, "bed", &["sofa", "day"]),
            0,
            "{p}: {:?}",
            s.objects.keys()
        );
    }
    // ... and passes its negation on to nothing after it
    let s = plan("a teen room: a daybed instead of a bed, a gaming desk and a lamp");
    assert_eq!(n(&s, "gaming desk", &[]), 1, "{:?}", s.objects.keys());
    // two names in a row are one object, named by the last
    let s = plan("a crypt with a stone coffin");
    assert_eq!(n(&s, "rock", &[]), 0, "{:?}", s.objects.keys());
    assert_eq!(n(&s, "sarcophagus", &[]), 1);
    // an owner's object is a particular one of its kind
    let s = plan("a lab with four benches and a professor's desk");
    assert_eq!(n(&s, "professor", &[]), 1, "{:?}", s.objects.keys());
    let s = plan("a classroom with twelve desks and the headmaster's desk");
    assert_eq!(n(&s, "desk", &["headmaster"]), 12, "{:?}", s.objects);
    assert_eq!(
        n(&s, "headmaster", &[]),
        1,
        "it takes the teacher desk's place"
    );
    // and fills its kind's role
    let s = plan("a kids room with the child's bed and a toy chest");
    assert_eq!(n(&s, "bed", &[]), 1, "{:?}", s.objects.keys());
}

#[test]
fn issue_21_counts_per_and_each_placed() {
    let s = plan("a tea room with six little tables and two chairs per table");
    assert_eq!(n(&s, "table", &["side", "coffee"]), 6, "{:?}", s.objects);
    assert_eq!(n(&s, "chair", &["arm"]), 12);
    // tables said with their seats are tables to sit at, even where the scene's are side tables
    let s = plan("a lounge with four small tables and three chairs at each table");
    assert_eq!(n(&s, "dining table", &[]), 4, "{:?}", s.objects);
    assert_eq!(n(&s, "chair", &["arm"]), 12, "{:?}", s.objects);
    let s = plan("a living room with three little tables");
    assert_eq!(n(&s, "side table", &[]), 3, "{:?}", s.objects);
    let s = plan("a dressing room with two stools, each in front of a mirror");
    assert_eq!(n(&s, "mirror", &[]), 2, "{:?}", s.objects);
    // "each facing the window" names one window, no object per stool
    let s = plan("a bar with four stools, each facing the tv");
    assert_eq!(n(&s, "tv", &["stand"]), 1, "{:?}", s.objects);
    let s = plan("a farmhouse kitchen with a big table and a bench on each long side");
    assert_eq!(n(&s, "bench", &[]), 2, "{:?}", s.objects);
}

#[test]
fn a_verb_between_a_relative_pronoun_and_a_number_is_no_object() {
    for (prompt, word, chairs) in [
        ("a kitchen with a table that seats six", "seat", Some(6)),
        (
            "a dining room with a long table which seats eight",
            "seat",
            Some(8),
        ),
        ("a campsite with a tent that sleeps four", "sleep", None),
    ] {
        let s = plan(prompt);
        assert_eq!(n(&s, word, &[]), 0, "{prompt}: {:?}", s.objects.keys());
        if let Some(c) = chairs {
            assert_eq!(
                n(&s, "chair", &["arm", "bar"]),
                c,
                "{prompt}: {:?}",
                s.objects.keys()
            );
        }
    }
    // A relative pronoun before a plural noun with no number keeps the noun an object.
    let s = plan("a cinema with a screen and rows of theater seats that face it");
    assert!(n(&s, "seat", &[]) > 0, "{:?}", s.objects.keys());
}

#[test]
fn a_size_word_does_not_name_another_kind_than_the_scene_uses() {
    // "long" describes the lab's own benches; it names no banquet bench.
    let s = plan("a science lab with four long benches in two rows, two stools at each bench");
    assert_eq!(n(&s, "banquet", &[]), 0, "{:?}", s.objects.keys());
    assert_eq!(n(&s, "science bench", &[]), 4, "{:?}", s.objects.keys());
    let s = plan("a classroom with a large desk for the teacher and twenty desks");
    assert_eq!(n(&s, "executive", &[]), 0, "{:?}", s.objects.keys());
}

#[test]
fn a_participle_after_the_determiner_describes_the_object() {
    for (prompt, word) in [
        ("a hunting lodge with a fireplace and a stuffed elk", "elk"),
        (
            "a gallery with two carved gargoyles and a bench",
            "gargoyle",
        ),
    ] {
        let s = plan(prompt);
        assert!(n(&s, word, &[]) >= 1, "{prompt}: {:?}", s.objects.keys());
    }
    // A participle after its noun still names nothing.
    let s = plan("a study with a big oak worktable covered in scrolls");
    assert_eq!(n(&s, "covered", &[]), 0, "{:?}", s.objects.keys());
}

#[test]
fn a_plain_noun_is_its_everyday_kind() {
    // A clock is a wall clock, a banner no tapestry, "dais" no plural of "dai" (WordNet).
    let s = plan("an office with a desk and a clock on the wall");
    assert_eq!(n(&s, "grandfather", &[]), 0, "{:?}", s.objects.keys());
    assert_eq!(n(&s, "clock", &[]), 1, "{:?}", s.objects.keys());
    let s = plan("a gym hall with a banner and two benches");
    assert_eq!(n(&s, "tapestry", &[]), 0, "{:?}", s.objects.keys());
    let s = plan("a throne room with a throne on a dais");
    assert!(
        s.objects.contains_key("dais") && !s.objects.contains_key("dai"),
        "{:?}",
        s.objects.keys()
    );
}

#[test]
fn an_unknown_noun_takes_its_wordnet_kind_for_its_size() {
    let s = plan("a study with a desk and a stuffed owl");
    let owl = &s.objects["owl"];
    assert!(owl.size[2] < 0.6, "an owl is small: {:?}", owl.size);
    let s = plan("a parlour with a divan and a rug");
    let sofa = dreamscene::plan::kb::KnowledgeBase::builtin()
        .object("sofa")
        .map(|o| o.size)
        .unwrap_or_default();
    assert_eq!(s.objects["divan"].size, sofa, "a divan is a kind of sofa");
}

#[test]
fn a_relation_said_of_each_item_holds_per_item() {
    for prompt in [
        "a bedroom with a double bed, two nightstands and a lamp on each nightstand",
        "a bedroom with a double bed and a lamp on each of the two nightstands",
    ] {
        let s = plan(prompt);
        let mut on: Vec<&str> = s
            .relations
            .iter()
            .filter(|r| r.subject.contains("lamp") && r.object.contains("nightstand"))
            .map(|r| r.object.as_str())
            .collect();
        on.sort();
        assert_eq!(
            on,
            ["nightstand1", "nightstand2"],
            "{prompt}: {:?}",
            s.relations
        );
    }
}

#[test]
fn what_a_thing_is_for_names_its_kind() {
    let s = plan("a nursery with a crib, a rocking chair and two little chairs for kids");
    assert_eq!(n(&s, "kids chair", &[]), 2, "{:?}", s.objects.keys());
    assert_eq!(n(&s, "rocking chair", &[]), 1, "{:?}", s.objects.keys());
}

#[test]
fn a_place_that_is_not_the_template_lends_only_generic_furniture() {
    for (prompt, not) in [
        (
            "a haunted ballroom with a grand piano and a few chairs",
            "dj booth",
        ),
        (
            "a steampunk workshop with a workbench and a telescope",
            "car",
        ),
        (
            "a pirate ship's hold with barrels, crates and a hammock",
            "cannon",
        ),
        (
            "a space station galley with a table and four chairs",
            "console",
        ),
    ] {
        let s = plan(prompt);
        assert_eq!(n(&s, not, &[]), 0, "{prompt}: {:?}", s.objects.keys());
    }
    // the template's own place keeps its furniture
    let s = plan("a ballroom with a grand piano");
    assert_eq!(n(&s, "dj booth", &[]), 1, "{:?}", s.objects.keys());
}

#[test]
fn wordnet_gives_kinds_and_singulars() {
    use dreamscene::plan::lexicon::{kind, known_singular, Kind};
    assert_eq!(kind("dais"), Some(Kind::Category("stage")));
    assert_eq!(kind("accordion"), Some(Kind::Size("small")));
    assert_eq!(kind("owl"), None, "owl is a knowledge-base name now");
    assert_eq!(kind("divan"), Some(Kind::Category("sofa")));
    assert_eq!(kind("sofa"), None, "a knowledge-base name needs no kind");
    assert_eq!(known_singular("dais"), Some("dais"));
    assert_eq!(known_singular("mice"), Some("mouse"));
    assert_eq!(known_singular("chairs"), None);
    // nouns that are never adjectives name an unknown thing's kind before its head noun
    use dreamscene::plan::lexicon::is_noun;
    assert!(is_noun("tape") && is_noun("information") && is_noun("hamster"));
    assert!(!is_noun("little") && !is_noun("wooden") && !is_noun("stone"));
}
