//! The one PLY reader and writer of the crate (ASCII, binary little- and big-endian): elements of
//! scalar and list properties of every PLY type, in any order, every value held as f64 in memory.
//! Row counts from the header never drive allocations beyond what the body can hold, so a corrupt
//! header is an error, not an abort. Typed layers build on it (`crate::core::mesh` for triangle meshes,
//! [`crate::core::surfels::ply`] for surfels).

use std::io::Write;
use std::path::{Path, PathBuf};

use thiserror::Error;

/// How the body of a PLY file is encoded.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlyFormat {
    Ascii,
    BinaryLittleEndian,
    BinaryBigEndian,
}

/// A PLY scalar type.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ScalarType {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl ScalarType {
    fn parse(name: &str) -> Option<Self> {
        Some(match name {
            "char" | "int8" => ScalarType::I8,
            "uchar" | "uint8" => ScalarType::U8,
            "short" | "int16" => ScalarType::I16,
            "ushort" | "uint16" => ScalarType::U16,
            "int" | "int32" => ScalarType::I32,
            "uint" | "uint32" => ScalarType::U32,
            "float" | "float32" => ScalarType::F32,
            "double" | "float64" => ScalarType::F64,
            _ => return None,
        })
    }

    fn name(self) -> &'static str {
        match self {
            ScalarType::I8 => "char",
            ScalarType::U8 => "uchar",
            ScalarType::I16 => "short",
            ScalarType::U16 => "ushort",
            ScalarType::I32 => "int",
            ScalarType::U32 => "uint",
            ScalarType::F32 => "float",
            ScalarType::F64 => "double",
        }
    }

    fn size(self) -> usize {
        match self {
            ScalarType::I8 | ScalarType::U8 => 1,
            ScalarType::I16 | ScalarType::U16 => 2,
            ScalarType::I32 | ScalarType::U32 | ScalarType::F32 => 4,
            ScalarType::F64 => 8,
        }
    }

    fn is_integer(self) -> bool {
        !matches!(self, ScalarType::F32 | ScalarType::F64)
    }

    /// Decodes one value from exactly `size()` bytes.
    fn decode(self, bytes: &[u8], little_endian: bool) -> f64 {
        macro_rules! num {
            ($t:ty) => {{
                let array = bytes.try_into().expect("slice of the type's size");
                (if little_endian {
                    <$t>::from_le_bytes(array)
                } else {
                    <$t>::from_be_bytes(array)
                }) as f64
            }};
        }
        match self {
            ScalarType::I8 => num!(i8),
            ScalarType::U8 => num!(u8),
            ScalarType::I16 => num!(i16),
            ScalarType::U16 => num!(u16),
            ScalarType::I32 => num!(i32),
            ScalarType::U32 => num!(u32),
            ScalarType::F32 => num!(f32),
            ScalarType::F64 => num!(f64),
        }
    }

    /// Appends `value` in little-endian binary (integers are rounded), or `None` when `value`
    /// does not fit the type (an integer type out of range or not finite).
    fn encode_le(self, value: f64, out: &mut Vec<u8>) -> Option<()> {
        let integer = |min: f64, max: f64| {
            let rounded = value.round();
            (rounded >= min && rounded <= max).then_some(rounded)
        };
        match self {
            ScalarType::I8 => {
                out.extend((integer(i8::MIN as f64, i8::MAX as f64)? as i8).to_le_bytes())
            }
            ScalarType::U8 => out.extend((integer(0.0, u8::MAX as f64)? as u8).to_le_bytes()),
            ScalarType::I16 => {
                out.extend((integer(i16::MIN as f64, i16::MAX as f64)? as i16).to_le_bytes())
            }
            ScalarType::U16 => out.extend((integer(0.0, u16::MAX as f64)? as u16).to_le_bytes()),
            ScalarType::I32 => {
                out.extend((integer(i32::MIN as f64, i32::MAX as f64)? as i32).to_le_bytes())
            }
            ScalarType::U32 => out.extend((integer(0.0, u32::MAX as f64)? as u32).to_le_bytes()),
            ScalarType::F32 => out.extend((value as f32).to_le_bytes()),
            ScalarType::F64 => out.extend(value.to_le_bytes()),
        }
        Some(())
    }
}

