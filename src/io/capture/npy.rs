//! NumPy `.npy` arrays and `.npz` archives of them, read within limits and written small: the
//! cameras of the IDR/NeuS layout (`cameras.npz`), LLFF's `poses_bounds.npy` and Stokes images
//! stored as float16/float32 arrays.
//!
//! npyz parses the header's Python literal and decodes the dtypes (float16/32/64, uint8/16,
//! int32/64, either byte order); the `.npz` archive is opened with the `zip` crate. Nothing is
//! allocated from a size the file declares before it is checked: the header's length against
//! [`NpyLimits::max_header_bytes`] (before npyz reads it), the element count against
//! [`NpyLimits::max_elements`], and the bytes the shape needs against the bytes the file (or the
//! archive entry) holds. Fortran-ordered arrays come back in C order.

use std::collections::BTreeMap;
use std::io::{Cursor, Read, Write};
use std::path::{Path, PathBuf};

use npyz::{DType, NpyFile, Order, TypeChar};
use thiserror::Error;

/// Why an array could not be read or written; each names the file (and the archive member).
#[derive(Debug, Error)]
pub enum NpyError {
    #[error("{path}: cannot read: {source}")]
    Io {
        path: String,
        source: std::io::Error,
    },
    /// Not a valid `.npy` file or `.npz` archive (bad magic, truncated, malformed header).
    #[error("{path}: not a valid NumPy file: {message}")]
    Format { path: String, message: String },
    /// A valid file that phygap does not read (a dtype such as complex or object).
    #[error("{path}: {message}")]
    Unsupported { path: String, message: String },
    /// The file declares more than the limits allow; nothing of that size was allocated.
    #[error("{path}: {message}")]
    TooLarge { path: String, message: String },
    #[error("cannot write {path}: {message}")]
    Write { path: PathBuf, message: String },
}

/// The most an array file may declare.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NpyLimits {
    /// Bytes of the header's Python literal (NumPy writes under 200 for plain arrays).
    pub max_header_bytes: usize,
    /// Elements of one array.
    pub max_elements: u64,
    /// Members of an `.npz` archive.
    pub max_members: usize,
}

impl NpyLimits {
    /// Camera files: 2,000 views of a handful of 4×4 matrices each.
    pub const CAMERAS: NpyLimits = NpyLimits {
        max_header_bytes: 64 << 10,
        max_elements: 1 << 20,
        max_members: 16_384,
    };

    /// One image of at most `pixels` pixels with up to `channels` values a pixel.
    pub fn image(pixels: u64, channels: u64) -> NpyLimits {
        NpyLimits {
            max_header_bytes: 64 << 10,
            max_elements: pixels.saturating_mul(channels),
            max_members: 1,
        }
    }
}

/// An array in C order: `data[((i0 · s1) + i1) · s2 + i2 …]` for shape `[s0, s1, s2 …]`.
#[derive(Clone, Debug, PartialEq)]
pub struct NpyArray<T> {
    pub shape: Vec<usize>,
    pub data: Vec<T>,
}

/// A value an array's elements are converted to.
pub trait Element: Copy {
    fn from_f64(v: f64) -> Self;
    fn from_f32(v: f32) -> Self;
}

impl Element for f64 {
    fn from_f64(v: f64) -> Self {
        v
    }
    fn from_f32(v: f32) -> Self {
        f64::from(v)
    }
}

impl Element for f32 {
    fn from_f64(v: f64) -> Self {
        v as f32
    }
    fn from_f32(v: f32) -> Self {
        v
    }
}

/// The shape and element size an `.npy` header declares.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NpyHeader {
    pub shape: Vec<usize>,
    /// E.g. `<f2`, `<f4`, `|u1`.
    pub dtype: String,
}

