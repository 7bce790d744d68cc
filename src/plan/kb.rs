//! The offline planner's knowledge base: object categories (real sizes, default anchors,
//! descriptions, synonyms) and scene types (default furniture, anchors, relations), kept as data
//! in `src/plan/kb/*.txt` and embedded in the binary.
use super::spec::{Anchor, RelationKind, SceneType};
use std::collections::BTreeMap;
use std::sync::OnceLock;

/// One object category.
#[derive(Debug, Clone, PartialEq)]
pub struct ObjectKind {
    pub category: String,
    pub synonyms: Vec<String>,
    /// [width, depth, height] in metres.
    pub size: [f64; 3],
    pub anchor: Anchor,
    pub description: String,
    /// The shape archetype that draws it, as the table's sixth column names it (empty when the
    /// row has none: `shape::archetype_of` then goes by the category's words). The planner does
    /// not depend on the shapes; `shape` resolves and checks the names.
    pub archetype: String,
}

/// A default relation of a scene type, between categories.
#[derive(Debug, Clone, PartialEq)]
pub struct KbRelation {
    pub subject: String,
    /// Applies to every instance of the subject (`*` in the data).
    pub every: bool,
    pub relation: RelationKind,
    pub object: String,
}

/// One scene type.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneKind {
    pub name: String,
    pub scene_type: SceneType,
    pub synonyms: Vec<String>,
    pub objects: Vec<(String, u32)>,
    /// Defaults that belong to the place's kind (a ballroom's dance floor; `+` after the count in
    /// `kb/scenes.txt`): a fantastical version of the place keeps them with its generic furniture.
    pub own: Vec<String>,
    /// Defaults the place cannot do without (a kitchen's refrigerator, a bedroom's bed; `!` after
    /// the count): a room too small for every default loses the others first.
    pub essential: Vec<String>,
    pub anchors: BTreeMap<String, Anchor>,
    pub relations: Vec<KbRelation>,
    /// The floor a place of this kind has when the text gives none (an optional seventh field
    /// of `kb/scenes.txt`, "W D" in metres): a balcony is a narrow strip, whatever its furniture.
    pub floor: Option<[f64; 2]>,
    /// The height of a place whose kind is tall (a church, a barn, a cave; `height H` in the
    /// seventh field): its room's height when the text gives none, instead of a house's 2.8 m.
    pub height: Option<f64>,
    /// Whether a place of this kind has windows (`windowless` in the seventh field: a cave, a
    /// cellar): one without gets none unless the text counts some.
    pub windows: bool,
}

/// The seventh field of `kb/scenes.txt`: an optional floor `W D` in metres, then optional
/// `height H` (metres) and `windowless`, in any order after the floor.
type PlaceField = (Option<[f64; 2]>, Option<f64>, bool);

fn place_field(x: &str) -> Result<PlaceField, String> {
    let mut nums = vec![];
    let (mut height, mut windows) = (None, true);
    let mut it = x.split_whitespace();
    while let Some(t) = it.next() {
        match t {
            "height" => {
                let h: f64 = it
                    .next()
                    .and_then(|n| n.parse().ok())
                    .filter(|h: &f64| *h >= 2.0 && *h <= 30.0)
                    .ok_or("height must be `height H` in metres (2 to 30)")?;
                height = Some(h);
            }
            "windowless" => windows = false,
            n => nums.push(
                n.parse::<f64>()
                    .map_err(|_| format!("`{n}` in the place field"))?,
            ),
        }
    }
    let floor = match nums[..] {
        [] => None,
        [w, d] if w > 0.0 && d > 0.0 => Some([w, d]),
        _ => return Err("floor must be `W D` in metres".into()),
    };
    Ok((floor, height, windows))
}

/// Categories and scene types.
#[derive(Debug, Clone)]
pub struct KnowledgeBase {
    pub objects: Vec<ObjectKind>,
    pub scenes: Vec<SceneKind>,
    by_name: BTreeMap<String, usize>,
}

pub fn parse_anchor(s: &str) -> Option<Anchor> {
    match s.trim().to_ascii_uppercase().as_str() {
        "CENTER" | "CENTRE" | "MIDDLE" => Some(Anchor::Center),
        "SIDE" | "WALL" | "EDGE" => Some(Anchor::Side),
        "CORNER" => Some(Anchor::Corner),
        "OTHERS" | "OTHER" | "ANY" | "ANYWHERE" | "NONE" => Some(Anchor::Others),
        "WINDOW" => Some(Anchor::Window),
        "FACE_WINDOW" => Some(Anchor::FaceWindow),
        "DOOR" => Some(Anchor::Door),
        "FACE_DOOR" => Some(Anchor::FaceDoor),
        _ => None,
    }
}