/// The values of one property of an element, one entry per element row.
#[derive(Clone, Debug, PartialEq)]
pub enum PropertyValues {
    Scalar {
        kind: ScalarType,
        values: Vec<f64>,
    },
    List {
        count: ScalarType,
        item: ScalarType,
        values: Vec<Vec<f64>>,
    },
}

impl PropertyValues {
    fn len(&self) -> usize {
        match self {
            PropertyValues::Scalar { values, .. } => values.len(),
            PropertyValues::List { values, .. } => values.len(),
        }
    }
}

/// A named element (`vertex`, `face`, ...) with its properties in file order.
#[derive(Clone, Debug, PartialEq)]
pub struct Element {
    pub name: String,
    pub count: usize,
    pub properties: Vec<(String, PropertyValues)>,
}

impl Element {
    /// An element with `count` rows and no properties yet.
    pub fn new(name: impl Into<String>, count: usize) -> Self {
        Element {
            name: name.into(),
            count,
            properties: Vec::new(),
        }
    }

    /// Adds a scalar property (one value per row).
    pub fn with_scalar(mut self, name: &str, kind: ScalarType, values: Vec<f64>) -> Self {
        self.properties
            .push((name.to_owned(), PropertyValues::Scalar { kind, values }));
        self
    }

    /// Adds a list property (one list per row).
    pub fn with_list(
        mut self,
        name: &str,
        count: ScalarType,
        item: ScalarType,
        values: Vec<Vec<f64>>,
    ) -> Self {
        self.properties.push((
            name.to_owned(),
            PropertyValues::List {
                count,
                item,
                values,
            },
        ));
        self
    }

    /// The values of scalar property `name`.
    pub fn scalar(&self, name: &str) -> Option<&[f64]> {
        self.properties.iter().find_map(|(n, p)| match p {
            PropertyValues::Scalar { values, .. } if n == name => Some(&values[..]),
            _ => None,
        })
    }

    /// The values of list property `name`.
    pub fn list(&self, name: &str) -> Option<&[Vec<f64>]> {
        self.properties.iter().find_map(|(n, p)| match p {
            PropertyValues::List { values, .. } if n == name => Some(&values[..]),
            _ => None,
        })
    }

    /// Like [`Element::scalar`], or an error naming the element and the property.
    pub fn require_scalar(&self, name: &str) -> Result<&[f64], PlyError> {
        self.scalar(name).ok_or_else(|| PlyError::MissingProperty {
            element: self.name.clone(),
            property: name.to_owned(),
        })
    }
}

/// A whole PLY document.
#[derive(Clone, Debug, PartialEq)]
pub struct Ply {
    pub format: PlyFormat,
    pub comments: Vec<String>,
    pub elements: Vec<Element>,
}

impl Ply {
    pub fn element(&self, name: &str) -> Option<&Element> {
        self.elements.iter().find(|e| e.name == name)
    }

    /// Like [`Ply::element`], or an error naming the element.
    pub fn require_element(&self, name: &str) -> Result<&Element, PlyError> {
        self.element(name)
            .ok_or_else(|| PlyError::MissingElement(name.to_owned()))
    }
}

/// Errors of PLY reading and writing.
#[derive(Debug, Error)]
pub enum PlyError {
    #[error("{path}: cannot access file: {message}")]
    Io { path: PathBuf, message: String },
    #[error("PLY header line {line}: {message}")]
    Header { line: usize, message: String },
    #[error("PLY element `{element}` row {row}: {message}")]
    Body {
        element: String,
        row: usize,
        message: String,
    },
    #[error("PLY file has no element `{0}`")]
    MissingElement(String),
    #[error("PLY element `{element}` has no property `{property}`")]
    MissingProperty { element: String, property: String },
    #[error("PLY element `{element}`: {message}")]
    Invalid { element: String, message: String },
}