/// Reads the magic, version and header length, checks the length, and returns the bytes read so
/// far (handed back to npyz) with the total header size.
fn read_preamble(
    reader: &mut impl Read,
    name: &str,
    limits: &NpyLimits,
) -> Result<(Vec<u8>, u64), NpyError> {
    let format = |message: String| NpyError::Format {
        path: name.to_owned(),
        message,
    };
    let mut preamble = vec![0u8; 10];
    reader.read_exact(&mut preamble).map_err(|_| {
        format(
            "shorter than the 10-byte preamble of an .npy file (\\x93NUMPY, version, length)"
                .into(),
        )
    })?;
    if &preamble[..6] != b"\x93NUMPY" {
        return Err(format(
            "does not start with the magic string \\x93NUMPY".into(),
        ));
    }
    let header_len = match preamble[6] {
        1 => u64::from(u16::from_le_bytes([preamble[8], preamble[9]])),
        2 | 3 => {
            let mut rest = [0u8; 2];
            reader
                .read_exact(&mut rest)
                .map_err(|_| format("truncated in the header length".into()))?;
            preamble.extend_from_slice(&rest);
            u64::from(u32::from_le_bytes([
                preamble[8],
                preamble[9],
                rest[0],
                rest[1],
            ]))
        }
        major => {
            return Err(format(format!(
                "format version {major}.{} (1.0, 2.0 and 3.0 exist)",
                preamble[7]
            )))
        }
    };
    if header_len > limits.max_header_bytes as u64 {
        return Err(NpyError::TooLarge {
            path: name.to_owned(),
            message: format!(
                "the header declares {header_len} bytes, over the limit of {} for an .npy header",
                limits.max_header_bytes
            ),
        });
    }
    let total = preamble.len() as u64 + header_len;
    Ok((preamble, total))
}

/// An array stream whose preamble was read (and checked) before npyz parses the header.
type Reopened<R> = NpyFile<std::io::Chain<Cursor<Vec<u8>>, R>>;

/// Parses the header of an array stream holding `available` bytes in all; also returns the
/// bytes before the data (preamble and header).
fn open_array<R: Read>(
    mut reader: R,
    available: u64,
    name: &str,
    limits: &NpyLimits,
) -> Result<(Reopened<R>, u64), NpyError> {
    let (preamble, header_total) = read_preamble(&mut reader, name, limits)?;
    if header_total > available {
        return Err(NpyError::Format {
            path: name.to_owned(),
            message: format!(
                "truncated: the header needs {header_total} bytes, the file holds {available}"
            ),
        });
    }
    let file = NpyFile::new(Cursor::new(preamble).chain(reader)).map_err(|e| NpyError::Format {
        path: name.to_owned(),
        message: format!("malformed header: {e}"),
    })?;
    Ok((file, header_total))
}

/// The shape (as usize) and element count of a parsed header, checked against the limits and
/// against the `data_bytes` that follow the header.
fn checked_shape(
    header: &npyz::NpyHeader,
    data_bytes: u64,
    name: &str,
    limits: &NpyLimits,
) -> Result<(Vec<usize>, usize), NpyError> {
    let too_large = |message: String| NpyError::TooLarge {
        path: name.to_owned(),
        message,
    };
    let shape_text = format!("{:?}", header.shape());
    let elements = header
        .shape()
        .iter()
        .try_fold(1u64, |n, &s| n.checked_mul(s))
        .ok_or_else(|| too_large(format!("the shape {shape_text} overflows")))?;
    if elements > limits.max_elements {
        return Err(too_large(format!(
            "the shape {shape_text} declares {elements} elements, over the limit of {}",
            limits.max_elements
        )));
    }
    let item = header.dtype().num_bytes().unwrap_or(0) as u64;
    let needed = elements.saturating_mul(item);
    if needed > data_bytes {
        return Err(NpyError::Format {
            path: name.to_owned(),
            message: format!(
                "truncated: the shape {shape_text} of {} needs {needed} bytes of data, the file holds {data_bytes}",
                header.dtype().descr()
            ),
        });
    }
    let shape = header.shape().iter().map(|&s| s as usize).collect();
    Ok((shape, elements as usize))
}

/// The dtype's element kind and size, e.g. (`f`, 2) for float16.
fn element_kind(dtype: &DType) -> Option<(TypeChar, u64)> {
    match dtype {
        DType::Plain(ty) => Some((ty.type_char(), ty.size_field())),
        _ => None,
    }
}

