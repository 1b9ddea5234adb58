//! The WGSL files behind the programs' parts, and their `// requires:` headers, checked
//! against what each file declares and uses in every program of [`ALL`](super::ALL).
//!
//! A header names, by path under `shaders/`, the files a file is written against, which every
//! program holding it must hold too: it uses their declarations, or supplies hooks they use (a
//! pass file's `AXIS` in `hbao_separable.wgsl`). `a | b` names alternatives, of which a program
//! holds one (the kinds of depth input, say). WGSL declarations are seen module-wide, so a
//! required file may come after (the two-channel formats follow the passes that write them). A
//! file may also use a hook that a file requiring it supplies (a method's `estimate` in
//! `common/ao_entry.wgsl`), which is in no header, since that file is written against it.
//!
//! Names are found by a token scan, not a parser: a local that shares a global's name of
//! another part counts as a use of it, which can only ask for a header line too many.

use std::collections::{BTreeSet, HashMap};
use std::path::Path;

use super::{ALL, ShaderSource};

/// One WGSL file: its path under `shaders/`, its header and its names.
struct Part {
    path: String,
    /// Each requirement, as its alternatives.
    requires: Vec<Vec<String>>,
    /// Names declared at module scope.
    declares: BTreeSet<String>,
    /// Every identifier outside comments, but the names of struct members and of fields after a
    /// `.`.
    uses: BTreeSet<String>,
}

impl Part {
    fn new(path: String, text: &str) -> Self {
        let requires = text
            .lines()
            .take_while(|line| line.starts_with("//"))
            .filter_map(|line| line.strip_prefix("// requires:"))
            .flat_map(|list| list.split(','))
            .map(|alternatives| {
                alternatives
                    .split('|')
                    .map(|path| path.trim().to_string())
                    .collect()
            })
            .collect();
        let (declares, uses) = names(text);
        Self {
            path,
            requires,
            declares,
            uses,
        }
    }
}

/// The module-scope declarations and the identifiers used in `text`, by a token scan: WGSL
/// declares at module scope with a keyword and a name, so brace depth 0 tells them apart from
/// locals.
fn names(text: &str) -> (BTreeSet<String>, BTreeSet<String>) {
    let code: String = text
        .lines()
        .map(|line| line.split("//").next().unwrap_or_default())
        .collect::<Vec<_>>()
        .join("\n");
    let mut declares = BTreeSet::new();
    let mut uses = BTreeSet::new();
    let mut depth = 0;
    let mut previous = String::new();
    let mut declaring = false;
    let mut in_struct = false;
    let mut chars = code.char_indices().peekable();
    while let Some((start, c)) = chars.next() {
        if c.is_ascii_alphabetic() || c == '_' {
            let mut end = start + c.len_utf8();
            while let Some(&(i, next)) = chars.peek() {
                if !(next.is_ascii_alphanumeric() || next == '_') {
                    break;
                }
                end = i + next.len_utf8();
                chars.next();
            }
            let word = &code[start..end];
            if declaring {
                declares.insert(word.to_string());
                declaring = false;
            } else if depth == 0
                && matches!(
                    word,
                    "fn" | "struct" | "alias" | "const" | "override" | "var"
                )
            {
                declaring = true;
                in_struct = word == "struct";
            } else if previous != "."
                && !(in_struct && depth == 1 && code[end..].trim_start().starts_with(':'))
            {
                uses.insert(word.to_string());
            }
            previous = word.to_string();
        } else if !c.is_whitespace() {
            match c {
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    in_struct &= depth > 0;
                }
                // `var<uniform> name`: the name comes after the address space.
                '<' if declaring && previous == "var" => {
                    for (_, next) in chars.by_ref() {
                        if next == '>' {
                            break;
                        }
                    }
                }
                _ => {}
            }
            previous = c.to_string();
        }
    }
    (declares, uses)
}