/// Reads a PLY file.
pub fn read_ply(path: &Path) -> Result<Ply, PlyError> {
    let bytes = std::fs::read(path).map_err(|e| PlyError::Io {
        path: path.to_owned(),
        message: e.to_string(),
    })?;
    parse_ply(&bytes)
}

/// An element as declared in the header: name, row count, properties.
struct DeclaredElement {
    name: String,
    count: usize,
    properties: Vec<(String, Declared)>,
}

/// A property as declared in the header.
enum Declared {
    Scalar(ScalarType),
    List(ScalarType, ScalarType),
}

/// Parses PLY bytes.
pub fn parse_ply(bytes: &[u8]) -> Result<Ply, PlyError> {
    let header_error = |line: usize, message: String| PlyError::Header { line, message };
    let mut offset = 0;
    let next_line = |offset: &mut usize| -> Option<String> {
        let rest = &bytes[*offset..];
        let end = rest.iter().position(|&b| b == b'\n')?;
        *offset += end + 1;
        Some(
            String::from_utf8_lossy(&rest[..end])
                .trim_end_matches('\r')
                .to_owned(),
        )
    };
    if next_line(&mut offset).as_deref().map(str::trim) != Some("ply") {
        return Err(header_error(
            1,
            "not a PLY file (first line is not `ply`)".into(),
        ));
    }
    let mut format = None;
    let mut comments = Vec::new();
    let mut declared: Vec<DeclaredElement> = Vec::new();
    let mut line_no = 1;
    loop {
        let Some(line) = next_line(&mut offset) else {
            return Err(header_error(line_no, "header has no `end_header`".into()));
        };
        line_no += 1;
        let words: Vec<&str> = line.split_whitespace().collect();
        match words.as_slice() {
            ["end_header"] => break,
            ["format", kind, _version] => {
                format = Some(match *kind {
                    "ascii" => PlyFormat::Ascii,
                    "binary_little_endian" => PlyFormat::BinaryLittleEndian,
                    "binary_big_endian" => PlyFormat::BinaryBigEndian,
                    other => {
                        return Err(header_error(line_no, format!("unknown format `{other}`")))
                    }
                })
            }
            ["comment", ..] | ["obj_info", ..] => {
                comments.push(line.split_once(' ').map_or("", |(_, c)| c).to_owned())
            }
            ["element", name, count] => {
                let count = count
                    .parse()
                    .map_err(|_| header_error(line_no, format!("bad element count `{count}`")))?;
                declared.push(DeclaredElement {
                    name: name.to_string(),
                    count,
                    properties: Vec::new(),
                });
            }
            ["property", "list", count, item, name] => {
                let (Some(count), Some(item)) = (ScalarType::parse(count), ScalarType::parse(item))
                else {
                    return Err(header_error(line_no, format!("bad list types in `{line}`")));
                };
                if !count.is_integer() {
                    return Err(header_error(
                        line_no,
                        "list count must be an integer type".into(),
                    ));
                }
                let Some(element) = declared.last_mut() else {
                    return Err(header_error(line_no, "property before any element".into()));
                };
                element
                    .properties
                    .push((name.to_string(), Declared::List(count, item)));
            }
            ["property", kind, name] => {
                let Some(kind) = ScalarType::parse(kind) else {
                    return Err(header_error(line_no, format!("unknown type `{kind}`")));
                };
                let Some(element) = declared.last_mut() else {
                    return Err(header_error(line_no, "property before any element".into()));
                };
                element
                    .properties
                    .push((name.to_string(), Declared::Scalar(kind)));
            }
            [] => {}
            _ => return Err(header_error(line_no, format!("unexpected line `{line}`"))),
        }
    }
    let format = format.ok_or_else(|| header_error(line_no, "no `format` line".into()))?;
    let body = &bytes[offset..];
    let text;
    let values = match format {
        PlyFormat::Ascii => {
            text = String::from_utf8_lossy(body);
            BodyValues::Ascii(text.split_whitespace())
        }
        PlyFormat::BinaryLittleEndian | PlyFormat::BinaryBigEndian => BodyValues::Binary {
            bytes: body,
            at: 0,
            little_endian: format == PlyFormat::BinaryLittleEndian,
        },
    };
    let elements = read_body(values, declared, body.len())?;
    Ok(Ply {
        format,
        comments,
        elements,
    })
}

