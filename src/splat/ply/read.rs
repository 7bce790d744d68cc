//! The PLY reader: binary little- and big-endian and ASCII, any property types. Properties the
//! splat does not use are skipped whatever their type (colours as `uchar red green blue`, normals,
//! lists); splat properties may be `float` or `double` (converted to 32-bit). Elements before
//! `vertex` are skipped, elements after it are not read.
//!
//! Nothing is allocated by a count read from the header: rows are read one at a time and the
//! cloud grows with the data actually present, so a header claiming 10^12 vertices on a short
//! file ends in a "truncated" error, not an allocation. Every loop consumes input or stops.
use super::super::cloud::{sh_coeffs, Gaussians};
use super::header::{header, Element, Encoding, Kind, Prop, Ty};
use std::io::{BufRead, Read};

/// Cloud rows reserved up front at most, whatever the header says.
const MAX_RESERVE: usize = 1 << 16;

/// What to do with Gaussians whose values are not finite (NaN, ±Inf, or a double too large for
/// a float) or whose rotation quaternion is zero.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Invalid {
    /// Refuse the file, with the count and the first such vertex.
    #[default]
    Refuse,
    /// Leave them out and report how many.
    Drop,
}

/// A cloud read from a PLY, and how many invalid Gaussians were dropped.
#[derive(Debug, Clone, PartialEq)]
pub struct PlyRead {
    pub gaussians: Gaussians,
    pub dropped: usize,
    /// The per-Gaussian labels, when the file has an `instance_id` property (`semantic_id`
    /// reads as 0 where absent); one per kept Gaussian.
    pub labels: Option<Labels>,
}

/// Per-Gaussian labels (ARCHITECTURE.md, "Labels"): the instance (0 = walls, floor, ground)
/// and the semantic class, as `labels.json` names them.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Labels {
    pub instance: Vec<u16>,
    pub semantic: Vec<u8>,
}

impl Labels {
    /// The labels of the Gaussians `keep` says to keep, in order.
    pub fn filter(&self, keep: &[bool]) -> Labels {
        let pick = |i: &usize| keep.get(*i).copied().unwrap_or(false);
        Labels {
            instance: (0..self.instance.len())
                .filter(pick)
                .map(|i| self.instance[i])
                .collect(),
            semantic: (0..self.semantic.len())
                .filter(pick)
                .map(|i| self.semantic[i])
                .collect(),
        }
    }
}

/// Reads values row by row in either encoding.
struct Rows<'a, R: BufRead> {
    r: &'a mut R,
    encoding: Encoding,
    buf: Vec<u8>,
    token: Vec<u8>,
}

/// The input ended inside a row.
struct Eof;