/// Every WGSL file under `shaders/`, by its text, which is how a program's parts name them.
fn files() -> HashMap<String, Part> {
    fn walk(root: &Path, dir: &Path, files: &mut HashMap<String, Part>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                walk(root, &path, files);
            } else if path.extension().is_some_and(|e| e == "wgsl") {
                let text = std::fs::read_to_string(&path).unwrap();
                // Headers write paths with `/` on every platform.
                let name = path
                    .strip_prefix(root)
                    .unwrap()
                    .to_string_lossy()
                    .replace('\\', "/");
                let part = Part::new(name, &text);
                assert!(
                    files.insert(text, part).is_none(),
                    "{} has a twin",
                    path.display()
                );
            }
        }
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("shaders");
    let mut files = HashMap::new();
    walk(&root, &root, &mut files);
    files
}

/// What is wrong with the headers of `program`'s parts, `files` by text.
fn check(program: &ShaderSource, files: &HashMap<String, Part>) -> Vec<String> {
    let Some(parts) = program
        .parts
        .iter()
        .map(|text| files.get(*text))
        .collect::<Option<Vec<_>>>()
    else {
        return vec![format!("{}: a part is in no .wgsl file", program.name)];
    };
    let mut errors = Vec::new();
    for (i, part) in parts.iter().enumerate() {
        let error = |message: String| format!("{} in {}: {message}", part.path, program.name);
        // The files this one draws on: the alternative each requirement takes here...
        let mut sources = Vec::new();
        for alternatives in &part.requires {
            match parts.iter().find(|p| alternatives.contains(&p.path)) {
                Some(required) => sources.push(*required),
                None => errors.push(error(format!("requires {alternatives:?}, not in it"))),
            }
        }
        for required in &sources {
            if part.uses.is_disjoint(&required.declares)
                && required.uses.is_disjoint(&part.declares)
            {
                errors.push(error(format!(
                    "requires {}, but neither uses the other",
                    required.path
                )));
            }
        }
        // ...and the files that require it, which may supply hooks.
        let dependents = parts
            .iter()
            .copied()
            .filter(|p| p.requires.iter().any(|a| a.contains(&part.path)));
        let known: BTreeSet<&String> = sources
            .iter()
            .copied()
            .chain(dependents)
            .flat_map(|p| &p.declares)
            .chain(&part.declares)
            .collect();
        for other in parts[..i].iter().chain(&parts[i + 1..]) {
            for name in other.declares.intersection(&part.uses) {
                if !known.contains(name) {
                    errors.push(error(format!(
                        "uses `{name}` of {}, not required",
                        other.path
                    )));
                }
            }
        }
    }
    errors
}

#[test]
fn every_part_is_a_file_and_its_header_names_what_it_uses() {
    let files = files();
    let errors: Vec<String> = ALL
        .iter()
        .flat_map(|program| check(program, &files))
        .collect::<BTreeSet<_>>()
        .into_iter()
        .collect();
    assert!(errors.is_empty(), "{}", errors.join("\n"));
}

#[test]
fn every_wgsl_file_is_part_of_a_validated_program() {
    for (text, part) in files() {
        assert!(
            ALL.iter().any(|s| s.parts.contains(&text.as_str())),
            "shaders/{} is in no program of shader::ALL, so nothing validates it",
            part.path
        );
    }
}

#[test]
fn the_scan_finds_declarations_and_uses() {
    let (declares, uses) = names(
        "// fn commented() {}
struct S { member: f32, other: T }
@group(0) @binding(0) var<uniform> settings: S;
alias T = texture_2d<f32>;
fn f(x: f32) -> f32 { let y = settings.member; return g(x) + y; }",
    );
    let set = |names: &[&str]| names.iter().map(|n| n.to_string()).collect::<BTreeSet<_>>();
    assert_eq!(declares, set(&["S", "T", "f", "settings"]));
    assert!(
        ["g", "settings", "S", "T"]
            .iter()
            .all(|n| uses.contains(*n))
    );
    assert!(
        ["member", "other", "commented"]
            .iter()
            .all(|n| !uses.contains(*n))
    );
}
