//! Tests of the guidance rules (a child module of `guidance`).
use super::super::schedule::{Schedule, SchedulerConfig};
use super::*;
use rand::SeedableRng;

/// ε = k(cond) x + t / 1000: simple enough to compute the chain by hand. Counts calls.
struct Fake {
    calls: Vec<(u32, usize)>,
}
fn k(c: Cond) -> f32 {
    match c {
        Cond::Positive => 0.5,
        Cond::Negative => 0.2,
        Cond::Null => 0.1,
        Cond::Edit => 0.9,
    }
}
impl NoisePredictor for Fake {
    fn predict(&mut self, x: &[f32], t: u32, conds: &[Cond]) -> Result<Vec<Vec<f32>>, String> {
        self.calls.push((t, conds.len()));
        Ok(conds
            .iter()
            .map(|c| x.iter().map(|v| k(*c) * v + t as f32 / 1000.0).collect())
            .collect())
    }
}

#[test]
fn schedules_follow_their_rules() {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
    assert_eq!(t_end(&OBJECT_MTS, 0), 850);
    assert_eq!(t_end(&OBJECT_MTS, 750), 625);
    assert_eq!(t_end(&OBJECT_MTS, 5000), 400);
    for step in [0u32, 300, 900, 1500] {
        for _ in 0..50 {
            let ts = code_schedule(&OBJECT_MTS, step, &mut rng);
            assert!(!ts.is_empty() && ts.len() <= MAX_POINTS);
            assert!((175..225).contains(&ts[0]));
            for w in ts.windows(2) {
                assert!((175..225).contains(&(w[1] - w[0])));
                assert!(w[1] < t_end(&OBJECT_MTS, step));
            }
            let p = paper_schedule(&OBJECT_MTS, step, 4, &mut rng);
            let end = t_end(&OBJECT_MTS, step);
            assert_eq!(p.len(), 4);
            for (i, t) in p.iter().enumerate() {
                let lo = 1 + (end - 1) * i as u32 / 4;
                let hi = 1 + (end - 1) * (i as u32 + 1) / 4;
                assert!(*t >= lo && *t < hi.max(lo + 1), "{t} not in [{lo}, {hi})");
            }
        }
    }
    assert_eq!(dreamtime_t(0, 100, 20, 980), 980);
    assert_eq!(dreamtime_t(100, 100, 20, 980), 20);
}

#[test]
fn mts_gradient_matches_the_chain_computed_by_hand() {
    let sched = Schedule::new(SchedulerConfig::sd21_base()).unwrap();
    let z0: Vec<f32> = (0..16).map(|i| (i as f32 * 0.3).sin()).collect();
    let eps: Vec<f32> = (0..16).map(|i| (i as f32 * 0.7).cos()).collect();
    let ts = [200u32, 410, 600];
    let s = MtsSettings::default();
    let mut fake = Fake { calls: vec![] };
    let g = mts_gradient(&mut fake, &sched, &z0, &eps, &ts, &s).unwrap();
    // One batched call per chain point: the start (t = 1) drives only the first inversion step,
    // so it asks for the null prompt alone; the three sampled points ask for all three.
    assert_eq!(fake.calls, vec![(1, 1), (200, 3), (410, 3), (600, 3)]);
    // By hand, in f64.
    let ab = |t: u32| sched.alpha_bar(t as i64);
    let mut x: Vec<f64> = z0
        .iter()
        .zip(&eps)
        .map(|(a, b)| ab(1).sqrt() * *a as f64 + (1.0 - ab(1)).sqrt() * *b as f64)
        .collect();
    let mut want = vec![0.0f64; 16];
    let mut want_paper = vec![0.0f64; 16];
    let mut cur = 1u32;
    for &t in &ts {
        // invert with the null prediction
        for xi in x.iter_mut() {
            let e = 0.1 * *xi + cur as f64 / 1000.0;
            let x0 = (*xi - (1.0 - ab(cur)).sqrt() * e) / ab(cur).sqrt();
            *xi = ab(t).sqrt() * x0 + (1.0 - ab(t)).sqrt() * e;
        }
        cur = t;
        for (k, xi) in x.iter().enumerate() {
            let c = t as f64 / 1000.0;
            let (pos, neg, null) = (0.5 * xi + c, 0.2 * xi + c, 0.1 * xi + c);
            let e_cfg = neg + 7.5 * (pos - neg);
            want[k] += 0.1 * weight(ab(t)) * (e_cfg - null) / 3.0;
            want_paper[k] += 0.1 * weight(ab(t)) * (pos - null);
        }
    }
    for (a, b) in g.iter().zip(&want) {
        assert!(
            (*a as f64 - b).abs() < 1e-4 * b.abs().max(1.0),
            "{a} vs {b}"
        );
    }
    // The paper's rule differs: no CFG, no averaging.
    let sp = MtsSettings {
        rule: MtsRule::Paper,
        ..s
    };
    let mut fake = Fake { calls: vec![] };
    let gp = mts_gradient(&mut fake, &sched, &z0, &eps, &ts, &sp).unwrap();
    assert!(gp.iter().zip(&g).any(|(a, b)| (a - b).abs() > 1e-3));
    for (a, b) in gp.iter().zip(&want_paper) {
        assert!(
            (*a as f64 - b).abs() < 1e-4 * b.abs().max(1.0),
            "paper rule: {a} vs {b}"
        );
    }
    // The paper's rule has no CFG, so it never asks for the negative prompt.
    assert_eq!(fake.calls, vec![(1, 1), (200, 2), (410, 2), (600, 2)]);
}

