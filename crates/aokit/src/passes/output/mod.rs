//! The output stage: what is applied to the final AO.

pub(crate) mod mask;
