//! Sixty requests as people write them (homes, shops, venues, outdoor places), each with the
//! objects and counts it names, the room size it states, and the functional groups its room
//! must show. Planned and laid out: every named object present, counts exact, sizes as stated,
//! every layout valid, and at least 95% of the functional-group relations met over the set.
use dreamscene::plan::check::{relation_holds, validity_problems};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::*;
use std::collections::BTreeMap;

/// (prompt, stated room [W, D] in metres, (category, exact count; 0: absent)).
type Case = (
    &'static str,
    Option<[f64; 2]>,
    &'static [(&'static str, u32)],
);

const CASES: &[Case] = &[
    // homes
    (
        "a cozy living room with a grey sofa, two armchairs and a coffee table",
        None,
        &[("sofa", 1), ("armchair", 2), ("coffee table", 1)],
    ),
    (
        "a living room, 5m x 4m, with a fireplace and a bookshelf, no tv",
        Some([5.0, 4.0]),
        &[("fireplace", 1), ("bookshelf", 1), ("tv", 0)],
    ),
    (
        "a small living room with a loveseat and a tv on a tv stand",
        None,
        &[("loveseat", 1), ("tv", 1), ("tv stand", 1)],
    ),
    (
        "a scandinavian living room with a sectional sofa, a rug and three plants",
        None,
        &[("sectional sofa", 1), ("rug", 1), ("potted plant", 3)],
    ),
    (
        "a family room with a piano, a sofa and a floor lamp next to the sofa",
        None,
        &[("piano", 1), ("sofa", 1), ("floor lamp", 1)],
    ),
    (
        "a bedroom with a king bed, two nightstands and a dresser",
        None,
        &[("bed", 1), ("nightstand", 2), ("dresser", 1)],
    ),
    (
        "a master bedroom, 4.5 x 4 m, with a wardrobe and a reading chair",
        Some([4.5, 4.0]),
        &[("bed", 1), ("wardrobe", 1), ("reading chair", 1)],
    ),
    (
        "a guest room with a single bed and one nightstand, without a rug",
        None,
        &[("single bed", 1), ("nightstand", 1), ("rug", 0)],
    ),
    (
        "a kid's bedroom with a bunk bed and a toy chest",
        None,
        &[("bunk bed", 1), ("toy chest", 1)],
    ),
    (
        "a nursery with a crib, a changing table and a rocking chair",
        None,
        &[("crib", 1), ("changing table", 1), ("rocking chair", 1)],
    ),
    (
        "a teenager's room with a desk, an office chair and a bean bag",
        None,
        &[("desk", 1), ("office chair", 1), ("bean bag", 1)],
    ),
    (
        "a dining room with a table for eight",
        None,
        &[("dining table", 1), ("dining chair", 8)],
    ),
    (
        "a dining room with a round table and four chairs",
        None,
        &[("round table", 1), ("dining chair", 4)],
    ),
    (
        "a rustic dining room with a farmhouse table, six chairs and a sideboard",
        None,
        &[
            ("farmhouse table", 1),
            ("dining chair", 6),
            ("sideboard", 1),
        ],
    ),
    (
        "a kitchen with an island and three bar stools",
        None,
        &[("kitchen island", 1), ("bar stool", 3)],
    ),
    (
        "a small kitchen, 3 x 2.5 m, with a fridge, a stove and a sink",
        Some([3.0, 2.5]),
        &[("refrigerator", 1), ("stove", 1), ("kitchen sink", 1)],
    ),
    (
        "a kitchen with a kitchen table and four chairs, no island",
        None,
        &[("kitchen island", 0), ("dining chair", 4)],
    ),
    (
        "a bathroom with a bathtub, a toilet and a sink",
        None,
        &[("bathtub", 1), ("toilet", 1), ("bathroom sink", 1)],
    ),
    (
        "a bathroom 2.5m by 2m with a shower and a toilet",
        Some([2.5, 2.0]),
        &[("shower", 1), ("toilet", 1)],
    ),
    (
        "a home office with a standing desk, an office chair and two bookshelves",
        None,
        &[("standing desk", 1), ("office chair", 1), ("bookshelf", 2)],
    ),
    (
        "a study with a desk, a lamp on the desk and a globe",
        None,
        &[("desk", 1), ("table lamp", 1), ("globe", 1)],
    ),
    (
        "a laundry room with a washing machine and a dryer",
        None,
        &[("washing machine", 1), ("dryer", 1)],
    ),
    (
        "a hallway with a bench, a coat rack and a mirror",
        None,
        &[("bench", 1), ("coat rack", 1), ("mirror", 1)],
    ),
    (
        "a garage with a car, a workbench and two bicycles",
        None,
        &[("car", 1), ("workbench", 1), ("bicycle", 2)],
    ),
    (
        "a home gym with a treadmill, a weight bench and a yoga mat",
        None,
        &[("treadmill", 1), ("weight bench", 1), ("yoga mat", 1)],
    ),
    (
        "a studio apartment with a futon and a kitchen table",
        None,
        &[("futon", 1), ("dining table", 1)],
    ),
    (
        "a game room with a pool table and two arcade machines",
        None,
        &[("pool table", 1), ("arcade machine", 2)],
    ),
    (
        "a home theater with six theater seats and a projector screen",
        None,
        &[("theater seat", 6), ("projector screen", 1)],
    ),
    (
        "a music room with a grand piano and a harp",
        None,
        &[("grand piano", 1), ("harp", 1)],
    ),
    (
        "a tea room with a low tea table and four floor cushions",
        None,
        &[("tea table", 1), ("floor cushion", 4)],
    ),
    // shops, offices, schools
    (
        "a cafe with five tables and ten chairs",
        None,
        &[("cafe table", 5), ("cafe chair", 10)],
    ),
    (
        "a coffee shop with a counter, an espresso machine and four bistro tables",
        None,
        &[("counter", 1), ("coffee machine", 1), ("cafe table", 4)],
    ),
    (
        "a bakery with two pastry cases and a counter",
        None,
        &[("pastry case", 2), ("counter", 1)],
    ),
    (
        "a clothing store with four clothes racks and two mannequins",
        None,
        &[("clothes rack", 4), ("mannequin", 2)],
    ),
    (
        "a bookstore with six display shelves and a reading chair",
        None,
        &[("display shelf", 6), ("reading chair", 1)],
    ),
    (
        "a grocery store with eight shelves and two checkout counters",
        None,
        &[("display shelf", 8), ("checkout counter", 2)],
    ),
    (
        "a pharmacy with a counter and five pharmacy shelves",
        None,
        &[("counter", 1), ("pharmacy shelf", 5)],
    ),
    (
        "a barber shop with three barber chairs",
        None,
        &[("barber chair", 3)],
    ),
    (
        "a florist with three flower stands and a counter",
        None,
        &[("flower bucket stand", 3), ("counter", 1)],
    ),
    (
        "an office with four desks and four office chairs",
        None,
        &[("desk", 4), ("office chair", 4)],
    ),
    (
        "a meeting room with a conference table and ten chairs",
        None,
        &[("conference table", 1), ("office chair", 10)],
    ),
    (
        "a classroom with 12 desks and a whiteboard",
        None,
        &[("school desk", 12), ("dining chair", 12), ("whiteboard", 1)],
    ),
    (
        "a classroom for 20 students",
        None,
        &[("school desk", 20), ("dining chair", 20)],
    ),
    (
        "a library with four shelves and two reading tables",
        None,
        &[("library shelf", 4), ("reading table", 2)],
    ),
    (
        "a science lab with three lab benches and a fume hood",
        None,
        &[("science bench", 3), ("fume hood", 1)],
    ),
    // venues
    ("a restaurant with six tables", None, &[("dining table", 6)]),
    (
        "a tavern with a long bar, five stools and three tables",
        None,
        &[("bar counter", 1), ("bar stool", 5), ("cafe table", 3)],
    ),
    (
        "a cocktail bar with a pool table and no wine rack",
        None,
        &[("pool table", 1), ("wine rack", 0)],
    ),
    (
        "a hotel lobby with a reception desk and two sofas",
        None,
        &[("hotel reception desk", 1), ("lobby sofa", 2)],
    ),
    (
        "a waiting room with eight chairs and a water cooler",
        None,
        &[("waiting chair", 8), ("water cooler", 1)],
    ),
    (
        "a church with six pews and an altar",
        None,
        &[("pew", 6), ("altar", 1)],
    ),
    (
        "a museum with three statues and four paintings",
        None,
        &[("statue", 3), ("painting", 4)],
    ),
    (
        "a casino with two poker tables and six slot machines",
        None,
        &[("poker table", 2), ("slot machine", 6)],
    ),
    // outdoor
    (
        "a garden with a fountain in the middle and three benches",
        None,
        &[("fountain", 1), ("park bench", 3)],
    ),
    (
        "a Japanese zen garden with a stone lantern and a koi pond",
        None,
        &[("stone lantern", 1), ("koi pond", 1)],
    ),
    (
        "a small cafe terrace with four tables",
        None,
        &[("cafe table", 4), ("sun lounger", 0), ("barbecue grill", 0)],
    ),
    (
        "a campsite with two tents and four logs around the fire",
        None,
        &[("tent", 2), ("campfire log", 4), ("fire pit", 1)],
    ),
    (
        "a beach with three sun loungers and two umbrellas",
        None,
        &[("sun lounger", 3), ("beach umbrella", 2)],
    ),
    (
        "a playground with a slide, a swing set and a sandbox",
        None,
        &[("slide", 1), ("swing set", 1), ("sandbox", 1)],
    ),
    (
        "a patio with a table, four chairs and a grill",
        None,
        &[
            ("patio table", 1),
            ("patio chair", 4),
            ("barbecue grill", 1),
        ],
    ),
    (
        "a park with a fountain, four trees and two benches",
        None,
        &[("fountain", 1), ("tree", 4), ("park bench", 2)],
    ),
    (
        "a backyard, 12 x 10 m, with a trampoline and a shed",
        Some([12.0, 10.0]),
        &[("trampoline", 1), ("shed", 1)],
    ),
];

