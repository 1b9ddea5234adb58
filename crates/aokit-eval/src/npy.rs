//! NumPy `.npy` files of 32- or 64-bit floats, read without numpy.
//!
//! Layout: the magic `\x93NUMPY`, a version byte pair, the header length (2 bytes little-endian
//! for version 1, 4 for versions 2 and 3), then a Python dict literal such as
//! `{'descr': '<f4', 'fortran_order': False, 'shape': (480, 640), }` and the raw samples.

use std::path::Path;

use crate::error::{EvalError, Result};
use crate::float_image::{FloatImage, sample_count};

const MAGIC: &[u8] = b"\x93NUMPY";

/// A value in the header dict; only the kinds numpy writes for these keys.
#[derive(Debug, PartialEq)]
enum Value {
    Str(String),
    Bool(bool),
    Tuple(Vec<u64>),
}

/// A cursor over the header text with just enough grammar for numpy's dict literal.
struct Dict<'a> {
    text: &'a [u8],
    pos: usize,
}

impl Dict<'_> {
    fn skip_space(&mut self) {
        while self.text.get(self.pos).is_some_and(u8::is_ascii_whitespace) {
            self.pos += 1;
        }
    }

    fn peek(&mut self) -> Option<u8> {
        self.skip_space();
        self.text.get(self.pos).copied()
    }

    fn expect(&mut self, byte: u8) -> Result<(), String> {
        if self.peek() == Some(byte) {
            self.pos += 1;
            Ok(())
        } else {
            Err(format!(
                "expected '{}' at byte {} of the header",
                byte as char, self.pos
            ))
        }
    }

    fn string(&mut self) -> Result<String, String> {
        let quote = self
            .peek()
            .filter(|q| matches!(q, b'\'' | b'"'))
            .ok_or("expected a quoted string in the header")?;
        let start = self.pos + 1;
        let len = self.text[start..]
            .iter()
            .position(|&b| b == quote)
            .ok_or("unterminated string in the header")?;
        self.pos = start + len + 1;
        Ok(String::from_utf8_lossy(&self.text[start..start + len]).into_owned())
    }

    fn word(&mut self) -> &str {
        self.skip_space();
        let start = self.pos;
        while self
            .text
            .get(self.pos)
            .is_some_and(u8::is_ascii_alphanumeric)
        {
            self.pos += 1;
        }
        std::str::from_utf8(&self.text[start..self.pos]).unwrap_or("")
    }

    fn tuple(&mut self) -> Result<Vec<u64>, String> {
        self.expect(b'(')?;
        let mut items = Vec::new();
        loop {
            if self.peek() == Some(b')') {
                self.pos += 1;
                return Ok(items);
            }
            // Python 2 wrote longs as `480L`.
            let word = self.word();
            let digits = word.strip_suffix('L').unwrap_or(word);
            items.push(
                digits
                    .parse()
                    .map_err(|_| format!("shape entry {word:?} is not a whole number"))?,
            );
            match self.peek() {
                Some(b',') => self.pos += 1,
                Some(b')') => {}
                _ => return Err("malformed shape tuple in the header".to_string()),
            }
        }
    }

    fn value(&mut self) -> Result<Value, String> {
        match self.peek() {
            Some(b'\'' | b'"') => self.string().map(Value::Str),
            Some(b'(') => self.tuple().map(Value::Tuple),
            _ => match self.word() {
                "True" => Ok(Value::Bool(true)),
                "False" => Ok(Value::Bool(false)),
                other => Err(format!("unexpected value {other:?} in the header")),
            },
        }
    }

    fn entries(&mut self) -> Result<Vec<(String, Value)>, String> {
        self.expect(b'{')?;
        let mut entries = Vec::new();
        loop {
            if self.peek() == Some(b'}') {
                return Ok(entries);
            }
            let key = self.string()?;
            self.expect(b':')?;
            entries.push((key, self.value()?));
            match self.peek() {
                Some(b',') => self.pos += 1,
                Some(b'}') => {}
                _ => return Err("malformed header dict".to_string()),
            }
        }
    }
}

/// The sample type named by `descr`.
#[derive(Clone, Copy)]
enum Dtype {
    F32 { little: bool },
    F64 { little: bool },
}

impl Dtype {
    fn parse(descr: &str) -> Option<Self> {
        match descr {
            "<f4" => Some(Self::F32 { little: true }),
            ">f4" => Some(Self::F32 { little: false }),
            "<f8" => Some(Self::F64 { little: true }),
            ">f8" => Some(Self::F64 { little: false }),
            _ => None,
        }
    }