impl<R: BufRead> Rows<'_, R> {
    /// The next value of type `ty`.
    fn value(&mut self, ty: Ty) -> Result<Result<f64, String>, Eof> {
        match self.encoding {
            Encoding::Ascii => {
                self.next_token()?;
                let s = String::from_utf8_lossy(&self.token);
                Ok(s.parse::<f64>()
                    .map_err(|_| format!("`{s}` is not a number")))
            }
            Encoding::Little | Encoding::Big => {
                let n = ty.size();
                self.buf.resize(n, 0);
                self.r.read_exact(&mut self.buf[..n]).map_err(|_| Eof)?;
                Ok(Ok(ty.decode(&self.buf, self.encoding == Encoding::Big)))
            }
        }
    }

    /// Reads one whitespace-separated token (at most 64 bytes) into `self.token`.
    fn next_token(&mut self) -> Result<(), Eof> {
        self.token.clear();
        loop {
            let (used, done) = {
                let b = self.r.fill_buf().map_err(|_| Eof)?;
                if b.is_empty() {
                    if self.token.is_empty() {
                        return Err(Eof);
                    }
                    return Ok(());
                }
                let mut used = 0;
                let mut done = false;
                for &c in b {
                    used += 1;
                    if c.is_ascii_whitespace() {
                        if !self.token.is_empty() {
                            done = true;
                            break;
                        }
                    } else if self.token.len() < 64 {
                        self.token.push(c);
                    }
                }
                (used, done)
            };
            self.r.consume(used);
            if done {
                return Ok(());
            }
        }
    }

    /// Reads one row of `props`, storing scalar values in `out` (lists are read and dropped).
    fn row(&mut self, props: &[Prop], out: &mut [f64]) -> Result<Result<(), String>, Eof> {
        for (i, p) in props.iter().enumerate() {
            match p.kind {
                Kind::Scalar(t) => match self.value(t)? {
                    Ok(v) => out[i] = v,
                    Err(e) => return Ok(Err(format!("property `{}`: {e}", p.name))),
                },
                Kind::List(c, t) => {
                    let n = match self.value(c)? {
                        Ok(v) if v >= 0.0 && v.fract() == 0.0 => v as u64,
                        Ok(v) => {
                            return Ok(Err(format!("list `{}` has length {v}", p.name)));
                        }
                        Err(e) => return Ok(Err(format!("list `{}`: {e}", p.name))),
                    };
                    // Each item consumes input, so a huge length ends at the end of the file.
                    for _ in 0..n {
                        if let Err(e) = self.value(t)? {
                            return Ok(Err(format!("list `{}`: {e}", p.name)));
                        }
                    }
                }
            }
        }
        Ok(Ok(()))
    }

    /// Skips every row of an element that comes before `vertex`.
    fn skip(&mut self, e: &Element) -> Result<(), String> {
        if e.props.is_empty() {
            return Ok(());
        }
        let truncated = || format!("truncated inside element `{}`", e.name);
        let scalar_bytes: Option<u64> = e
            .props
            .iter()
            .map(|p| match p.kind {
                Kind::Scalar(t) => Some(t.size() as u64),
                Kind::List(..) => None,
            })
            .sum();
        if let (Some(stride), false) = (scalar_bytes, self.encoding == Encoding::Ascii) {
            let want = e.count.saturating_mul(stride);
            let got = std::io::copy(&mut (&mut *self.r).take(want), &mut std::io::sink())
                .map_err(|e| e.to_string())?;
            return if got == want {
                Ok(())
            } else {
                Err(truncated())
            };
        }
        let mut scratch = vec![0.0; e.props.len()];
        for _ in 0..e.count {
            match self.row(&e.props, &mut scratch) {
                Err(Eof) => return Err(truncated()),
                Ok(Err(m)) => return Err(m),
                Ok(Ok(())) => {}
            }
        }
        Ok(())
    }
}

