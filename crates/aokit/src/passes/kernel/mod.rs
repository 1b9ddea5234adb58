//! The kernel stage: a method's AO (and bent normals) at working resolution, and the depth MIP
//! chains the kernels read.

pub(crate) mod depth_mips;
pub(crate) mod method;
pub(crate) mod msvo;
pub(crate) mod separable_hbao;
