//! Which EXR channels hold the depth, the normals or the AO.
//!
//! Renderers name channels differently: aokit writes `Z` or `Y`, Blender writes `Z`, `Depth.V`
//! or `ViewLayer.Depth.Z` next to `ViewLayer.Normal.X` and `ViewLayer.Vector.Z`. The rules rank
//! candidate names so the intended channel wins and a genuine tie is reported instead of guessed.

/// The outcome of looking for a channel (or channel group) among one layer's names.
#[derive(Debug, PartialEq, Eq)]
pub(crate) enum Pick<T> {
    /// Nothing in this layer matches.
    None,
    /// The best match.
    One(T),
    /// Several matches rank equally; their indices.
    Tie(Vec<usize>),
}

/// The part after the last `.`, which names the channel inside a layer-qualified name.
fn suffix(name: &str) -> &str {
    name.rsplit_once('.').map_or(name, |(_, s)| s)
}

/// AO or reference files: `Y`, else `R` (plain or layer-qualified).
pub(crate) fn scalar_rank(name: &str) -> u8 {
    match suffix(name) {
        "Y" => 2,
        "R" => 1,
        _ => 0,
    }
}

/// Depth files. A name counts when its last part is Y, R, Z, V or depth (any case). Among those,
/// a bare `Z` or any name with a `depth` part (Blender's `Depth.V`, `ViewLayer.Depth.Z`) ranks
/// first, other bare names next, other qualified names (such as `Normal.Z`) last.
pub(crate) fn depth_rank(name: &str) -> u8 {
    let lower = name.to_ascii_lowercase();
    if !matches!(suffix(&lower), "y" | "r" | "z" | "v" | "depth") {
        return 0;
    }
    let qualified = lower.contains('.');
    if lower == "z" || lower.split('.').any(|part| part == "depth") {
        3
    } else if !qualified {
        2
    } else {
        1
    }
}

/// The best-ranked name of one layer; rank 0 means "not a candidate".
pub(crate) fn pick_by_rank<'a>(
    names: impl IntoIterator<Item = &'a str>,
    rank: fn(&str) -> u8,
) -> Pick<usize> {
    let ranks: Vec<u8> = names.into_iter().map(rank).collect();
    let best = ranks.iter().copied().max().unwrap_or(0);
    if best == 0 {
        return Pick::None;
    }
    let top: Vec<usize> = (0..ranks.len()).filter(|&i| ranks[i] == best).collect();
    match top.as_slice() {
        [one] => Pick::One(*one),
        _ => Pick::Tie(top),
    }
}

/// Normals: three channels sharing a prefix and ending in X, Y, Z or R, G, B. A prefix that
/// mentions "normal" ranks first, then no prefix, then any other; XYZ beats RGB under one prefix.
/// Returns the indices of the x, y and z channels.
pub(crate) fn pick_normals(names: &[&str]) -> Pick<[usize; 3]> {
    let find = |prefix: &str, letter: &str| {
        names.iter().position(|name| {
            let (p, s) = name.rsplit_once('.').unwrap_or(("", name));
            p == prefix && s.eq_ignore_ascii_case(letter)
        })
    };
    let mut groups: Vec<(u8, [usize; 3])> = Vec::new();
    let mut prefixes: Vec<&str> = names
        .iter()
        .map(|n| n.rsplit_once('.').map_or("", |(p, _)| p))
        .collect();
    prefixes.sort_unstable();
    prefixes.dedup();
    for prefix in prefixes {
        let group = |letters: [&str; 3]| -> Option<[usize; 3]> {
            Some([
                find(prefix, letters[0])?,
                find(prefix, letters[1])?,
                find(prefix, letters[2])?,
            ])
        };
        if let Some(indices) = group(["X", "Y", "Z"]).or_else(|| group(["R", "G", "B"])) {
            let rank = if prefix.to_ascii_lowercase().contains("normal") {
                3
            } else if prefix.is_empty() {
                2
            } else {
                1
            };
            groups.push((rank, indices));
        }
    }
    let Some(best) = groups.iter().map(|g| g.0).max() else {
        return Pick::None;
    };
    let top: Vec<[usize; 3]> = groups
        .into_iter()
        .filter(|g| g.0 == best)
        .map(|g| g.1)
        .collect();
    match top.as_slice() {
        [one] => Pick::One(*one),
        _ => Pick::Tie(top.iter().flatten().copied().collect()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn depth_prefers_named_depth_over_other_z_channels() {
        let names = [
            "ViewLayer.Combined.R",
            "ViewLayer.Depth.Z",
            "ViewLayer.Normal.Z",
            "ViewLayer.Vector.Z",
        ];
        assert_eq!(pick_by_rank(names, depth_rank), Pick::One(1));
        assert_eq!(
            pick_by_rank(["A", "B", "G", "R", "Z"], depth_rank),
            Pick::One(4)
        );
        assert_eq!(pick_by_rank(["Depth.V"], depth_rank), Pick::One(0));
        assert_eq!(pick_by_rank(["depth"], depth_rank), Pick::One(0));
        assert_eq!(pick_by_rank(["G", "B"], depth_rank), Pick::None);
    }

    #[test]
    fn depth_reports_ties() {
        assert_eq!(
            pick_by_rank(["Normal.X", "Normal.Y", "Normal.Z"], depth_rank),
            Pick::Tie(vec![1, 2])
        );
    }

    #[test]
    fn scalar_prefers_y_then_r() {
        assert_eq!(
            pick_by_rank(["B", "G", "R", "Y"], scalar_rank),
            Pick::One(3)
        );
        assert_eq!(pick_by_rank(["B", "G", "R"], scalar_rank), Pick::One(2));
        assert_eq!(pick_by_rank(["A"], scalar_rank), Pick::None);
    }

    #[test]
    fn normals_find_groups() {
        assert_eq!(pick_normals(&["B", "G", "R"]), Pick::One([2, 1, 0]));
        assert_eq!(pick_normals(&["X", "Y", "Z"]), Pick::One([0, 1, 2]));
        let blender = [
            "ViewLayer.Combined.B",
            "ViewLayer.Combined.G",
            "ViewLayer.Combined.R",
            "ViewLayer.Normal.X",
            "ViewLayer.Normal.Y",
            "ViewLayer.Normal.Z",
            "ViewLayer.Vector.X",
            "ViewLayer.Vector.Y",
            "ViewLayer.Vector.Z",
        ];
        assert_eq!(pick_normals(&blender), Pick::One([3, 4, 5]));
        assert_eq!(
            pick_normals(&["A.X", "A.Y", "A.Z", "B.X", "B.Y", "B.Z"]),
            Pick::Tie(vec![0, 1, 2, 3, 4, 5])
        );
        assert_eq!(pick_normals(&["R", "G"]), Pick::None);
    }
}
