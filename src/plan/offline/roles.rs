//! The roles stage of the offline planner: which objects the plan holds before counting (the
//! scene's defaults, only the generic ones for a place that is not the template's own), the
//! category each mention means in this scene ("desks" in a classroom are school desks, "a big
//! potted palm" a potted plant), and after counting what negation and the roles of named objects
//! take away (the role table is `plan::roles`).
use super::seats::seat_for;
use super::Draft;
use crate::plan::kb::KnowledgeBase;
use crate::plan::lang;
use std::collections::BTreeMap;

/// The scene's default furniture (`counts` and `defaults`), less what a place that is not the
/// template's own does not take.
pub(super) fn scene_defaults(d: &mut Draft) {
    let (kb, scene) = (d.kb, d.scene);
    let Draft {
        r, counts, notes, ..
    } = d;
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
        notes.extend(without_their_partners(
            scene,
            counts,
            &Default::default(),
            |_| true,
        ));
    }
    d.defaults = d.counts.clone();
}

/// The scene's defaults of the kinds `which` keeps that serve only what the plan no longer
/// holds go with it: a seat whose group partners (`kb/groups.txt`: the tables it stands at or
/// around) are among the scene's defaults but none is left (the visitor chairs of an office
/// "with no meeting table"). Named categories (`named`) stay. One note each.
fn without_their_partners(
    scene: Option<&crate::plan::kb::SceneKind>,
    counts: &mut BTreeMap<String, u32>,
    named: &std::collections::BTreeSet<String>,
    which: impl Fn(&str) -> bool,
) -> Vec<String> {
    let lone: Vec<String> = counts
        .keys()
        .filter(|c| !named.contains(*c) && which(c))
        .filter(|c| {
            let objs = crate::plan::groups::partners_of(c);
            scene.is_some_and(|s| s.objects.iter().any(|(o, _)| objs.contains(&o.as_str())))
                && !objs.iter().any(|o| counts.contains_key(*o))
        })
        .cloned()
        .collect();
    lone.into_iter()
        .map(|c| {
            counts.remove(&c);
            format!("default `{c}` left out: what it goes with is left out")
        })
        .collect()
}

/// Whether `category` is a kind of what the text named as `said` (singular): the same
/// category, a compound with it as head ("visitor chair" of "chair") or a one-word kind of it
/// (`kb/words.txt`: kinds; an armchair is a chair).
fn kind_of_said(category: &str, said: &str) -> bool {
    category == said
        || category
            .strip_suffix(said)
            .is_some_and(|q| q.ends_with(' '))
        || lang::kind_of_compound(category) == Some(said)
}

/// The category each mention means (`cats`).
/// "one long table with ten chairs around it, a vase on the table": "the table" is that long
/// table, whatever kind the place gives a bare table (after [`mention_kinds`]).
pub(super) fn definites_as_named(d: &mut Draft) {
    for i in 0..d.cats.len() {
        let m = &d.r.mentions[i];
        if !m.definite || m.count.is_some() || m.plural || m.negated || m.owner.is_some() {
            continue;
        }
        let earlier = d.r.mentions[..i]
            .iter()
            .position(|o| o.category == m.category && !o.definite && !o.negated && !o.reference);
        if let Some(e) = earlier {
            d.cats[i] = d.cats[e].clone();
        }
    }
}