    fn size(self) -> usize {
        match self {
            Self::F32 { .. } => 4,
            Self::F64 { .. } => 8,
        }
    }

    fn decode(self, b: &[u8]) -> f32 {
        match self {
            Self::F32 { little } => {
                let b = [b[0], b[1], b[2], b[3]];
                if little {
                    f32::from_le_bytes(b)
                } else {
                    f32::from_be_bytes(b)
                }
            }
            Self::F64 { little } => {
                let b = [b[0], b[1], b[2], b[3], b[4], b[5], b[6], b[7]];
                (if little {
                    f64::from_le_bytes(b)
                } else {
                    f64::from_be_bytes(b)
                }) as f32
            }
        }
    }
}

/// The header dict's text and where the samples start.
fn split_header<'a>(path: &Path, bytes: &'a [u8]) -> Result<(&'a [u8], &'a [u8])> {
    let bad = |problem: &str| EvalError::format(path, problem);
    if !bytes.starts_with(MAGIC) {
        return Err(bad("not a NumPy .npy file (missing the \\x93NUMPY magic)"));
    }
    let (len, start): (Option<usize>, usize) = match bytes.get(6) {
        Some(1) => (
            bytes
                .get(8..10)
                .map(|b| u16::from_le_bytes([b[0], b[1]]) as usize),
            10,
        ),
        Some(2 | 3) => (
            bytes
                .get(8..12)
                .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as usize),
            12,
        ),
        Some(v) => {
            return Err(EvalError::format(
                path,
                format!(".npy format version {v} is not supported (1, 2 or 3)"),
            ));
        }
        None => return Err(bad(".npy file ends inside its header")),
    };
    let len = len.ok_or_else(|| bad(".npy file ends inside its header"))?;
    let end = start
        .checked_add(len)
        .filter(|&end| end <= bytes.len())
        .ok_or_else(|| bad(".npy file ends inside its header"))?;
    Ok((&bytes[start..end], &bytes[end..]))
}

/// Parses a `.npy` holding a `(H, W)` or `(H, W, 1)` array (`channels` = 1) or a `(H, W, 3)`
/// array (`channels` = 3) of `<f4`, `>f4`, `<f8` or `>f8`, C order.
pub(crate) fn parse(path: &Path, bytes: &[u8], channels: u32) -> Result<FloatImage> {
    let (header, data) = split_header(path, bytes)?;
    let bad = |problem: String| EvalError::format(path, problem);
    let entries = Dict {
        text: header,
        pos: 0,
    }
    .entries()
    .map_err(|e| bad(format!("cannot parse the .npy header: {e}")))?;
    let get = |key: &str| entries.iter().find(|(k, _)| k == key).map(|(_, v)| v);
    let dtype = match get("descr") {
        Some(Value::Str(descr)) => Dtype::parse(descr).ok_or_else(|| {
            bad(format!(
                "dtype '{descr}' is not supported; save as float32 ('<f4') or float64"
            ))
        })?,
        _ => return Err(bad(".npy header has no 'descr' string".to_string())),
    };
    match get("fortran_order") {
        Some(Value::Bool(false)) => {}
        Some(Value::Bool(true)) => {
            return Err(bad(
                "array is in Fortran order; save a C-ordered array (np.ascontiguousarray)"
                    .to_string(),
            ));
        }
        _ => return Err(bad(".npy header has no 'fortran_order' flag".to_string())),
    }
    let shape = match get("shape") {
        Some(Value::Tuple(shape)) => shape.as_slice(),
        _ => return Err(bad(".npy header has no 'shape' tuple".to_string())),
    };
    let shown = format!(
        "({})",
        shape
            .iter()
            .map(u64::to_string)
            .collect::<Vec<_>>()
            .join(", ")
    );
    let (height, width) = match (shape, channels) {
        ([h, w], 1) | ([h, w, 1], 1) | ([h, w, 3], 3) => (*h, *w),
        _ => {
            let want = if channels == 1 {
                "(H, W) or (H, W, 1)"
            } else {
                "(H, W, 3)"
            };
            return Err(bad(format!("array shape {shown} is not {want}")));
        }
    };
    let count = sample_count(path, width, height, channels.into())?;
    let expected = count
        .checked_mul(dtype.size())
        .ok_or_else(|| bad(format!("array shape {shown} is too large")))?;
    if data.len() != expected {
        return Err(bad(format!(
            "array data is {} bytes but shape {shown} needs {expected}",
            data.len()
        )));
    }
    Ok(FloatImage {
        width: width as u32,
        height: height as u32,
        channels,
        data: data
            .chunks_exact(dtype.size())
            .map(|b| dtype.decode(b))
            .collect(),
    })
}