pub fn parse_relation(s: &str) -> Option<RelationKind> {
    use RelationKind::*;
    match s
        .trim()
        .to_ascii_uppercase()
        .replace(['_', '-'], " ")
        .as_str()
    {
        "LEFT" | "LEFT OF" | "TO THE LEFT OF" => Some(Left),
        "RIGHT" | "RIGHT OF" | "TO THE RIGHT OF" => Some(Right),
        "FRONT" | "IN FRONT OF" | "IN FRONT" | "FRONT OF" => Some(Front),
        "BEHIND" | "BACK" | "BACK OF" => Some(Behind),
        "OVER" | "ON" | "ON TOP OF" | "ABOVE" | "ATOP" => Some(Over),
        "UNDER" | "BELOW" | "BENEATH" | "UNDERNEATH" => Some(Under),
        "NEXT" | "NEXT TO" | "BESIDE" | "NEAR" | "BY" | "ADJACENT" => Some(Next),
        "OPPOSITE" | "OPPOSITE OF" | "OPPOSITE TO" | "FACING" | "ACROSS FROM" => Some(Opposite),
        "AROUND" | "AROUND OF" => Some(Around),
        "AT" => Some(At),
        "FLANK" | "FLANKING" | "ON EITHER SIDE OF" => Some(Flank),
        "CIRCLE" | "CIRCLING" => Some(Circle),
        "ROW" | "IN A ROW" | "ROWS" => Some(Row),
        "AT BACK" => Some(AtBack),
        "BEFORE" => Some(Before),
        _ => None,
    }
}

fn list(s: &str) -> Vec<String> {
    s.split(',')
        .map(|x| x.trim().to_lowercase())
        .filter(|x| !x.is_empty())
        .collect()
}

