//! The PLY header: format, elements and their properties (scalar or list, any PLY type).
use std::io::{BufRead, Read};

/// The most header bytes read before giving up (INRIA headers are about 1.5 KB).
const MAX_HEADER: u64 = 1 << 20;

#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Ty {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl Ty {
    fn parse(s: &str) -> Option<Ty> {
        Some(match s {
            "char" | "int8" => Ty::I8,
            "uchar" | "uint8" => Ty::U8,
            "short" | "int16" => Ty::I16,
            "ushort" | "uint16" => Ty::U16,
            "int" | "int32" => Ty::I32,
            "uint" | "uint32" => Ty::U32,
            "float" | "float32" => Ty::F32,
            "double" | "float64" => Ty::F64,
            _ => return None,
        })
    }

    pub fn size(self) -> usize {
        match self {
            Ty::I8 | Ty::U8 => 1,
            Ty::I16 | Ty::U16 => 2,
            Ty::I32 | Ty::U32 | Ty::F32 => 4,
            Ty::F64 => 8,
        }
    }

    pub fn is_float(self) -> bool {
        matches!(self, Ty::F32 | Ty::F64)
    }

    /// Decodes one value of this type from `b` (exactly `size()` bytes).
    pub fn decode(self, b: &[u8], big: bool) -> f64 {
        macro_rules! num {
            ($t:ty, $n:expr) => {{
                let mut a = [0u8; $n];
                a.copy_from_slice(&b[..$n]);
                if big {
                    <$t>::from_be_bytes(a) as f64
                } else {
                    <$t>::from_le_bytes(a) as f64
                }
            }};
        }
        match self {
            Ty::I8 => num!(i8, 1),
            Ty::U8 => num!(u8, 1),
            Ty::I16 => num!(i16, 2),
            Ty::U16 => num!(u16, 2),
            Ty::I32 => num!(i32, 4),
            Ty::U32 => num!(u32, 4),
            Ty::F32 => num!(f32, 4),
            Ty::F64 => num!(f64, 8),
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Encoding {
    Ascii,
    Little,
    Big,
}

#[derive(Debug)]
pub(super) enum Kind {
    Scalar(Ty),
    /// A list: the type of its length, then of its items.
    List(Ty, Ty),
}

#[derive(Debug)]
pub(super) struct Prop {
    pub name: String,
    pub kind: Kind,
}

#[derive(Debug)]
pub(super) struct Element {
    pub name: String,
    pub count: u64,
    pub props: Vec<Prop>,
}

/// Reads the header, returning the encoding and the elements.
pub(super) fn header<R: BufRead>(r: &mut R) -> Result<(Encoding, Vec<Element>), String> {
    let mut limited = r.take(MAX_HEADER);
    let mut line = Vec::new();
    let mut encoding = None;
    let mut elements: Vec<Element> = Vec::new();
    for number in 1.. {
        line.clear();
        let n = limited
            .read_until(b'\n', &mut line)
            .map_err(|e| format!("header: {e}"))?;
        if n == 0 {
            return Err(if number == 1 {
                "empty file; expected a splat PLY".into()
            } else {
                "header ends before `end_header`".into()
            });
        }
        let text = String::from_utf8_lossy(&line);
        let l = text.trim();
        if number > 1 && !line.ends_with(b"\n") && l != "end_header" {
            return Err("header ends before `end_header`".into());
        }
        if number == 1 {
            if l != "ply" {
                // Enough of the file to say what it is.
                let mut head = line.clone();
                let _ = (&mut limited).take(4096).read_to_end(&mut head);
                return Err(format!(
                    "not a PLY file: it {}; expected a splat PLY",
                    crate::util::describe_bytes(&head)
                ));
            }
            continue;
        }
        let parts: Vec<&str> = l.split_whitespace().collect();
        match parts.as_slice() {
            [] | ["comment", ..] | ["obj_info", ..] => {}
            ["format", fmt, _] => {
                encoding = Some(match *fmt {
                    "ascii" => Encoding::Ascii,
                    "binary_little_endian" => Encoding::Little,
                    "binary_big_endian" => Encoding::Big,
                    _ => return Err(format!("format `{fmt}` is not a PLY format")),
                })
            }
            ["element", name, n] => {
                let count = n
                    .parse::<u64>()
                    .map_err(|_| format!("element `{name}` has a bad count `{n}`"))?;
                elements.push(Element {
                    name: name.to_string(),
                    count,
                    props: Vec::new(),
                });
            }
            ["property", "list", cty, ity, name] => {
                let (c, i) = match (Ty::parse(cty), Ty::parse(ity)) {
                    (Some(c), Some(i)) if !c.is_float() => (c, i),
                    _ => {
                        return Err(format!(
                            "list property `{name}` has bad types `{cty}` `{ity}`"
                        ))
                    }
                };
                let e = elements
                    .last_mut()
                    .ok_or_else(|| format!("property `{name}` before any element"))?;
                e.props.push(Prop {
                    name: name.to_string(),
                    kind: Kind::List(c, i),
                });
            }
            ["property", ty, name] => {
                let t = Ty::parse(ty)
                    .ok_or_else(|| format!("property `{name}` has unknown type `{ty}`"))?;
                let e = elements
                    .last_mut()
                    .ok_or_else(|| format!("property `{name}` before any element"))?;
                e.props.push(Prop {
                    name: name.to_string(),
                    kind: Kind::Scalar(t),
                });
            }
            ["end_header"] => break,
            _ => {
                let shown: String = l.chars().take(60).collect();
                return Err(format!("header line {number} is not PLY: `{shown}`"));
            }
        }
    }
    let encoding = encoding.ok_or("no `format` line in the header")?;
    Ok((encoding, elements))
}
