//! Settings as `--settings FILE.toml` and `--set KEY=VALUE` give them, through the library
//! pieces the CLI uses: TOML into `AoSettings` then `validate()`, and `SettingSpec::parse` then
//! `AoSettings::set` for each `KEY=VALUE` line after the first NUL byte. Settings that pass
//! `validate()` hold finite numbers, and a value `set` accepts passes its setting's check.
#![no_main]

use aokit::AoSettings;
use aokit::settings::{SETTINGS, SettingValue, find_setting};
use libfuzzer_sys::fuzz_target;

fn check_valid(settings: &AoSettings) {
    for spec in SETTINGS {
        if let SettingValue::Float(v) = spec.get(settings) {
            assert!(v.is_finite(), "{} = {v} passed validate()", spec.name);
        }
    }
    // A validated setting reaches the pipeline's derived quantities without a panic.
    let _ = settings.samples_per_pixel();
    let px = settings.effective_max_radius_px();
    assert!(!px.is_nan(), "effective_max_radius_px {px}");
}

fuzz_target!(|data: &[u8]| {
    let (file, sets) = match data.iter().position(|&b| b == 0) {
        Some(nul) => (&data[..nul], &data[nul + 1..]),
        None => (data, &[][..]),
    };
    let mut settings = AoSettings::default();
    if let Ok(text) = std::str::from_utf8(file)
        && let Ok(parsed) = toml::from_str::<AoSettings>(text)
        && parsed.validate().is_ok()
    {
        check_valid(&parsed);
        settings = parsed;
    }
    for line in String::from_utf8_lossy(sets).lines() {
        let Some((key, text)) = line.split_once('=') else {
            continue;
        };
        let Some(spec) = find_setting(key.trim()) else {
            continue;
        };
        let Ok(value) = spec.parse(text) else {
            continue;
        };
        if settings.set(spec.name, value).is_ok() {
            spec.check(&settings)
                .expect("a value set() accepted passes its check");
            if settings.validate().is_ok() {
                check_valid(&settings);
            }
        }
    }
});