/// Decodes every element of `file` as `T`, in the order stored.
fn decode<T: Element, R: Read>(file: NpyFile<R>, name: &str) -> Result<Vec<T>, NpyError> {
    let dtype = file.dtype();
    let unsupported = || NpyError::Unsupported {
        path: name.to_owned(),
        message: format!(
            "arrays of dtype {} are not read (float16/32/64, uint8/16 and int32/64 are)",
            dtype.descr()
        ),
    };
    let read_error = |e: std::io::Error| NpyError::Format {
        path: name.to_owned(),
        message: format!("unreadable data: {e}"),
    };
    fn all<U: npyz::Deserialize, R: Read, T>(
        file: NpyFile<R>,
        convert: impl Fn(U) -> T,
    ) -> std::io::Result<Vec<T>> {
        file.data::<U>()
            .map_err(|e| std::io::Error::new(std::io::ErrorKind::InvalidData, e.to_string()))?
            .map(|v| v.map(&convert))
            .collect()
    }
    let values = match element_kind(&dtype).ok_or_else(unsupported)? {
        (TypeChar::Float, 2) => all(file, |v: npyz::half::f16| T::from_f32(v.to_f32())),
        (TypeChar::Float, 4) => all(file, T::from_f32),
        (TypeChar::Float, 8) => all(file, T::from_f64),
        (TypeChar::Uint, 1) => all(file, |v: u8| T::from_f32(f32::from(v))),
        (TypeChar::Uint, 2) => all(file, |v: u16| T::from_f32(f32::from(v))),
        (TypeChar::Int, 4) => all(file, |v: i32| T::from_f64(f64::from(v))),
        (TypeChar::Int, 8) => all(file, |v: i64| T::from_f64(v as f64)),
        _ => return Err(unsupported()),
    };
    values.map_err(read_error)
}

/// Reorders Fortran-ordered `data` of `shape` into C order.
fn fortran_to_c<T: Copy>(shape: &[usize], data: Vec<T>) -> Vec<T> {
    if shape.len() < 2 {
        return data;
    }
    let mut out = Vec::with_capacity(data.len());
    let mut index = vec![0usize; shape.len()];
    for _ in 0..data.len() {
        // Offset of `index` in Fortran order: the first axis varies fastest.
        let mut offset = 0;
        for axis in (0..shape.len()).rev() {
            offset = offset * shape[axis] + index[axis];
        }
        out.push(data[offset]);
        for axis in (0..shape.len()).rev() {
            index[axis] += 1;
            if index[axis] < shape[axis] {
                break;
            }
            index[axis] = 0;
        }
    }
    out
}

/// Reads one array from a stream of `available` bytes named `name` in messages.
pub fn read_array_from<T: Element>(
    reader: impl Read,
    available: u64,
    name: &str,
    limits: &NpyLimits,
) -> Result<NpyArray<T>, NpyError> {
    let (file, header_total) = open_array(reader, available, name, limits)?;
    let data_bytes = available - header_total;
    let (shape, _) = checked_shape(file.header(), data_bytes, name, limits)?;
    let order = file.order();
    let data = decode(file, name)?;
    let data = match order {
        Order::C => data,
        Order::Fortran => fortran_to_c(&shape, data),
    };
    Ok(NpyArray { shape, data })
}

/// Reads the array file at `path` within `limits`.
pub fn read_npy<T: Element>(path: &Path, limits: &NpyLimits) -> Result<NpyArray<T>, NpyError> {
    let name = path.display().to_string();
    let io = |source| NpyError::Io {
        path: name.clone(),
        source,
    };
    let file = std::fs::File::open(path).map_err(io)?;
    let length = file.metadata().map_err(io)?.len();
    read_array_from(std::io::BufReader::new(file), length, &name, limits)
}

/// The shape and dtype the array file at `path` declares, read without its data.
pub fn read_npy_header(path: &Path, limits: &NpyLimits) -> Result<NpyHeader, NpyError> {
    let name = path.display().to_string();
    let io = |source| NpyError::Io {
        path: name.clone(),
        source,
    };
    let file = std::fs::File::open(path).map_err(io)?;
    let length = file.metadata().map_err(io)?.len();
    let (parsed, header_total) = open_array(std::io::BufReader::new(file), length, &name, limits)?;
    let data_bytes = length - header_total;
    let (shape, _) = checked_shape(parsed.header(), data_bytes, &name, limits)?;
    Ok(NpyHeader {
        shape,
        dtype: parsed
            .header()
            .dtype()
            .descr()
            .trim_matches('\'')
            .to_owned(),
    })
}

