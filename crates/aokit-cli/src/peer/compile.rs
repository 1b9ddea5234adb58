//! Compiling aokit's XeGTAO wrapper against the user's XeGTAO.h and XeGTAO.hlsli with
//! glslangValidator, one SPIR-V module per entry point.

use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::{Context, Result, anyhow, bail};

use super::Quality;
use super::gpu::binding;
use super::spirv;

/// aokit's wrapper: bindings, thread groups, entry points and the engine hooks.
const WRAPPER: &str = include_str!("../../peers/xegtao.hlsl");
const WRAPPER_FILE: &str = "aokit-xegtao.hlsl";
/// The user's files the wrapper includes.
pub const SOURCE_FILES: [&str; 2] = ["XeGTAO.h", "XeGTAO.hlsli"];
/// Where the compiler is looked for: `$AOKIT_GLSLANG`, else `glslangValidator` on PATH.
const COMPILER_VARIABLE: &str = "AOKIT_GLSLANG";
const COMPILER: &str = "glslangValidator";

/// One SPIR-V module: an entry point of the wrapper, the main pass per quality level.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Entry {
    Prefilter,
    Main(Quality),
    Denoise,
    DenoiseLast,
}

impl Entry {
    /// Every module `aokit peer compile` writes.
    pub fn all() -> Vec<Entry> {
        let mut all = vec![Entry::Prefilter];
        all.extend(Quality::ALL.map(Entry::Main));
        all.extend([Entry::Denoise, Entry::DenoiseLast]);
        all
    }

    fn entry_point(self) -> &'static str {
        match self {
            Entry::Prefilter => "prefilter",
            Entry::Main(_) => "main_pass",
            Entry::Denoise => "denoise",
            Entry::DenoiseLast => "denoise_last",
        }
    }

    /// The module's file name in a compiled folder.
    pub fn file_name(self) -> String {
        match self {
            Entry::Main(quality) => format!("main-{}.spv", quality.name()),
            other => format!("{}.spv", other.entry_point().replace('_', "-")),
        }
    }

    /// The storage images the entry point only writes.
    fn write_only(self) -> &'static [u32] {
        match self {
            Entry::Prefilter => binding::prefilter::WRITE_ONLY,
            Entry::Main(_) => binding::main::WRITE_ONLY,
            Entry::Denoise | Entry::DenoiseLast => binding::denoise::WRITE_ONLY,
        }
    }

    fn defines(self) -> Vec<String> {
        match self {
            Entry::Main(quality) => {
                let (slices, steps) = quality.slices_and_steps();
                vec![
                    format!("-DAOKIT_SLICES={slices}"),
                    format!("-DAOKIT_STEPS={steps}"),
                ]
            }
            _ => Vec::new(),
        }
    }
}

/// A digest of the wrapper, which a compiled folder records: its modules only fit the
/// bindings of the wrapper they were compiled from (FNV-1a, 64 bits).
pub fn wrapper_digest() -> String {
    let hash = WRAPPER.bytes().fold(0xcbf2_9ce4_8422_2325_u64, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    });
    format!("{hash:016x}")
}

/// Writes integer literals' swizzles, `2.xx`, as `(2).xx`: HLSL compilers accept the first,
/// glslang only the second. Float literals' (`0.5.xx`) and names' are left as they are; line
/// numbers do not change.
fn fix_literal_swizzles(text: &str) -> String {
    let bytes = text.as_bytes();
    let is_word = |b: u8| b.is_ascii_alphanumeric() || b == b'_' || b == b'.';
    let mut out = String::with_capacity(text.len());
    let mut copied = 0;
    let mut i = 0;
    while i < bytes.len() {
        let starts_number = bytes[i].is_ascii_digit() && (i == 0 || !is_word(bytes[i - 1]));
        if !starts_number {
            i += 1;
            continue;
        }
        let digits_end = i + bytes[i..].iter().take_while(|b| b.is_ascii_digit()).count();
        let swizzle = bytes[digits_end + 1..]
            .iter()
            .take_while(|b| b"xyzwrgba".contains(b))
            .count();
        let after = digits_end + 1 + swizzle;
        let is_swizzle = bytes.get(digits_end) == Some(&b'.')
            && (1..=4).contains(&swizzle)
            && bytes
                .get(after)
                .is_none_or(|&b| !(b.is_ascii_alphanumeric() || b == b'_'));
        if is_swizzle {
            out.push_str(&text[copied..i]);
            out.push('(');
            out.push_str(&text[i..digits_end]);
            out.push(')');
            copied = digits_end;
        }
        i = digits_end;
    }
    out.push_str(&text[copied..]);
    out
}

