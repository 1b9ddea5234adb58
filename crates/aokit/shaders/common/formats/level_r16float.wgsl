// The depth MIP levels stored as `R16Float`.
alias LevelTexture = texture_storage_2d<r16float, write>;