/// Predicts the true noise for every condition: the inversion chain then stays on
/// add_noise(z0, eps, t), x̂₀ is z0 exactly and every guidance difference vanishes.
struct Oracle(Vec<f32>);
impl NoisePredictor for Oracle {
    fn predict(&mut self, _: &[f32], _: u32, conds: &[Cond]) -> Result<Vec<Vec<f32>>, String> {
        Ok(conds.iter().map(|_| self.0.clone()).collect())
    }
}

#[test]
fn a_perfect_predictor_recovers_the_latent() {
    let sched = Schedule::new(SchedulerConfig::sd21_base()).unwrap();
    let z0: Vec<f32> = (0..32).map(|i| (i as f32 * 0.21).sin()).collect();
    let eps: Vec<f32> = (0..32).map(|i| (i as f32 * 0.9).cos()).collect();
    let s = MtsSettings::default();
    let gt = pseudo_gt(&mut Oracle(eps.clone()), &sched, &z0, &eps, &[130, 300], &s).unwrap();
    for (a, b) in gt.iter().zip(&z0) {
        assert!((a - b).abs() < 1e-4, "{a} vs {b}");
    }
    let g = mts_gradient(&mut Oracle(eps.clone()), &sched, &z0, &eps, &[200, 400], &s).unwrap();
    assert!(g.iter().all(|v| v.abs() < 1e-6));
    let sds = sds_gradient(&mut Oracle(eps.clone()), &sched, &z0, &eps, 500, &s).unwrap();
    assert!(sds.iter().all(|v| v.abs() < 1e-5));
    // A predictor returning the wrong number of outputs is an error, not a panic.
    struct Short;
    impl NoisePredictor for Short {
        fn predict(&mut self, x: &[f32], _: u32, _: &[Cond]) -> Result<Vec<Vec<f32>>, String> {
            Ok(vec![x.to_vec()])
        }
    }
    assert!(mts_gradient(&mut Short, &sched, &z0, &eps, &[200], &s).is_err());
}

#[test]
fn pseudo_gt_edit_sds_and_ism_run_and_differ() {
    let sched = Schedule::new(SchedulerConfig::sd21_base()).unwrap();
    let z0 = vec![0.3f32; 8];
    let eps = vec![-0.4f32; 8];
    let s = MtsSettings::default();
    let mut fake = Fake { calls: vec![] };
    let gt = pseudo_gt(&mut fake, &sched, &z0, &eps, &[120, 260], &s).unwrap();
    assert!(gt.iter().all(|v| v.is_finite()));
    // x̂₀ at the first sampled point needs its CFG pair only; the start point its null prompt.
    assert_eq!(fake.calls, vec![(1, 1), (120, 2)]);
    let e = edit_gradient(&mut Fake { calls: vec![] }, &sched, &z0, &eps, &[300], &s).unwrap();
    assert!(e.iter().all(|v| *v > 0.0), "edit prompt pulls away from y");
    let sds = sds_gradient(&mut Fake { calls: vec![] }, &sched, &z0, &eps, 500, &s).unwrap();
    let mut f = Fake { calls: vec![] };
    let ism = ism_gradient(&mut f, &sched, &z0, &eps, 400, 480, 200, 5, &s).unwrap();
    assert_eq!(
        f.calls.iter().map(|c| c.0).collect::<Vec<_>>(),
        vec![1, 201, 400, 480]
    );
    assert!(sds.iter().zip(&ism).any(|(a, b)| (a - b).abs() > 1e-4));
}