/// Empty value columns for an element of `count` rows, with room reserved for at most
/// `body_len` rows (every row takes at least one byte of the body, so larger counts from a corrupt
/// header fail on reading instead of reserving memory).
fn empty_values(
    declared: &[(String, Declared)],
    count: usize,
    body_len: usize,
) -> Vec<(String, PropertyValues)> {
    let count = count.min(body_len);
    declared
        .iter()
        .map(|(name, d)| {
            let values = match *d {
                Declared::Scalar(kind) => PropertyValues::Scalar {
                    kind,
                    values: Vec::with_capacity(count),
                },
                Declared::List(count_type, item) => PropertyValues::List {
                    count: count_type,
                    item,
                    values: Vec::with_capacity(count),
                },
            };
            (name.clone(), values)
        })
        .collect()
}

/// The values of a body in file order, whatever its encoding.
enum BodyValues<'a> {
    Ascii(std::str::SplitWhitespace<'a>),
    Binary {
        bytes: &'a [u8],
        at: usize,
        little_endian: bool,
    },
}

impl BodyValues<'_> {
    /// The next value, read as `kind`, or what is wrong with it.
    fn next(&mut self, kind: ScalarType) -> Result<f64, String> {
        let ends_early = || "file ends early".to_owned();
        match self {
            BodyValues::Ascii(tokens) => {
                let token = tokens.next().ok_or_else(ends_early)?;
                token
                    .parse()
                    .map_err(|_| format!("`{token}` is not a number"))
            }
            BodyValues::Binary {
                bytes,
                at,
                little_endian,
            } => {
                let value = bytes.get(*at..*at + kind.size()).ok_or_else(ends_early)?;
                *at += kind.size();
                Ok(kind.decode(value, *little_endian))
            }
        }
    }
}

/// Reads the rows of every declared element from `values`; `body_len` bounds the reservations.
fn read_body(
    mut values: BodyValues,
    declared: Vec<DeclaredElement>,
    body_len: usize,
) -> Result<Vec<Element>, PlyError> {
    let mut elements = Vec::with_capacity(declared.len());
    for DeclaredElement {
        name,
        count,
        properties: props,
    } in declared
    {
        let mut properties = empty_values(&props, count, body_len);
        // Rows without properties hold no bytes: nothing to read, however many are declared.
        let rows_to_read = if props.is_empty() { 0 } else { count };
        for row in 0..rows_to_read {
            let mut take = |kind: ScalarType| {
                values.next(kind).map_err(|message| PlyError::Body {
                    element: name.clone(),
                    row,
                    message,
                })
            };
            for (_, column) in properties.iter_mut() {
                match column {
                    PropertyValues::Scalar { kind, values } => values.push(take(*kind)?),
                    PropertyValues::List {
                        count: count_type,
                        item,
                        values,
                    } => {
                        let n = list_length(take(*count_type)?, &name, row)?;
                        let list = (0..n)
                            .map(|_| take(*item))
                            .collect::<Result<Vec<f64>, _>>()?;
                        values.push(list);
                    }
                }
            }
        }
        elements.push(Element {
            name,
            count,
            properties,
        });
    }
    Ok(elements)
}

/// A list length read from the body: a non-negative integer, or an error naming the row.
fn list_length(n: f64, element: &str, row: usize) -> Result<usize, PlyError> {
    if n >= 0.0 && n.fract() == 0.0 && n <= u32::MAX as f64 {
        Ok(n as usize)
    } else {
        Err(PlyError::Body {
            element: element.to_owned(),
            row,
            message: format!("invalid list length {n}"),
        })
    }
}