pub(super) fn mention_kinds(d: &mut Draft) {
    let (kb, scene) = (d.kb, d.scene);
    d.cats =
        d.r.mentions
            .iter()
            .map(|m| in_scene(kb, scene, m))
            .collect();
    let Draft {
        r,
        cats,
        counts,
        notes,
        ..
    } = d;
    // "ten round tables ... and a top table": an unknown kind of a noun of which the text
    // already names a kind is another object, not more of the scene's (it is sized as them).
    for i in 0..cats.len() {
        let m = &r.mentions[i];
        if m.known || m.reference || cats[i] == m.category {
            continue;
        }
        let head = m.category.rsplit(' ').next();
        let named_elsewhere = r.mentions.iter().zip(cats.iter()).any(|(o, c)| {
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
        let grouped_elsewhere = crate::plan::groups::group_of_category(c).is_some_and(|objs| {
            scene.is_some_and(|s| s.objects.iter().any(|(o, _)| objs.contains(&o.as_str())))
        });
        if *c != m.category
            && grouped_elsewhere
            && crate::plan::groups::relation_between(c, tc).is_none()
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
        // "a small table and four little chairs around it" says them with the table too
        use crate::plan::spec::RelationKind::{Around, At};
        let round_it = r
            .relations
            .iter()
            .any(|&(s, k, o)| s == i && o == i - 1 && matches!(k, Around | At));
        // "a big table in the middle, six chairs around it": said around it, a comma apart
        // ("a big table in the centre with 8 chairs": what the table is said with, after where)
        let with = (between.trim_start().starts_with("with ") || between.contains(" with "))
            && !between.contains([',', ';', '.']);
        let head = lang::singular(m.text.rsplit(' ').next().unwrap_or(""));
        // (a bare generic noun is read again even where the place has no kind of it)
        if (cats[i] == m.category && m.category != head) || !(with || round_it) {
            continue;
        }
        let table = &cats[i - 1];
        let sits = |c: &str| {
            let one: BTreeMap<String, u32> = [(c.to_string(), 0)].into();
            c.rsplit(' ').next() == Some(head.as_str())
                && seat_for(table, &one).as_deref() == Some(c)
        };
        // the one named like the table ("kids table", "kids chair"), the scene's seats of that
        // noun it sets at such tables, the text's own kind, the scene's other seats, the usual
        // seats, then any kind of it
        let named_like = table
            .split_once(' ')
            .map(|(q, _)| format!("{q} {head}"))
            .filter(|c| kb.object(c).is_some());
        let usual = seat_for(table, &BTreeMap::new());
        // (the scene's seats only where it sets them at tables of this one's role: "a big
        // table with 8 chairs" in a study seats dining chairs at it, not the study's office
        // chairs, which would call for desks)
        let role = crate::plan::roles::role_of(table);
        let set_at_such = |c: &String| {
            scene_seats.keys().any(|t| {
                let one: BTreeMap<String, u32> = [(c.clone(), 0)].into();
                t != c
                    && crate::plan::roles::role_of(t) == role
                    && seat_for(t, &one).as_deref() == Some(c.as_str())
            })
        };
        let own: Vec<String> = scene_seats
            .keys()
            .filter(|c| set_at_such(c))
            .cloned()
            .collect();
        // (a bare generic noun, "stools" with a breakfast bar, is the table's usual seat of
        // that noun, its bar stools, before the plain kind)
        let generic = (m.category == head).then(|| usual.clone()).flatten();
        let seat = named_like
            .into_iter()
            .chain(own)
            .chain(generic)
            .chain(Some(m.category.clone()))
            .chain(scene_seats.keys().cloned())
            .chain(usual)
            .chain(kb.objects.iter().map(|o| o.category.clone()))
            .find(|c| sits(c));
        if let Some(seat) = seat {
            cats[i] = seat;
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
        if crate::plan::groups::relation_between(&c, &t).is_some() {
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
    // "a chair either side of the fireplace" in a living room: a bare noun the scene has no
    // default of is the default that is a kind of it by another name (its armchairs), unless a
    // table the text names seats it ("a dining table and four chairs"). Seats set out in rows
    // ("chairs in rows") are an audience's, never the room's easy chairs.
    for i in 0..r.mentions.len() {
        let m = &r.mentions[i];
        let head = lang::singular(m.text.rsplit(' ').next().unwrap_or(""));
        if cats[i] != m.category
            || m.owner.is_some()
            || m.text.split(' ').count() != 1
            || m.in_rows
            || m.rows > 0
        {
            continue;
        }
        let Some(s) = scene else { continue };
        // no more than the scene holds of them: "six chairs" in a lounge are other chairs
        let Some((kind, _)) = s
            .objects
            .iter()
            .filter(|(c, _)| lang::kind_of_compound(c) == Some(head.as_str()))
            .filter(|(_, n)| m.count.unwrap_or(1) <= *n)
            .max_by_key(|(_, n)| *n)
        else {
            continue;
        };
        let seat: BTreeMap<String, u32> = [(m.category.clone(), 0)].into();
        let seated = cats
            .iter()
            .chain(r.mentions.iter().map(|o| &o.category))
            .any(|t| seat_for(t, &seat).as_deref() == Some(m.category.as_str()));
        if !seated && !s.objects.iter().any(|(c, _)| *c == m.category) {
            cats[i] = kind.clone();
        }
    }
    // "shelves on the wall above them", "two tapestries on the wall": a thing said to be on
    // a wall is the kind of its noun that hangs there (a wall shelf, not a storage shelf)
    let on_wall = regex::Regex::new(
        r"^(?: of [a-z]+(?: [a-z]+)?)?,? (?:(?:hung|hanging|mounted|fixed|high) )?on (?:the|a|one|each|every) walls?\b",
    )
    .expect("valid regex");
    let table = crate::plan::gcp::classes::Placements::builtin();
    let hangs = |c: &str| matches!(table.class(c), crate::plan::gcp::classes::Class::OnWall(_));
    for (i, m) in r.mentions.iter().enumerate() {
        if !on_wall.is_match(&r.text[m.end..]) || hangs(&cats[i]) {
            continue;
        }
        let head = lang::singular(m.text.rsplit(' ').next().unwrap_or(""));
        if let Some(o) = kb
            .objects
            .iter()
            .find(|o| o.category.rsplit(' ').next() == Some(head.as_str()) && hangs(&o.category))
        {
            // the scene's default the noun was read as is this one (the laundry's shelving)
            let was = std::mem::replace(&mut cats[i], o.category.clone());
            if was != m.category && !cats.contains(&was) && counts.remove(&was).is_some() {
                notes.push(format!(
                    "default {was} left out: the named {} takes its place",
                    o.category
                ));
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
}

/// What negation and the roles of named objects take away from the counts: a negated
/// category, the defaults whose roles named objects fill, the single default a particular
/// named one replaces ("the invigilator's desk"), and the defaults of a negated role.
pub(super) fn take_away(d: &mut Draft) {
    let Draft {
        r,
        scene,
        cats,
        counts,
        defaults,
        named,
        negated,
        others,
        explicit,
        notes,
        ..
    } = d;
    // Negation removes the category, defaults included.
    for c in negated.iter() {
        counts.remove(c);
        named.remove(c);
    }
    notes.extend(crate::plan::roles::without_what_they_hold(
        counts, named, negated,
    ));
    // Named objects fill the roles of the defaults they replace, and so does the kind a named
    // thing was said as ("a reading lamp on the desk", a table lamp, is the room's standing lamp).
    let filling: std::collections::BTreeSet<String> = named
        .iter()
        .cloned()
        .chain(
            r.mentions
                .iter()
                .filter(|m| !m.negated && !m.reference)
                .filter_map(|m| m.said_as.clone()),
        )
        .collect();
    let replaced = crate::plan::roles::apply(counts, &filling, r.exclusive);
    let any_replaced = !replaced.is_empty();
    notes.extend(replaced);
    // the seat of a default a named thing replaced goes with it (the teacher's chair of the
    // teacher's desk a named lectern replaced)
    if any_replaced {
        notes.extend(without_their_partners(*scene, counts, named, lang::is_seat));
    }
    // "the invigilator's desk": a particular one takes the place of the scene's single
    // default of its kind (the teacher's desk).
    for (m, cat) in r.mentions.iter().zip(cats.iter()) {
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
    for c in others.iter() {
        if !named.contains(c) {
            counts.remove(c);
        }
    }
    counted_nouns(r, cats, counts, defaults, named, explicit, *scene, notes);
    // "no chair": every kind of what is negated goes, the visitor chairs of an office as well
    // as its office chairs; a noun said alone names its role too ("no bath": no bathtub of any
    // kind), a kind said in full only itself ("no dining table" leaves a kitchen's island).
    let mut any = false;
    for (m, cat) in r.mentions.iter().zip(cats.iter()) {
        if !m.negated || !(negated.contains(cat) || others.contains(cat)) {
            continue;
        }
        any = true;
        let said = lang::singular(&m.text);
        let role = (!said.contains(' '))
            .then(|| crate::plan::roles::role_of(cat))
            .flatten();
        counts.retain(|k, _| {
            named.contains(k)
                || !(kind_of_said(k, &said)
                    || kind_of_said(k, cat)
                    || role.is_some_and(|role| crate::plan::roles::role_of(k) == Some(role)))
        });
    }
    // the seats that served only the negated things go with them (the chairs around a
    // table; a coffee table stays for the armchairs when the sofa goes)
    if any {
        notes.extend(without_their_partners(*scene, counts, named, lang::is_seat));
    }
}

/// "five manicure tables, two chairs at each": a bare noun the text counts ("chairs") is all of
/// it the place has (`kb/words.txt`: counted_whole), so the scene's other defaults of that noun
/// (its pedicure chairs) do not
/// add to it; those the place cannot do without or that is its own stay, and so do those that
/// serve something else the plan holds (the teacher's chair at the teacher's desk) or that the
/// place sets with another thing it holds (a library's reading chairs by their floor lamps).
#[allow(
    clippy::too_many_arguments,
    reason = "the draft's fields, borrowed apart"
)]
fn counted_nouns(
    r: &lang::Reading,
    cats: &[String],
    counts: &mut BTreeMap<String, u32>,
    defaults: &BTreeMap<String, u32>,
    named: &std::collections::BTreeSet<String>,
    explicit: &BTreeMap<String, u32>,
    scene: Option<&crate::plan::kb::SceneKind>,
    notes: &mut Vec<String>,
) {
    for (m, cat) in r.mentions.iter().zip(cats) {
        let counted = m.count.is_some_and(|n| n >= 2) || m.each_of.is_some();
        if m.negated || m.reference || !counted || m.text.contains(' ') {
            continue;
        }
        if !explicit.contains_key(cat) {
            continue;
        }
        let head = lang::singular(&m.text);
        if !lang::counts_whole(&head) {
            continue;
        }
        let gone: Vec<String> = defaults
            .keys()
            .filter(|c| *c != cat && !named.contains(*c) && counts.contains_key(*c))
            .filter(|c| c.rsplit(' ').next() == Some(head.as_str()))
            .filter(|c| scene.is_none_or(|s| !s.own.contains(c) && !s.essential.contains(c)))
            .filter(|c| {
                !crate::plan::groups::partners_of(c)
                    .iter()
                    .any(|p| *p != cat && counts.contains_key(*p))
            })
            .filter(|c| {
                let other = |o: &String| o != *c && o != cat && counts.contains_key(o);
                !scene.is_some_and(|s| {
                    s.relations.iter().any(|k| {
                        (k.subject == **c && other(&k.object))
                            || (k.object == **c && other(&k.subject))
                    })
                })
            })
            .cloned()
            .collect();
        for c in gone {
            counts.remove(&c);
            notes.push(format!(
                "default {c} left out: the text counts the {head}s ({cat})"
            ));
        }
    }
}

/// The scene's default category that the text's noun `m` means: "desks" in a classroom are
/// school desks, "chairs" in a cafe are cafe chairs (the default sharing the head noun, the
/// most numerous first).
fn in_scene(
    kb: &KnowledgeBase,
    scene: Option<&crate::plan::kb::SceneKind>,
    m: &lang::Mention,
) -> String {
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
        return most_its_own(s, s.objects.iter().filter(same_head))
            .unwrap_or_else(|| m.category.clone());
    }
    // "ten round tables" at a wedding: a kind said in several words that a kind of the
    // place's own names in full, with more words, is that kind (its round banquet tables,
    // with their banquet chairs round them)
    let said_words: Vec<String> = m.text.split(' ').map(lang::singular).collect();
    if said_words.len() > 1 {
        let fuller = s.objects.iter().filter(|(c, _)| {
            let words: Vec<&str> = c.split(' ').collect();
            words.len() > said_words.len()
                && words.last().copied() == said_words.last().map(String::as_str)
                && said_words.iter().all(|w| words.contains(&w.as_str()))
        });
        if let Some(c) = most_its_own(s, fuller) {
            return c;
        }
    }
    // "shelving units" in a shop: a thing said by a name that says only its role (`kb/roles.txt`:
    // generic) is the scene's default of that role (the shop's display shelves); a kind said
    // by its own name ("bookcases", "a drinks fridge") stays itself.
    let words: Vec<&str> = m.text.split(' ').collect();
    let said = match words.split_last() {
        Some((last, rest)) if !rest.is_empty() => {
            format!("{} {}", rest.join(" "), lang::singular(last))
        }
        _ => head.clone(),
    };
    // a synonym of a generic name says no more than it ("a front desk" is a reception desk)
    let generic = crate::plan::roles::is_generic(&said)
        || kb
            .object(&said)
            .is_some_and(|o| o.category != said && crate::plan::roles::is_generic(&o.category));
    if generic {
        if let Some(role) = crate::plan::roles::role_of(&m.category) {
            let filled = s
                .objects
                .iter()
                .filter(|(c, _)| crate::plan::roles::role_of(c) == Some(role))
                .max_by_key(|(_, n)| *n);
            if let Some((c, _)) = filled {
                return c.clone();
            }
        }
    }
    // "four seats" in a kitchen, "seats" in a waiting room: a name as general as a seat can be
    // (`kb/words.txt`: generic_seats) is the place's own seat, the most numerous (its theatre
    // seats only where it has them)
    if m.text.split(' ').count() == 1 && lang::is_generic_seat(&head) {
        let seats = s.objects.iter().filter(|(c, _)| lang::is_seat(c));
        if let Some(c) = most_its_own(s, seats) {
            return c;
        }
    }
    // Only what scenes specialise (`kb/words.txt`: specialised); a lamp stays a lamp.
    if !lang::is_specialised(&head) {
        return m.category.clone();
    }
    let head_cat = kb.object(&head).map(|o| o.category.clone());
    // Only a bare head noun ("desks", "a chair") is re-read; "an office chair" stays.
    // "two wall shelves", "floating shelves" name their kind (one of a compound name) by a
    // word of its own name even where the head noun alone ("shelf") is a name of it too; a
    // kind named by the bare noun ("computer desks" are desks) is still re-read
    let own_word = kb.object(&m.category).is_some_and(|o| {
        o.category != head
            && std::iter::once(&o.category)
                .chain(&o.synonyms)
                .flat_map(|n| n.split(' '))
                .filter(|w| *w != head)
                .any(|w| m.text.split(' ').any(|t| t == w))
    });
    let bare = m.text.split(' ').count() == 1
        || (head_cat.as_deref() == Some(m.category.as_str()) && !own_word);
    if !bare {
        return m.category.clone();
    }
    // "one long table for twenty" in a banquet hall: a round kind of the place's is not the
    // long one said, nor a long kind a round one
    let round = |c: &str| {
        c.split(' ').any(|w| w == "round")
            || kb
                .object(c)
                .is_some_and(|o| o.archetype.starts_with("round"))
    };
    let said_shape = m.adjectives.iter().find_map(|a| match a.as_str() {
        "round" | "circular" => Some(true),
        "long" | "rectangular" | "oblong" | "square" | "trestle" => Some(false),
        _ => None,
    });
    let sharing = s.objects.iter().filter(|(c, _)| {
        c.rsplit(' ').next() == Some(head.as_str())
            || kb.object(&head).is_some_and(|o| o.category == **c)
    });
    most_its_own(s, sharing)
        .or_else(|| set_on_its_own(kb, s, &head))
        .filter(|c| said_shape.is_none_or(|r| round(c) == r))
        .unwrap_or_else(|| m.category.clone())
}

/// The kind of `head` the knowledge base has that is set on a support of the place's own
/// (`kb/placement.txt`, first support): "a pot" in a kitchen is the cooking pot its stove holds.
fn set_on_its_own(
    kb: &KnowledgeBase,
    scene: &crate::plan::kb::SceneKind,
    head: &str,
) -> Option<String> {
    let placements = crate::plan::gcp::classes::Placements::builtin();
    kb.objects
        .iter()
        .filter(|o| o.category.rsplit(' ').next() == Some(head) && o.category != head)
        .find(|o| {
            placements
                .get(&o.category)
                .and_then(|p| p.supports.first())
                .is_some_and(|first| scene.objects.iter().any(|(c, _)| c == first))
        })
        .map(|o| o.category.clone())
}

/// Of the scene's defaults `candidates`, the one a bare noun means: the most numerous; of as
/// many, the place's own kind (`+` in `kb/scenes.txt`): "chairs" in a barber's are its barber
/// chairs, not its waiting chairs.
fn most_its_own<'a>(
    scene: &crate::plan::kb::SceneKind,
    candidates: impl Iterator<Item = &'a (String, u32)>,
) -> Option<String> {
    candidates
        .max_by_key(|(c, n)| (*n, scene.own.contains(c)))
        .map(|(c, _)| c.clone())
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
