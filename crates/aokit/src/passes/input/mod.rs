//! The input stage: the renderer's depth and normals turned into what the kernels read.

pub(crate) mod back_faces;
pub(crate) mod decode_normals;
pub(crate) mod linear_depth;
pub(crate) mod normals_from_depth;
