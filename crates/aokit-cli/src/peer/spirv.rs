//! The one edit aokit makes to glslang's SPIR-V: storage images the shader only writes get
//! `NonReadable`, which HLSL cannot say (its `RWTexture2D` is read-write). Without it naga and
//! wgpu take them as read-write storage, which WebGPU allows for 32-bit formats only.

use anyhow::{Result, bail};

const MAGIC: u32 = 0x0723_0203;
const HEADER_WORDS: usize = 5;
const OP_DECORATE: u32 = 71;
const DECORATION_BINDING: u32 = 33;
const DECORATION_NON_READABLE: u32 = 25;
/// The annotation section's instructions (SPIR-V 1.6, 2.4 "Logical Layout of a Module"):
/// OpDecorate, OpMemberDecorate, OpDecorationGroup, OpGroupDecorate, OpGroupMemberDecorate,
/// OpDecorateId, OpDecorateString, OpMemberDecorateString.
const ANNOTATIONS: [u32; 8] = [71, 72, 73, 74, 75, 332, 5632, 5633];

/// A SPIR-V module's words from its bytes, checked for the magic number.
pub fn words(bytes: &[u8]) -> Result<Vec<u32>> {
    if !bytes.len().is_multiple_of(4) || bytes.len() < 4 * HEADER_WORDS {
        bail!("not SPIR-V: {} bytes", bytes.len());
    }
    let words: Vec<u32> = bytes
        .chunks_exact(4)
        .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        .collect();
    if words[0] != MAGIC {
        bail!("not SPIR-V (magic number {:#010x})", words[0]);
    }
    Ok(words)
}

/// Decorates the variables at `bindings` (in any descriptor set) `NonReadable`; bindings the
/// module lacks are left alone, as the entry point does not use them.
pub fn mark_write_only(words: &mut Vec<u32>, bindings: &[u32]) -> Result<()> {
    let mut ids = Vec::new();
    let mut end_of_annotations = None;
    let mut at = HEADER_WORDS;
    while at < words.len() {
        let (count, opcode) = ((words[at] >> 16) as usize, words[at] & 0xffff);
        if count == 0 || at + count > words.len() {
            bail!("malformed SPIR-V at word {at}");
        }
        if opcode == OP_DECORATE
            && count >= 4
            && words[at + 2] == DECORATION_BINDING
            && bindings.contains(&words[at + 3])
        {
            ids.push(words[at + 1]);
        }
        if ANNOTATIONS.contains(&opcode) {
            end_of_annotations = Some(at + count);
        }
        at += count;
    }
    let Some(end) = end_of_annotations else {
        return Ok(());
    };
    let decorations = ids
        .into_iter()
        .flat_map(|id| [(3 << 16) | OP_DECORATE, id, DECORATION_NON_READABLE]);
    words.splice(end..end, decorations);
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn write_only_bindings_gain_a_decoration_among_the_others() {
        let header = [MAGIC, 0x0001_0000, 0, 100, 0];
        let decorate = |id, decoration, value| [(4 << 16) | OP_DECORATE, id, decoration, value];
        let mut module: Vec<u32> = header.to_vec();
        module.extend(decorate(7, DECORATION_BINDING, 3));
        module.extend(decorate(8, DECORATION_BINDING, 9));
        // OpTypeVoid %1, after the annotations.
        module.extend([(2 << 16) | 19, 1]);
        let bytes: Vec<u8> = module.iter().flat_map(|w| w.to_le_bytes()).collect();
        let mut words = words(&bytes).unwrap();
        mark_write_only(&mut words, &[3]).unwrap();
        let inserted = [(3 << 16) | OP_DECORATE, 7, DECORATION_NON_READABLE];
        assert_eq!(&words[13..16], &inserted);
        assert_eq!(&words[16..], &[(2 << 16) | 19, 1]);
        assert!(super::words(&bytes[..8]).is_err());
        assert!(super::words(&[0u8; 20]).is_err());
    }
}