/// Serializes a document as binary little-endian PLY (whatever `ply.format` says).
pub fn to_binary_le(ply: &Ply) -> Result<Vec<u8>, PlyError> {
    let mut out = Vec::new();
    let mut header = String::from("ply\nformat binary_little_endian 1.0\n");
    for comment in &ply.comments {
        header.push_str(&format!("comment {comment}\n"));
    }
    for element in &ply.elements {
        header.push_str(&format!("element {} {}\n", element.name, element.count));
        for (name, values) in &element.properties {
            if values.len() != element.count {
                return Err(PlyError::Invalid {
                    element: element.name.clone(),
                    message: format!(
                        "property `{name}` has {} values for {} rows",
                        values.len(),
                        element.count
                    ),
                });
            }
            match values {
                PropertyValues::Scalar { kind, .. } => {
                    header.push_str(&format!("property {} {name}\n", kind.name()))
                }
                PropertyValues::List { count, item, .. } => header.push_str(&format!(
                    "property list {} {} {name}\n",
                    count.name(),
                    item.name()
                )),
            }
        }
    }
    header.push_str("end_header\n");
    out.extend(header.as_bytes());
    for element in &ply.elements {
        for row in 0..element.count {
            for (name, values) in &element.properties {
                let encode = |kind: ScalarType, value: f64, out: &mut Vec<u8>| {
                    kind.encode_le(value, out).ok_or_else(|| PlyError::Invalid {
                        element: element.name.clone(),
                        message: format!(
                            "property `{name}` row {row}: {value} does not fit a {}",
                            kind.name()
                        ),
                    })
                };
                match values {
                    PropertyValues::Scalar { kind, values } => {
                        encode(*kind, values[row], &mut out)?
                    }
                    PropertyValues::List {
                        count,
                        item,
                        values,
                    } => {
                        encode(*count, values[row].len() as f64, &mut out)?;
                        for v in &values[row] {
                            encode(*item, *v, &mut out)?;
                        }
                    }
                }
            }
        }
    }
    Ok(out)
}

