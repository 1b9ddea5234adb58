// The storage type of a two-channel float target as `Rg32Float`.
alias pair_storage = texture_storage_2d<rg32float, write>;
