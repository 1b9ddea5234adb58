// The depth MIP levels stored as `R32Float`.
alias LevelTexture = texture_storage_2d<r32float, write>;