impl KnowledgeBase {
    /// The knowledge base shipped with the binary.
    pub fn builtin() -> &'static KnowledgeBase {
        static KB: OnceLock<KnowledgeBase> = OnceLock::new();
        KB.get_or_init(|| {
            KnowledgeBase::parse(
                include_str!("kb/objects.txt"),
                include_str!("kb/scenes.txt"),
            )
            .expect("the built-in knowledge base is valid (tested)")
        })
    }

    /// Parses the two tables; errors name the line.
    pub fn parse(objects: &str, scenes: &str) -> Result<KnowledgeBase, String> {
        let mut kb = KnowledgeBase {
            objects: vec![],
            scenes: vec![],
            by_name: BTreeMap::new(),
        };
        for (ln, line) in objects.lines().enumerate() {
            let line = line.trim();
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            let err = |m: &str| format!("objects.txt line {}: {m}", ln + 1);
            let f: Vec<&str> = line.split('|').map(str::trim).collect();
            if f.len() != 5 && f.len() != 6 {
                return Err(err("expected 5 or 6 fields"));
            }
            let size: Vec<f64> = f[2]
                .split_whitespace()
                .map(|v| v.parse::<f64>().map_err(|e| err(&e.to_string())))
                .collect::<Result<_, _>>()?;
            let [w, d, h] = size[..] else {
                return Err(err("size needs three numbers"));
            };
            let anchor = parse_anchor(f[3]).ok_or_else(|| err("unknown anchor"))?;
            let archetype = f.get(5).map_or(String::new(), |a| a.to_lowercase());
            let o = ObjectKind {
                category: f[0].to_lowercase(),
                synonyms: list(f[1]),
                size: [w, d, h],
                anchor,
                description: f[4].to_string(),
                archetype,
            };
            let idx = kb.objects.len();
            for name in std::iter::once(&o.category).chain(&o.synonyms) {
                if let Some(&other) = kb.by_name.get(name) {
                    if other == idx {
                        return Err(err(&format!("`{name}` listed twice")));
                    }
                    let first = &kb.objects[other].category;
                    return Err(err(&if *name == o.category && *first == o.category {
                        format!("category `{name}` defined twice")
                    } else {
                        format!("`{name}` already names `{first}`")
                    }));
                }
                kb.by_name.insert(name.clone(), idx);
            }
            kb.objects.push(o);
        }
        for (ln, line) in scenes.lines().enumerate() {
            let line = line.trim();
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            let err = |m: &str| format!("scenes.txt line {}: {m}", ln + 1);
            let f: Vec<&str> = line.split('|').map(str::trim).collect();
            if f.len() != 6 && f.len() != 7 {
                return Err(err("expected 6 or 7 fields"));
            }
            let (floor, height, windows) = match f.get(6) {
                None => (None, None, true),
                Some(x) => place_field(x).map_err(|m| err(&m))?,
            };
            let scene_type = match f[1] {
                "indoor" => SceneType::Indoor,
                "outdoor" => SceneType::Outdoor,
                _ => return Err(err("type must be indoor or outdoor")),
            };
            let resolve = |name: &str| -> Result<String, String> {
                kb.object(name)
                    .map(|o| o.category.clone())
                    .ok_or_else(|| err(&format!("unknown object `{name}`")))
            };
            let mut objs = vec![];
            let mut own = vec![];
            let mut essential = vec![];
            for item in list(f[3]) {
                let (name, n) = item
                    .rsplit_once(':')
                    .ok_or_else(|| err(&format!("`{item}` needs :count")))?;
                let marks = n.trim_start_matches(|c: char| c.is_ascii_digit() || c == ' ');
                let n: u32 = n[..n.len() - marks.len()]
                    .trim()
                    .parse()
                    .map_err(|_| err(&format!("count in `{item}`")))?;
                let c = resolve(name.trim())?;
                for m in marks.trim().chars() {
                    match m {
                        '+' => own.push(c.clone()),
                        '!' => essential.push(c.clone()),
                        _ => return Err(err(&format!("mark `{m}` in `{item}` (+ or !)"))),
                    }
                }
                objs.push((c, n));
            }
            let mut anchors = BTreeMap::new();
            for item in list(f[4]) {
                let (name, a) = item
                    .split_once('=')
                    .ok_or_else(|| err(&format!("`{item}` needs =ANCHOR")))?;
                let a = parse_anchor(a).ok_or_else(|| err(&format!("anchor in `{item}`")))?;
                anchors.insert(resolve(name.trim())?, a);
            }
            let mut relations = vec![];
            for item in f[5].split(';').map(str::trim).filter(|s| !s.is_empty()) {
                let words: Vec<&str> = item.split_whitespace().collect();
                let pos = words
                    .iter()
                    .position(|w| {
                        w.chars().all(|c| c.is_ascii_uppercase() || c == '_')
                            && parse_relation(w).is_some()
                    })
                    .ok_or_else(|| err(&format!("no relation in `{item}`")))?;
                let mut subject = words[..pos].join(" ");
                let every = subject.ends_with('*');
                subject = subject.trim_end_matches('*').to_string();
                let relation = parse_relation(words[pos]).expect("checked");
                let object = words[pos + 1..].join(" ");
                let (subject, object) = (resolve(&subject)?, resolve(&object)?);
                for c in [&subject, &object] {
                    if !objs.iter().any(|(o, _)| o == c) {
                        return Err(err(&format!("relation uses `{c}`, not in the scene")));
                    }
                }
                relations.push(KbRelation {
                    subject,
                    every,
                    relation,
                    object,
                });
            }
            kb.scenes.push(SceneKind {
                name: f[0].to_lowercase(),
                scene_type,
                synonyms: list(f[2]),
                objects: objs,
                own,
                essential,
                anchors,
                relations,
                floor,
                height,
                windows,
            });
        }
        Ok(kb)
    }

    /// The category named `name` (its name or a synonym, singular, lower case).
    pub fn object(&self, name: &str) -> Option<&ObjectKind> {
        self.by_name.get(name).map(|&i| &self.objects[i])
    }

    /// Every (name, category) pair: categories and synonyms.
    pub fn names(&self) -> impl Iterator<Item = (&str, &ObjectKind)> {
        self.by_name
            .iter()
            .map(|(k, &i)| (k.as_str(), &self.objects[i]))
    }

    /// The scene type named `name` or a synonym.
    pub fn scene(&self, name: &str) -> Option<&SceneKind> {
        self.scenes
            .iter()
            .find(|s| s.name == name || s.synonyms.iter().any(|x| x == name))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builtin_knowledge_base_is_complete() {
        let kb = KnowledgeBase::builtin();
        let indoor = kb
            .scenes
            .iter()
            .filter(|s| s.scene_type == SceneType::Indoor)
            .count();
        let outdoor = kb.scenes.len() - indoor;
        assert!(
            indoor >= 25 && outdoor >= 8,
            "{indoor} indoor, {outdoor} outdoor"
        );
        assert!(kb.objects.len() >= 500, "{} categories", kb.objects.len());
        for o in &kb.objects {
            assert!(
                o.size.iter().all(|&v| v > 0.0 && v <= 20.0),
                "{}",
                o.category
            );
            assert!(!o.description.is_empty());
        }
        for s in &kb.scenes {
            assert!(!s.objects.is_empty(), "{}", s.name);
            if s.scene_type == SceneType::Outdoor {
                assert!(
                    !s.anchors.values().any(|a| *a == Anchor::Corner),
                    "{}",
                    s.name
                );
            }
        }
        assert_eq!(kb.object("couch").unwrap().category, "sofa");
        assert_eq!(kb.scene("lounge").unwrap().name, "living room");
    }

    #[test]
    fn every_builtin_category_names_its_archetype() {
        for line in include_str!("kb/objects.txt").lines() {
            let line = line.trim();
            if !line.is_empty() && !line.starts_with('#') {
                assert_eq!(line.split('|').count(), 6, "no archetype column: {line}");
            }
        }
        let kb = KnowledgeBase::builtin();
        assert_eq!(kb.object("couch").unwrap().archetype, "sofa");
        let k = KnowledgeBase::parse("desk chair | | 0.6 0.6 1 | OTHERS | a chair", "").unwrap();
        assert_eq!(k.objects[0].archetype, "", "no column: left to the shapes");
    }

    #[test]
    fn malformed_tables_name_the_line() {
        let e = KnowledgeBase::parse("sofa | couch | 2 1 | SIDE | a sofa", "").unwrap_err();
        assert!(e.contains("line 1"), "{e}");
        let e = KnowledgeBase::parse(
            "sofa | couch | 2 1 0.8 | SIDE | a sofa",
            "x | indoor | | sofa:1, lamp:1 | | ",
        )
        .unwrap_err();
        assert!(e.contains("lamp"), "{e}");
    }

    #[test]
    fn every_row_names_known_categories_or_the_table_fails_with_its_line() {
        let objects =
            "sofa | couch | 2 1 0.8 | SIDE | a sofa\nlamp | | 0.3 0.3 1.5 | CORNER | a lamp";
        let e = KnowledgeBase::parse(
            objects,
            "# a comment\nx | indoor | | sofa:1, lamp:1 | | sofa NEXT lamp; lounge chair* NEXT sofa",
        )
        .unwrap_err();
        assert_eq!(e, "scenes.txt line 2: unknown object `lounge chair`");
        let e = KnowledgeBase::parse(objects, "x | indoor | | sofa:1 | chair=SIDE | ").unwrap_err();
        assert_eq!(e, "scenes.txt line 1: unknown object `chair`");
        let e = KnowledgeBase::parse(&format!("{objects}\nsettee | couch | 2 1 1 | SIDE | s"), "")
            .unwrap_err();
        assert_eq!(e, "objects.txt line 3: `couch` already names `sofa`");
        let e = KnowledgeBase::parse(objects, "x | indoor | | sofa:1?, lamp:1 | | ").unwrap_err();
        assert!(e.starts_with("scenes.txt line 1: mark `?`"), "{e}");
    }

    #[test]
    fn a_scene_marks_its_own_and_its_essential_defaults() {
        let k = KnowledgeBase::parse(
            "sofa | | 2 1 0.8 | SIDE | a sofa\nlamp | | 0.3 0.3 1.5 | CORNER | a lamp",
            "x | indoor | | sofa:1!+, lamp:2 | | ",
        )
        .unwrap();
        assert_eq!(
            k.scenes[0].objects,
            [("sofa".into(), 1), ("lamp".into(), 2)]
        );
        assert_eq!(k.scenes[0].own, ["sofa"]);
        assert_eq!(k.scenes[0].essential, ["sofa"]);
        let kitchen = KnowledgeBase::builtin().scene("kitchen").unwrap();
        assert!(
            kitchen.essential.iter().any(|c| c == "refrigerator"),
            "a kitchen cannot do without its refrigerator"
        );
    }
}