/// Writes a document as binary little-endian PLY.
pub fn write_ply(path: &Path, ply: &Ply) -> Result<(), PlyError> {
    let bytes = to_binary_le(ply)?;
    let io_error = |e: std::io::Error| PlyError::Io {
        path: path.to_owned(),
        message: e.to_string(),
    };
    let mut file = std::fs::File::create(path).map_err(io_error)?;
    file.write_all(&bytes).map_err(io_error)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> Ply {
        Ply {
            format: PlyFormat::BinaryLittleEndian,
            comments: vec!["made by a test".into()],
            elements: vec![
                Element::new("vertex", 3)
                    .with_scalar("x", ScalarType::F32, vec![0.5, -1.25, 3.0])
                    .with_scalar("w", ScalarType::F64, vec![0.1, 0.2, 1e-300])
                    .with_scalar("id", ScalarType::U16, vec![1.0, 2.0, 65535.0]),
                Element::new("face", 2)
                    .with_list(
                        "vertex_indices",
                        ScalarType::U8,
                        ScalarType::I32,
                        vec![vec![0.0, 1.0, 2.0], vec![2.0, 1.0, 0.0, 1.0]],
                    )
                    .with_scalar("material_id", ScalarType::U8, vec![1.0, 7.0]),
            ],
        }
    }

    #[test]
    fn binary_round_trip_is_exact_for_representable_values() {
        let ply = sample();
        let back = parse_ply(&to_binary_le(&ply).unwrap()).unwrap();
        assert_eq!(back, ply);
    }

    #[test]
    fn ascii_and_big_endian_bodies_are_read() {
        let ascii = b"ply\r\nformat ascii 1.0\r\nelement vertex 2\r\nproperty float x\r\n\
property int y\r\nelement face 1\r\nproperty list uchar uint vertex_index\r\nend_header\r\n\
1.5 -2\n3 4\n3 0 1 1\n";
        let ply = parse_ply(ascii).unwrap();
        assert_eq!(ply.format, PlyFormat::Ascii);
        assert_eq!(
            ply.element("vertex").unwrap().scalar("x"),
            Some(&[1.5, 3.0][..])
        );
        assert_eq!(
            ply.element("vertex").unwrap().scalar("y"),
            Some(&[-2.0, 4.0][..])
        );
        assert_eq!(
            ply.element("face").unwrap().list("vertex_index"),
            Some(&[vec![0.0, 1.0, 1.0]][..])
        );
        let mut big = b"ply\nformat binary_big_endian 1.0\nelement v 1\nproperty short a\nproperty double b\nend_header\n".to_vec();
        big.extend((-3i16).to_be_bytes());
        big.extend(2.5f64.to_be_bytes());
        let ply = parse_ply(&big).unwrap();
        assert_eq!(ply.elements[0].scalar("a"), Some(&[-3.0][..]));
        assert_eq!(ply.elements[0].scalar("b"), Some(&[2.5][..]));
    }

    #[test]
    fn truncated_and_malformed_files_are_named_errors() {
        let bytes = to_binary_le(&sample()).unwrap();
        let e = parse_ply(&bytes[..bytes.len() - 3])
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("`face` row 1") && e.contains("ends early"),
            "{e}"
        );
        let e = parse_ply(b"ply\nformat ascii 1.0\nproperty float x\nend_header\n")
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("line 3") && e.contains("before any element"),
            "{e}"
        );
        assert!(parse_ply(b"PLY\n").is_err());
        let mut bad = sample();
        bad.elements[0].count = 4;
        assert!(matches!(to_binary_le(&bad), Err(PlyError::Invalid { .. })));
    }

    #[test]
    fn corrupt_counts_and_list_lengths_are_named_errors() {
        // A row count far beyond what the body holds fails on reading, without reserving memory.
        let huge = b"ply\nformat binary_little_endian 1.0\nelement vertex 999999999999999\n\
property float x\nend_header\n\x00\x00\x80\x3f";
        let e = parse_ply(huge).unwrap_err().to_string();
        assert!(
            e.contains("`vertex` row 1") && e.contains("ends early"),
            "{e}"
        );
        let list = |length: &str| {
            format!(
                "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n\
end_header\n{length} 0 1 2\n"
            )
        };
        assert_eq!(
            parse_ply(list("3").as_bytes()).unwrap().elements[0].list("vertex_indices"),
            Some(&[vec![0.0, 1.0, 2.0]][..])
        );
        for bad in ["-1", "2.5"] {
            let e = parse_ply(list(bad).as_bytes()).unwrap_err().to_string();
            assert!(
                e.contains("`face` row 0") && e.contains(&format!("invalid list length {bad}")),
                "{e}"
            );
        }
        let mut big = b"ply\nformat binary_big_endian 1.0\nelement face 1\n\
property list char int vertex_indices\nend_header\n"
            .to_vec();
        big.push(0xff); // -1 as a signed char
        let e = parse_ply(&big).unwrap_err().to_string();
        assert!(e.contains("invalid list length -1"), "{e}");
    }

    #[test]
    fn integers_that_do_not_fit_their_type_are_refused_on_writing() {
        for (kind, value) in [
            (ScalarType::U8, 256.0),
            (ScalarType::U8, -1.0),
            (ScalarType::I32, 2_147_483_648.0),
            (ScalarType::U16, f64::NAN),
        ] {
            let ply = Ply {
                format: PlyFormat::BinaryLittleEndian,
                comments: Vec::new(),
                elements: vec![Element::new("v", 2).with_scalar("a", kind, vec![0.0, value])],
            };
            let e = to_binary_le(&ply).unwrap_err().to_string();
            assert!(
                e.contains("`v`") && e.contains("`a` row 1") && e.contains(kind.name()),
                "{e}"
            );
        }
        let edges = Ply {
            format: PlyFormat::BinaryLittleEndian,
            comments: Vec::new(),
            elements: vec![Element::new("v", 2)
                .with_scalar("a", ScalarType::I8, vec![-128.0, 127.0])
                .with_scalar("b", ScalarType::U32, vec![0.0, u32::MAX as f64])],
        };
        assert_eq!(parse_ply(&to_binary_le(&edges).unwrap()).unwrap(), edges);
    }
}
