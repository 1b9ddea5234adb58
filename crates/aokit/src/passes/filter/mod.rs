//! The filter stage: one spatial filter kind, then the temporal filter.

pub(crate) mod edge_filter;
pub(crate) mod guided_filter;
pub(crate) mod spatial_filter;
pub(crate) mod temporal_filter;
