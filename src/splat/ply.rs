//! INRIA 3DGS splat PLY: binary little-endian, one `vertex` element of float properties
//! `x y z nx ny nz f_dc_0..2 f_rest_* opacity scale_0..2 rot_0..3`; `f_rest` is channel-major.
//! Reads SH degree 0 to 3 in any property order; writes the standard order.
use super::cloud::{sh_coeffs, Gaussians};
use std::io::{BufRead, BufReader, Read};
use std::path::Path;

/// A PLY that cannot be read, with the file and what is wrong.
#[derive(Debug, thiserror::Error)]
#[error("{path}: {msg}")]
pub struct PlyError {
    pub path: String,
    pub msg: String,
}

/// Reads a splat PLY.
pub fn read_ply(path: &Path) -> Result<Gaussians, PlyError> {
    let err = |msg: String| PlyError {
        path: path.display().to_string(),
        msg,
    };
    let file = std::fs::File::open(path).map_err(|e| err(e.to_string()))?;
    let mut r = BufReader::new(file);
    let mut line = String::new();
    let mut props: Vec<(String, usize)> = Vec::new(); // name, byte size
    let mut count: Option<usize> = None;
    let mut in_vertex = false;
    let mut first = true;
    loop {
        line.clear();
        let n = r
            .read_line(&mut line)
            .map_err(|e| err(format!("header: {e}")))?;
        if n == 0 {
            return Err(err("header ends before `end_header`".into()));
        }
        let l = line.trim();
        if first {
            if l != "ply" {
                return Err(err("not a PLY file (no `ply` magic)".into()));
            }
            first = false;
            continue;
        }
        let parts: Vec<&str> = l.split_whitespace().collect();
        match parts.as_slice() {
            ["format", fmt, _] if *fmt != "binary_little_endian" => {
                return Err(err(format!(
                    "format `{fmt}` is not supported; splat PLYs are binary_little_endian"
                )));
            }
            ["element", name, n] => {
                in_vertex = *name == "vertex";
                if in_vertex {
                    count = Some(
                        n.parse()
                            .map_err(|_| err(format!("bad vertex count `{n}`")))?,
                    );
                } else if count.is_none() {
                    return Err(err(format!(
                        "element `{name}` before `vertex` is not supported"
                    )));
                }
            }
            ["property", ty, name] if in_vertex => {
                let size = match *ty {
                    "float" | "float32" => 4,
                    "double" | "float64" => 8,
                    "uchar" | "uint8" | "char" | "int8" => 1,
                    "ushort" | "short" | "uint16" | "int16" => 2,
                    "uint" | "int" | "uint32" | "int32" => 4,
                    _ => return Err(err(format!("property `{name}` has unknown type `{ty}`"))),
                };
                if size != 4 || !(ty.starts_with("float")) {
                    return Err(err(format!(
                        "property `{name}` is `{ty}`; splat properties must be float"
                    )));
                }
                props.push((name.to_string(), size));
            }
            ["property", "list", ..] if in_vertex => {
                return Err(err("list properties in `vertex` are not supported".into()))
            }
            ["end_header"] => break,
            _ => {}
        }
    }
    let n = count.ok_or_else(|| err("no `vertex` element".into()))?;
    let idx = |name: &str| props.iter().position(|p| p.0 == name);
    let need = |name: &str| idx(name).ok_or_else(|| err(format!("missing property `{name}`")));
    let rest: Vec<usize> = {
        let mut v: Vec<(usize, usize)> = props
            .iter()
            .enumerate()
            .filter_map(|(i, p)| {
                p.0.strip_prefix("f_rest_")
                    .and_then(|s| s.parse::<usize>().ok())
                    .map(|k| (k, i))
            })
            .collect();
        v.sort();
        for (expect, (k, _)) in v.iter().enumerate() {
            if *k != expect {
                return Err(err(format!(
                    "f_rest_ properties are not numbered 0..{}",
                    v.len()
                )));
            }
        }
        v.into_iter().map(|x| x.1).collect()
    };
    let degree = match rest.len() {
        0 => 0,
        9 => 1,
        24 => 2,
        45 => 3,
        k => {
            return Err(err(format!(
                "{k} f_rest properties: expected 0, 9, 24 or 45 (SH degree 0 to 3)"
            )))
        }
    };
    let pos = [need("x")?, need("y")?, need("z")?];
    let dc = [need("f_dc_0")?, need("f_dc_1")?, need("f_dc_2")?];
    let op = need("opacity")?;
    let sc = [need("scale_0")?, need("scale_1")?, need("scale_2")?];
    let rot = [
        need("rot_0")?,
        need("rot_1")?,
        need("rot_2")?,
        need("rot_3")?,
    ];
    let stride = props.len() * 4;
    let total = n
        .checked_mul(stride)
        .ok_or_else(|| err("vertex count overflows".into()))?;
    let mut data = Vec::new();
    r.take(total as u64)
        .read_to_end(&mut data)
        .map_err(|e| err(format!("data: {e}")))?;
    if data.len() < total {
        return Err(err(format!(
            "truncated: {} vertices need {total} bytes of data, the file has {}",
            n,
            data.len()
        )));
    }
    let k = sh_coeffs(degree);
    let per = k - 1;
    let mut g = Gaussians {
        sh_degree: degree,
        ..Default::default()
    };
    g.means.reserve(n);
    g.sh.reserve(n * k * 3);
    for v in 0..n {
        let row = &data[v * stride..(v + 1) * stride];
        let f = |i: usize| {
            f32::from_le_bytes([row[4 * i], row[4 * i + 1], row[4 * i + 2], row[4 * i + 3]])
        };
        g.means.push(pos.map(f));
        g.scales.push(sc.map(f));
        g.rotations.push(rot.map(f));
        g.opacities.push(f(op));
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
    Ok(g)
}

/// Writes a splat PLY (through a temporary file, so a crash never leaves half a file).
pub fn write_ply(path: &Path, g: &Gaussians) -> std::io::Result<()> {
    g.check().map_err(std::io::Error::other)?;
    let k = g.coeffs();
    let per = k - 1;
    let mut header = String::from("ply\nformat binary_little_endian 1.0\n");
    header += &format!("element vertex {}\n", g.len());
    let mut names: Vec<String> = [
        "x", "y", "z", "nx", "ny", "nz", "f_dc_0", "f_dc_1", "f_dc_2",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    names.extend((0..3 * per).map(|i| format!("f_rest_{i}")));
    names.push("opacity".into());
    names.extend((0..3).map(|i| format!("scale_{i}")));
    names.extend((0..4).map(|i| format!("rot_{i}")));
    for n in &names {
        header += &format!("property float {n}\n");
    }
    header += "end_header\n";
    let mut out = header.into_bytes();
    out.reserve(g.len() * names.len() * 4);
    for i in 0..g.len() {
        let mut row: Vec<f32> = Vec::with_capacity(names.len());
        row.extend(g.means[i]);
        row.extend([0.0; 3]);
        row.extend((0..3).map(|ch| g.sh[i * k * 3 + ch]));
        for ch in 0..3 {
            for c in 1..k {
                row.push(g.sh[(i * k + c) * 3 + ch]);
            }
        }
        row.push(g.opacities[i]);
        row.extend(g.scales[i]);
        row.extend(g.rotations[i]);
        for v in row {
            out.extend(v.to_le_bytes());
        }
    }
    crate::util::write_atomic(path, &out)
}
