// The storage type of a two-channel float target as `Rgba32Float`, for adapters that cannot
// write `Rg32Float`.
alias pair_storage = texture_storage_2d<rgba32float, write>;
