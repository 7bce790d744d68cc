//! Lengths and areas as people write them: metres, centimetres, millimetres, feet (ft, ′, '),
//! inches (in, ″, "), "by", "x" and "×", square metres and square feet. Pure text in, metres out.
use regex::Regex;
use std::sync::OnceLock;

/// A room or object size stated in the text, with the byte span it covers.
#[derive(Debug, Clone, PartialEq)]
pub struct Dims {
    pub start: usize,
    pub end: usize,
    /// Width and depth (and height when three numbers are given), metres.
    pub values: Vec<f64>,
    /// An area in square metres instead ("20 square meters"): `values` is empty then.
    pub area: Option<f64>,
    /// No unit was given ("a bedroom 3 x 4"): the numbers were read as metres.
    pub unitless: bool,
}

const UNIT: &str = r#"(?:mm|millimet(?:er|re)s?|cm|centimet(?:er|re)s?|m|met(?:er|re)s?|ft|feet|foot|in|inch|inches|'|"|′|″)"#;

/// Whether `w` is a unit word ("m", "metres", "inch", "ft").
pub fn is_unit_word(w: &str) -> bool {
    static RE: std::sync::OnceLock<Regex> = std::sync::OnceLock::new();
    RE.get_or_init(|| re(&format!("^{UNIT}$"))).is_match(w)
}

/// Metres per unit word.
fn unit_scale(u: &str) -> Option<f64> {
    let u = u.trim();
    Some(match u {
        "mm" => 0.001,
        "cm" => 0.01,
        "m" => 1.0,
        "ft" | "feet" | "foot" | "'" | "′" => 0.3048,
        "in" | "inch" | "inches" | "\"" | "″" => 0.0254,
        _ if u.starts_with("milli") => 0.001,
        _ if u.starts_with("centi") => 0.01,
        _ if u.starts_with("met") => 1.0,
        _ => return None,
    })
}

fn re(p: &str) -> Regex {
    Regex::new(p).expect("valid regex")
}

fn dims_re() -> &'static Regex {
    static R: OnceLock<Regex> = OnceLock::new();
    R.get_or_init(|| {
        let num = r"(\d+(?:\.\d+)?)";
        let sep = r"\s*(?:x|×|by|\*)\s*";
        re(&format!(
            r"\b{num}\s*({UNIT})?{sep}{num}\s*({UNIT})?(?:{sep}{num}\s*({UNIT})?)?(?:\b|\s|$)"
        ))
    })
}

fn area_re() -> &'static Regex {
    static R: OnceLock<Regex> = OnceLock::new();
    R.get_or_init(|| {
        re(r"\b(\d+(?:\.\d+)?)\s*(?:square\s*(met(?:er|re)s?|m|feet|foot|ft)|sq\.?\s*(m|ft|feet|met(?:er|re)s?)|(m2|m²|ft2|ft²))")
    })
}

/// Every "W x D [x H] unit" and area phrase in `t` (lower case), in text order. A number
/// without its own unit takes the unit of the others; at least one unit must be given.
pub fn find_dims(t: &str) -> Vec<Dims> {
    let mut out = vec![];
    for c in dims_re().captures_iter(t) {
        let m = c.get(0).expect("whole match");
        let nums: Vec<Option<f64>> = [1, 3, 5]
            .iter()
            .map(|&k| c.get(k).and_then(|v| v.as_str().parse().ok()))
            .collect();
        let units: Vec<Option<f64>> = [2, 4, 6]
            .iter()
            .map(|&k| c.get(k).and_then(|u| unit_scale(u.as_str())))
            .collect();
        // No unit at all: metres when every number is a plausible length in metres.
        let unitless = units.iter().all(Option::is_none);
        let plausible = nums.iter().flatten().count() >= 2
            && nums.iter().flatten().all(|&n| (1.0..=60.0).contains(&n));
        let default = match units.iter().rev().flatten().next().copied() {
            Some(u) => u,
            None if plausible => 1.0,
            None => continue,
        };
        let values: Vec<f64> = nums
            .iter()
            .zip(&units)
            .filter_map(|(n, u)| n.map(|n| n * u.unwrap_or(default)))
            .collect();
        out.push(Dims {
            start: m.start(),
            end: m.end(),
            values,
            area: None,
            unitless,
        });
    }
    for c in area_re().captures_iter(t) {
        let m = c.get(0).expect("whole match");
        if out.iter().any(|d| d.start < m.end() && m.start() < d.end) {
            continue;
        }
        let Ok(a) = c[1].parse::<f64>() else { continue };
        let unit = (2..=4)
            .find_map(|k| c.get(k))
            .map(|u| u.as_str())
            .unwrap_or("m");
        let feet = unit.contains('f');
        out.push(Dims {
            start: m.start(),
            end: m.end(),
            values: vec![],
            area: Some(if feet { a * 0.3048 * 0.3048 } else { a }),
            unitless: false,
        });
    }
    out.sort_by_key(|d| d.start);
    out
}

/// One length with its unit ("2.4 m", "90cm", "7 ft"), in metres, with its span.
pub fn find_lengths(t: &str) -> Vec<(usize, usize, f64)> {
    static R: OnceLock<Regex> = OnceLock::new();
    let r = R.get_or_init(|| re(&format!(r"\b(\d+(?:\.\d+)?)\s*({UNIT})(?:\b|\s|$)")));
    r.captures_iter(t)
        .filter_map(|c| {
            let m = c.get(0)?;
            let v: f64 = c[1].parse().ok()?;
            Some((m.start(), m.end(), v * unit_scale(&c[2])?))
        })
        .collect()
}

/// Rounds to centimetres.
pub fn cm(v: f64) -> f64 {
    (v * 100.0).round() / 100.0
}

/// The room's floor from a stated area: aspect 5:4, decimetres.
pub fn floor_from_area(a: f64) -> [f64; 2] {
    let w = (a * 1.25).sqrt();
    let r = |v: f64| (v * 10.0).round() / 10.0;
    [r(w), r(a / w)]
}
