//! Settings from the arguments of `Context.ao`: a method at a preset, the radius and dotted
//! keys, each set with [`AoSettings::set`] (the checks and error text of `aokit ao --set`).

use aokit::settings::{SETTINGS, SetError, SettingValue, find_setting, suggest_setting};
use aokit::{AoSettings, Method, NormalSpace, Preset};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};

/// What the arguments resolve to: the settings, and the space the normals come in.
pub struct Resolved {
    /// Checked settings.
    pub settings: AoSettings,
    /// `normals.space` as resolved (the `normal_space` argument, or the settings' key).
    pub normal_space: NormalSpace,
}

/// A ValueError with `error`'s text.
fn set_error(error: SetError) -> PyErr {
    PyValueError::new_err(error.to_string())
}

/// A Python value for the setting `key`: bool, int, float (NumPy scalars too) or str. Each is
/// read from the text `--set` would be given for it (`True` as `true`, `0.25` as `0.25`), so a
/// value of the wrong kind or out of range fails with the text `aokit ao --set` prints.
fn setting_value(key: &str, value: &Bound<'_, PyAny>) -> PyResult<SettingValue> {
    let spec = find_setting(key).ok_or_else(|| {
        set_error(SetError::UnknownKey {
            key: key.to_string(),
            suggestion: suggest_setting(key),
        })
    })?;
    let text = if let Ok(text) = value.cast::<PyString>() {
        text.to_cow()?.into_owned()
    } else if let Ok(flag) = value.extract::<bool>() {
        flag.to_string()
    } else if let Ok(integer) = value.extract::<i64>() {
        integer.to_string()
    } else if let Ok(number) = value.extract::<f64>() {
        // Python's shortest round-trip text, as an f-string would put it on a command line.
        number.to_string()
    } else {
        return Err(PyTypeError::new_err(format!(
            "settings[{key:?}]: expected bool, int, float or str, not {}",
            value.get_type().name()?
        )));
    };
    spec.parse(&text).map_err(set_error)
}

/// Resolves the arguments as `aokit ao` resolves its flags: the preset (VBAO's tuned with
/// back faces where the overrides turn them on), then `normal_space`, then `radius`, then each
/// of `overrides` in order, checked.
pub fn resolve(
    method: &str,
    preset: &str,
    radius: Option<f32>,
    overrides: Option<&Bound<'_, PyDict>>,
    normal_space: Option<&str>,
) -> PyResult<Resolved> {
    let method: Method = method
        .parse()
        .map_err(|e: String| PyValueError::new_err(format!("method: {e}")))?;
    let preset: Preset = preset
        .parse()
        .map_err(|e: String| PyValueError::new_err(format!("preset: {e}")))?;
    let apply = |mut settings: AoSettings| -> PyResult<AoSettings> {
        if let Some(space) = normal_space {
            let value = find_setting("normals.space")
                .expect("normals.space is declared")
                .parse(space)
                .map_err(|e| PyValueError::new_err(format!("normal_space: {e}")))?;
            settings.set("normals.space", value).map_err(set_error)?;
        }
        if let Some(radius) = radius {
            settings
                .set("radius", SettingValue::Float(radius))
                .map_err(set_error)?;
        }
        for (key, value) in overrides.into_iter().flat_map(|d| d.iter()) {
            let key: String = key
                .extract()
                .map_err(|_| PyTypeError::new_err("settings: keys must be str"))?;
            let value = setting_value(&key, &value)?;
            settings.set(&key, value).map_err(set_error)?;
        }
        settings
            .validate()
            .map_err(|e| PyValueError::new_err(e.to_string()))?;
        Ok(settings)
    };
    let mut settings = apply(AoSettings::preset(method, preset))?;
    if settings.method == Method::Vbao && settings.vbao.back_faces {
        settings = apply(AoSettings::preset_with_back_faces(Method::Vbao, preset))?;
    }
    Ok(Resolved {
        normal_space: settings.normals.space,
        settings,
    })
}

/// The value of every setting, by dotted key, that `method`, `preset`, `radius` and `settings`
/// resolve to (what `Context.ao` would run).
#[pyfunction]
#[pyo3(signature = (method = "gtao", preset = "high", radius = None, settings = None))]
pub fn resolve_settings<'py>(
    py: Python<'py>,
    method: &str,
    preset: &str,
    radius: Option<f32>,
    settings: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let resolved = resolve(method, preset, radius, settings, None)?.settings;
    let out = PyDict::new(py);
    for spec in SETTINGS {
        match spec.get(&resolved) {
            SettingValue::Bool(v) => out.set_item(spec.name, v)?,
            SettingValue::Integer(v) => out.set_item(spec.name, v)?,
            SettingValue::Float(v) => out.set_item(spec.name, v)?,
            SettingValue::Choice(v) => out.set_item(spec.name, v)?,
        }
    }
    Ok(out)
}

/// Every setting: `(key, type, range, help)`, as `aokit settings` lists them.
#[pyfunction]
pub fn setting_names() -> Vec<(&'static str, &'static str, String, &'static str)> {
    SETTINGS
        .iter()
        .map(|spec| {
            (
                spec.name,
                spec.kind.type_name(),
                spec.kind.range_text(),
                spec.help,
            )
        })
        .collect()
}