/// Counts the batched calls over views; predicts as [`Fake`] with a slope per view.
struct Views(Vec<(u32, usize, usize)>);
impl ViewsPredictor for Views {
    fn predict_views(
        &mut self,
        xs: &[&[f32]],
        t: u32,
        conds: &[Cond],
    ) -> Result<Vec<Vec<Vec<f32>>>, String> {
        self.0.push((t, xs.len(), conds.len()));
        Ok(xs
            .iter()
            .enumerate()
            .map(|(v, x)| PerViewFake(v).predict(x, t, conds).unwrap())
            .collect())
    }
}
struct PerViewFake(usize);
impl NoisePredictor for PerViewFake {
    fn predict(&mut self, x: &[f32], t: u32, conds: &[Cond]) -> Result<Vec<Vec<f32>>, String> {
        let s = 1.0 + 0.3 * self.0 as f32;
        Ok(conds
            .iter()
            .map(|c| {
                x.iter()
                    .map(|v| s * k(*c) * v + t as f32 / 1000.0)
                    .collect()
            })
            .collect())
    }
}

/// Every rule over a batch of views gives each view what it gives that view alone, with one
/// predictor call per chain point for all the views.
#[test]
fn rules_over_views_equal_the_rules_view_by_view() {
    let sched = Schedule::new(SchedulerConfig::sd21_base()).unwrap();
    let z: Vec<Vec<f32>> = (0..3)
        .map(|v| (0..16).map(|i| ((i + 5 * v) as f32 * 0.3).sin()).collect())
        .collect();
    let e: Vec<Vec<f32>> = (0..3)
        .map(|v| (0..16).map(|i| ((i * 3 + v) as f32 * 0.7).cos()).collect())
        .collect();
    let zs: Vec<&[f32]> = z.iter().map(Vec::as_slice).collect();
    let es: Vec<&[f32]> = e.iter().map(Vec::as_slice).collect();
    let s = MtsSettings::default();
    let ts = [190u32, 380, 600];
    type Many<'a> = Box<dyn Fn(&mut Views) -> Vec<Vec<f32>> + 'a>;
    type One<'a> = Box<dyn Fn(&mut PerViewFake, usize) -> Vec<f32> + 'a>;
    let cases: Vec<(&str, Many, One, usize)> = vec![
        (
            "mts",
            Box::new(|p| mts_gradients(p, &sched, &zs, &es, &ts, &s).unwrap()),
            Box::new(|p, v| mts_gradient(p, &sched, zs[v], es[v], &ts, &s).unwrap()),
            4,
        ),
        (
            "pseudo-gt",
            Box::new(|p| pseudo_gts(p, &sched, &zs, &es, &ts, &s).unwrap()),
            Box::new(|p, v| pseudo_gt(p, &sched, zs[v], es[v], &ts, &s).unwrap()),
            2,
        ),
        (
            "edit",
            Box::new(|p| edit_gradients(p, &sched, &zs, &es, &ts, &s).unwrap()),
            Box::new(|p, v| edit_gradient(p, &sched, zs[v], es[v], &ts, &s).unwrap()),
            4,
        ),
        (
            "sds",
            Box::new(|p| sds_gradients(p, &sched, &zs, &es, 500, &s).unwrap()),
            Box::new(|p, v| sds_gradient(p, &sched, zs[v], es[v], 500, &s).unwrap()),
            1,
        ),
        (
            "ism",
            Box::new(|p| ism_gradients(p, &sched, &zs, &es, 400, 480, 200, 5, &s).unwrap()),
            Box::new(|p, v| ism_gradient(p, &sched, zs[v], es[v], 400, 480, 200, 5, &s).unwrap()),
            4,
        ),
    ];
    for (name, many, one, points) in cases {
        let mut rec = Views(vec![]);
        let all = many(&mut rec);
        assert_eq!(rec.0.len(), points, "{name}: one call per chain point");
        assert!(
            rec.0.iter().all(|c| c.1 == 3),
            "{name}: every view in each call"
        );
        for (v, got) in all.iter().enumerate() {
            assert_eq!(*got, one(&mut PerViewFake(v), v), "{name} view {v}");
        }
        assert_ne!(all[0], all[1], "{name}: the views differ");
    }
}

#[test]
fn view_prompts_as_the_code_builds_them() {
    let (p, n) = view_prompts("a chair", "ugly", 10.0, 0.0);
    assert!(p.starts_with("a chair, front view, 4k"));
    assert_eq!(n, "ugly, side view, back view, overhead view");
    assert!(view_prompts("a chair", "ugly", 90.0, 0.0)
        .0
        .contains("side view"));
    assert!(view_prompts("a chair", "ugly", -170.0, 0.0)
        .0
        .contains("back view"));
    assert!(view_prompts("a chair", "ugly", 0.0, -70.0)
        .0
        .contains("overhead view"));
}