/// Reads the members of the `.npz` archive at `path` whose array name (the member's name less
/// `.npy`) `wanted` accepts, each within `limits`.
pub fn read_npz<T: Element>(
    path: &Path,
    limits: &NpyLimits,
    wanted: impl Fn(&str) -> bool,
) -> Result<BTreeMap<String, NpyArray<T>>, NpyError> {
    let name = path.display().to_string();
    let file = std::fs::File::open(path).map_err(|source| NpyError::Io {
        path: name.clone(),
        source,
    })?;
    let mut archive =
        zip::ZipArchive::new(std::io::BufReader::new(file)).map_err(|e| NpyError::Format {
            path: name.clone(),
            message: format!("not a zip archive (an .npz is a zip of .npy files): {e}"),
        })?;
    if archive.len() > limits.max_members {
        return Err(NpyError::TooLarge {
            path: name,
            message: format!(
                "{} members, over the limit of {}",
                archive.len(),
                limits.max_members
            ),
        });
    }
    let mut arrays = BTreeMap::new();
    for index in 0..archive.len() {
        let mut member = archive.by_index(index).map_err(|e| NpyError::Format {
            path: name.clone(),
            message: format!("member {index}: {e}"),
        })?;
        let Some(array_name) = member.name().strip_suffix(".npy").map(str::to_owned) else {
            continue;
        };
        if !wanted(&array_name) {
            continue;
        }
        let label = format!("{name}:{array_name}");
        let size = member.size();
        let array = read_array_from(&mut member, size, &label, limits)?;
        arrays.insert(array_name, array);
    }
    Ok(arrays)
}

/// An element type the writer stores.
pub trait WriteElement: Copy {
    /// NumPy's dtype string, e.g. `<f8`.
    const DESCR: &'static str;
    fn write_le(self, out: &mut Vec<u8>);
}

impl WriteElement for f64 {
    const DESCR: &'static str = "<f8";
    fn write_le(self, out: &mut Vec<u8>) {
        out.extend_from_slice(&self.to_le_bytes());
    }
}

impl WriteElement for f32 {
    const DESCR: &'static str = "<f4";
    fn write_le(self, out: &mut Vec<u8>) {
        out.extend_from_slice(&self.to_le_bytes());
    }
}

impl WriteElement for npyz::half::f16 {
    const DESCR: &'static str = "<f2";
    fn write_le(self, out: &mut Vec<u8>) {
        out.extend_from_slice(&self.to_le_bytes());
    }
}

/// The bytes of a version-1.0 `.npy` file of `data` (C order) with `shape`, as `numpy.save`
/// writes it: the header padded with spaces and a newline to a multiple of 64 bytes.
///
/// # Panics
/// When `data` does not hold the product of `shape` elements.
pub fn npy_bytes<T: WriteElement>(shape: &[usize], data: &[T]) -> Vec<u8> {
    assert_eq!(
        shape.iter().product::<usize>(),
        data.len(),
        "shape and data"
    );
    let dims: Vec<String> = shape.iter().map(usize::to_string).collect();
    let shape_text = match dims.len() {
        1 => format!("({},)", dims[0]),
        _ => format!("({})", dims.join(", ")),
    };
    let mut header = format!(
        "{{'descr': '{}', 'fortran_order': False, 'shape': {shape_text}, }}",
        T::DESCR
    );
    let unpadded = 10 + header.len() + 1;
    header.push_str(&" ".repeat(unpadded.next_multiple_of(64) - unpadded));
    header.push('\n');
    let mut out = Vec::with_capacity(10 + header.len() + data.len() * 8);
    out.extend_from_slice(b"\x93NUMPY\x01\x00");
    out.extend_from_slice(&(header.len() as u16).to_le_bytes());
    out.extend_from_slice(header.as_bytes());
    for &v in data {
        v.write_le(&mut out);
    }
    out
}

/// Writes an `.npy` file.
pub fn write_npy<T: WriteElement>(
    path: &Path,
    shape: &[usize],
    data: &[T],
) -> Result<(), NpyError> {
    std::fs::write(path, npy_bytes(shape, data)).map_err(|e| NpyError::Write {
        path: path.to_owned(),
        message: e.to_string(),
    })
}

/// Writes an `.npz` archive (stored, as `numpy.savez`) of `(name, shape, data)` arrays.
pub fn write_npz(path: &Path, arrays: &[(String, Vec<usize>, Vec<f64>)]) -> Result<(), NpyError> {
    let error = |message: String| NpyError::Write {
        path: path.to_owned(),
        message,
    };
    let file = std::fs::File::create(path).map_err(|e| error(e.to_string()))?;
    let mut writer = zip::ZipWriter::new(file);
    let options =
        zip::write::SimpleFileOptions::default().compression_method(zip::CompressionMethod::Stored);
    for (name, shape, data) in arrays {
        writer
            .start_file(format!("{name}.npy"), options)
            .map_err(|e| error(e.to_string()))?;
        writer
            .write_all(&npy_bytes(shape, data))
            .map_err(|e| error(e.to_string()))?;
    }
    writer.finish().map_err(|e| error(e.to_string()))?;
    Ok(())
}