/// The compiler, checked to run: an error naming the tool and its package where it does not.
pub fn compiler() -> Result<(PathBuf, String)> {
    let path = std::env::var_os(COMPILER_VARIABLE)
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(COMPILER));
    let output = Command::new(&path).arg("--version").output().map_err(|e| {
        anyhow!(
            "cannot run {} ({e}): the XeGTAO peer compiles its HLSL with glslangValidator; \
             install it (Debian and Ubuntu package `glslang-tools`), set ${COMPILER_VARIABLE} \
             to its path, or point --peer at a folder `aokit peer compile` wrote on a machine \
             that has it",
            path.display()
        )
    })?;
    let version = String::from_utf8_lossy(&output.stdout)
        .lines()
        .next()
        .unwrap_or_default()
        .trim()
        .to_string();
    Ok((path, version))
}

/// The user's sources beside aokit's wrapper in a temporary folder, ready to compile.
pub struct Prepared {
    dir: tempfile::TempDir,
    compiler: PathBuf,
    /// The compiler's version line.
    pub compiler_version: String,
}

impl Prepared {
    /// Copies the files from `sources`, the folder holding XeGTAO.h and XeGTAO.hlsli.
    pub fn new(sources: &Path) -> Result<Self> {
        let (compiler, compiler_version) = compiler()?;
        let dir = tempfile::tempdir().context("cannot make a temporary folder")?;
        for name in SOURCE_FILES {
            let path = sources.join(name);
            let text = std::fs::read_to_string(&path)
                .with_context(|| format!("cannot read {}", path.display()))?;
            std::fs::write(dir.path().join(name), fix_literal_swizzles(&text))?;
        }
        std::fs::write(dir.path().join(WRAPPER_FILE), WRAPPER)?;
        Ok(Self {
            dir,
            compiler,
            compiler_version,
        })
    }

    /// Compiles `entry` to SPIR-V words, its write-only images marked so.
    pub fn compile(&self, entry: Entry) -> Result<Vec<u32>> {
        let output_path = self.dir.path().join(entry.file_name());
        let output = Command::new(&self.compiler)
            .current_dir(self.dir.path())
            .args(["-V", "-D", "-S", "comp", "-e", entry.entry_point()])
            .args(entry.defines())
            .arg("-o")
            .arg(&output_path)
            .arg(WRAPPER_FILE)
            .output()
            .with_context(|| format!("cannot run {}", self.compiler.display()))?;
        if !output.status.success() {
            // glslang reports on stdout; line numbers are those of the user's files.
            let report = [output.stdout, output.stderr]
                .map(|text| String::from_utf8_lossy(&text).trim().to_string())
                .join("\n");
            bail!(
                "{} failed on XeGTAO's {} entry ({}):\n{}",
                self.compiler.display(),
                entry.entry_point(),
                self.compiler_version,
                report.trim()
            );
        }
        let bytes = std::fs::read(&output_path)
            .with_context(|| format!("cannot read {}", output_path.display()))?;
        let mut words = spirv::words(&bytes)?;
        spirv::mark_write_only(&mut words, entry.write_only())?;
        Ok(words)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integer_literal_swizzles_get_parentheses() {
        assert_eq!(
            fix_literal_swizzles("a % 2.xx == 0; dot(e, 1.xxxx); 0.5.xx; 2.0.xxx; v12.xy"),
            "a % (2).xx == 0; dot(e, (1).xxxx); 0.5.xx; 2.0.xxx; v12.xy"
        );
        assert_eq!(
            fix_literal_swizzles("16.xyzwx 3.x_ 7.x"),
            "16.xyzwx 3.x_ (7).x"
        );
        assert_eq!(fix_literal_swizzles("1e5 2.f 9."), "1e5 2.f 9.");
    }

    #[test]
    fn module_names_follow_the_entry_and_quality() {
        let names: Vec<String> = Entry::all().into_iter().map(Entry::file_name).collect();
        assert_eq!(
            names,
            [
                "prefilter.spv",
                "main-low.spv",
                "main-medium.spv",
                "main-high.spv",
                "main-ultra.spv",
                "denoise.spv",
                "denoise-last.spv"
            ]
        );
        assert_eq!(wrapper_digest().len(), 16);
    }
}