const GROUP_KINDS: [RelationKind; 5] = [
    RelationKind::Around,
    RelationKind::At,
    RelationKind::Flank,
    RelationKind::Circle,
    RelationKind::Row,
];

#[test]
fn sixty_requests_are_planned_and_furnished() {
    assert!(CASES.len() >= 60, "{} cases", CASES.len());
    let start = std::time::Instant::now();
    let (mut g_ok, mut g_n, mut r_ok, mut r_n, mut named) = (0, 0, 0, 0, 0);
    let mut failures = vec![];
    for (p, room, expect) in CASES {
        let plan = match plan_prompt(p) {
            Ok(x) => x,
            Err(e) => {
                failures.push(format!("{p}: {e}"));
                continue;
            }
        };
        let s = &plan.spec;
        if let Some(n) = plan
            .notes
            .iter()
            .find(|n| n.contains("not in the knowledge base"))
        {
            failures.push(format!("{p}: {n}"));
        }
        for (cat, n) in *expect {
            named += 1;
            let got = s.objects.get(*cat).map(|o| o.number).unwrap_or(0);
            if got != *n {
                failures.push(format!(
                    "{p}: {cat} {got}, expected {n} (have {:?})",
                    s.objects.keys().collect::<Vec<_>>()
                ));
            }
        }
        if let Some([w, d]) = room {
            let r = s.room.unwrap().size;
            if (r[0] - w).abs() > 1e-9 || (r[1] - d).abs() > 1e-9 {
                failures.push(format!("{p}: room {r:?}"));
            }
        }
        let l = match layout(s, LayoutOptions::seeded(0)) {
            Ok(l) => l,
            Err(e) => {
                failures.push(format!("{p}: {e}"));
                continue;
            }
        };
        let problems = validity_problems(&l, s);
        if !problems.is_empty() {
            failures.push(format!("{p}: {problems:?}"));
        }
        let by: BTreeMap<&str, &PlacedObject> =
            l.objects.iter().map(|o| (o.id.as_str(), o)).collect();
        for r in &s.relations {
            let ok = relation_holds(by[r.subject.as_str()], r.relation, by[r.object.as_str()]);
            r_n += 1;
            r_ok += ok as usize;
            if GROUP_KINDS.contains(&r.relation) {
                g_n += 1;
                g_ok += ok as usize;
                if !ok {
                    eprintln!("{p}: {r} not met");
                }
            }
        }
    }
    let g = g_ok as f64 / g_n.max(1) as f64;
    eprintln!(
        "{} prompts, {named} named objects/counts checked, functional groups {g_ok}/{g_n} = {:.1}%, all relations {r_ok}/{r_n} = {:.1}%, {:.2} s",
        CASES.len(),
        100.0 * g,
        100.0 * r_ok as f64 / r_n.max(1) as f64,
        start.elapsed().as_secs_f64()
    );
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
    assert!(g >= 0.95, "functional groups met {g:.3}");
}