/// Reads a splat PLY from `r`; errors are one line without the file name.
pub fn parse_ply<R: BufRead>(r: &mut R, invalid: Invalid) -> Result<PlyRead, String> {
    let (encoding, elements) = header(r)?;
    let vi = elements
        .iter()
        .position(|e| e.name == "vertex")
        .ok_or("no `vertex` element")?;
    let vertex = &elements[vi];
    let props = &vertex.props;
    let idx = |name: &str| props.iter().position(|p| p.name == name);
    let need = |name: &str| -> Result<usize, String> {
        let i = idx(name).ok_or_else(|| format!("missing property `{name}`"))?;
        match props[i].kind {
            Kind::Scalar(t) if t.is_float() => Ok(i),
            _ => Err(format!(
                "property `{name}` is not `float` or `double`; splat properties are floating point"
            )),
        }
    };
    let mut rest: Vec<(usize, usize)> = props
        .iter()
        .enumerate()
        .filter_map(|(i, p)| {
            p.name
                .strip_prefix("f_rest_")
                .and_then(|s| s.parse::<usize>().ok())
                .map(|k| (k, i))
        })
        .collect();
    rest.sort();
    for (expect, (k, _)) in rest.iter().enumerate() {
        if *k != expect {
            return Err(format!(
                "f_rest_ properties are not numbered 0..{}",
                rest.len()
            ));
        }
    }
    let degree = match rest.len() {
        0 => 0,
        9 => 1,
        24 => 2,
        45 => 3,
        k => {
            return Err(format!(
                "{k} f_rest properties: expected 0, 9, 24 or 45 (SH degree 0 to 3)"
            ))
        }
    };
    let rest: Vec<usize> = rest
        .into_iter()
        .map(|(k, _)| need(&format!("f_rest_{k}")))
        .collect::<Result<_, _>>()?;
    let pos = [need("x")?, need("y")?, need("z")?];
    let dc = [need("f_dc_0")?, need("f_dc_1")?, need("f_dc_2")?];
    let op = need("opacity")?;
    let sc = [need("scale_0")?, need("scale_1")?, need("scale_2")?];
    // Labels are integers of any type (splat-transform rewrites them as `uint`), or floats.
    let label_idx = |name: &str| idx(name).filter(|&i| matches!(props[i].kind, Kind::Scalar(_)));
    let (inst_at, sem_at) = (label_idx("instance_id"), label_idx("semantic_id"));
    let mut labels = inst_at.map(|_| Labels::default());
    let rot = [
        need("rot_0")?,
        need("rot_1")?,
        need("rot_2")?,
        need("rot_3")?,
    ];

    let mut rows = Rows {
        r,
        encoding,
        buf: Vec::new(),
        token: Vec::new(),
    };
    for e in &elements[..vi] {
        rows.skip(e)?;
    }
    let n = vertex.count;
    let k = sh_coeffs(degree);
    let per = k - 1;
    let reserve = usize::try_from(n).unwrap_or(usize::MAX).min(MAX_RESERVE);
    let mut g = Gaussians {
        sh_degree: degree,
        ..Default::default()
    };
    g.means.reserve(reserve);
    g.scales.reserve(reserve);
    g.rotations.reserve(reserve);
    g.opacities.reserve(reserve);
    g.sh.reserve(reserve * k * 3);
    let mut vals = vec![0.0f64; props.len()];
    let mut bad = 0usize;
    let mut first_bad: Option<(u64, String)> = None;
    for v in 0..n {
        match rows.row(props, &mut vals) {
            Err(Eof) => {
                return Err(format!(
                    "truncated: the header says {n} vertices, the data ends in vertex {v}"
                ))
            }
            Ok(Err(m)) => return Err(format!("vertex {v}: {m}")),
            Ok(Ok(())) => {}
        }
        let f = |i: usize| vals[i] as f32;
        let used = pos
            .iter()
            .chain(&dc)
            .chain(&rest)
            .chain(&sc)
            .chain(&rot)
            .chain(std::iter::once(&op));
        let mut why = used
            .map(|&i| (i, f(i)))
            .find(|(_, x)| !x.is_finite())
            .map(|(i, x)| format!("`{}` = {}", props[i].name, shown(vals[i], x)));
        if why.is_none() && rot.iter().all(|&i| f(i) == 0.0) {
            why = Some("its rotation quaternion is zero".into());
        }
        if let Some(why) = why {
            bad += 1;
            first_bad.get_or_insert((v, why));
            continue;
        }
        g.means.push(pos.map(f));
        g.scales.push(sc.map(f));
        g.rotations.push(rot.map(f));
        g.opacities.push(f(op));
        if let (Some(l), Some(i)) = (labels.as_mut(), inst_at) {
            l.instance
                .push(vals[i].clamp(0.0, f64::from(u16::MAX)) as u16);
            l.semantic
                .push(sem_at.map_or(0, |s| vals[s].clamp(0.0, 255.0) as u8));
        }
        for c in 0..k {
            for ch in 0..3 {
                g.sh.push(if c == 0 {
                    f(dc[ch])
                } else {
                    f(rest[ch * per + c - 1])
                });
            }
        }
    }
    if let (Some((v, why)), Invalid::Refuse) = (first_bad, invalid) {
        return Err(format!(
            "{bad} of {n} Gaussians are not finite or have a zero rotation (first: vertex {v}, \
             {why}); --drop-invalid leaves them out"
        ));
    }
    Ok(PlyRead {
        gaussians: g,
        dropped: bad,
        labels,
    })
}

/// A value as read, and as a float when the conversion overflowed.
fn shown(read: f64, as_f32: f32) -> String {
    if read.is_finite() {
        format!("{read:e} (beyond a 32-bit float, {as_f32})")
    } else {
        format!("{read}")
    }
}
