//! The settings panel, generated from [`aokit::settings::SETTINGS`]: one widget per declared
//! setting, grouped by the key's prefix, bounded by the declared range, with the help as a
//! tooltip; and the settings written out as flags or TOML.
//!
//! The mapping from a declaration to a widget ([`widget_for`]) and the text written out
//! ([`flags`], [`toml_text`]) are pure functions, tested without a window.

use aokit::settings::{FloatRange, SETTINGS, SettingKind, SettingSpec, SettingValue};
use aokit::{AoSettings, Method, Preset};

/// The widget a setting gets, with the bounds it allows.
#[derive(Clone, Debug, PartialEq)]
pub enum Widget {
    /// A check box.
    Check,
    /// A slider over whole numbers from `min` to `max` in steps of `step`.
    IntSlider {
        /// Smallest value.
        min: u32,
        /// Largest value.
        max: u32,
        /// Spacing of the values from `min`.
        step: u32,
    },
    /// A slider over `min..=max`, both values the setting accepts.
    FloatSlider {
        /// Smallest value the slider reaches.
        min: f32,
        /// Largest value the slider reaches.
        max: f32,
    },
    /// A number dragged from `min` upwards, for ranges without an upper end (or whose upper
    /// end is another setting's 0, meaning none).
    FloatDrag {
        /// Smallest value the drag reaches.
        min: f32,
    },
    /// A menu of these names.
    Combo(&'static [&'static str]),
}

impl Widget {
    /// One word for the widget and its bounds, as `aokit view --panel-layout` prints it:
    /// `check`, `int-slider 1..=64 step 1`, `float-slider 0..=1`, `float-drag 0.0001..`,
    /// `combo low|medium|high`.
    pub fn describe(&self) -> String {
        match self {
            Widget::Check => "check".to_string(),
            Widget::IntSlider { min, max, step } => format!("int-slider {min}..={max} step {step}"),
            Widget::FloatSlider { min, max } => format!("float-slider {min}..={max}"),
            Widget::FloatDrag { min } => format!("float-drag {min}.."),
            Widget::Combo(names) => format!("combo {}", names.join("|")),
        }
    }
}

/// The panel's settings part as text, one line per setting in the order the panel shows them:
/// group, key and widget ([`Widget::describe`]), tab-separated. `aokit view --panel-layout`
/// prints it, and the CLI tests check it against the declarations without a window.
pub fn layout(settings: &AoSettings) -> String {
    let mut text = String::new();
    for (group, specs) in groups() {
        for spec in specs {
            let widget = widget_for(spec, settings).describe();
            text += &format!("{group}\t{}\t{widget}\n", spec.name);
        }
    }
    text
}

/// The nearest value above `min` an exclusive lower end allows: a slider cannot land on it.
fn open_min(range: &FloatRange) -> f32 {
    if range.min_inclusive {
        range.min
    } else {
        // A step the setting resolves: relative to the bound, at least 1e-4.
        range.min + (range.min.abs() * 1e-3).max(1e-4)
    }
}

/// The widget for `spec` given the other values in `settings` (a float's upper end may be
/// another setting's value). Every value the widget can produce lies in the declared range.
pub fn widget_for(spec: &SettingSpec, settings: &AoSettings) -> Widget {
    match spec.kind {
        SettingKind::Bool => Widget::Check,
        SettingKind::Integer(range) => Widget::IntSlider {
            min: range.min,
            max: range.max,
            step: range.step,
        },
        SettingKind::Choice(names) => Widget::Combo(names),
        SettingKind::Float(range) => {
            let min = open_min(&range);
            match range.max_value(settings) {
                None => Widget::FloatDrag { min },
                Some(max) => {
                    let max = if range.max_inclusive {
                        max
                    } else {
                        max - (max.abs() * 1e-3).max(1e-4)
                    };
                    Widget::FloatSlider {
                        min,
                        max: max.max(min),
                    }
                }
            }
        }
    }
}

/// The group a setting belongs to: its section (`gtao` for `gtao.slice_count`), `general` for a
/// key without one.
pub fn group_of(spec: &SettingSpec) -> &'static str {
    spec.section().unwrap_or("general")
}

/// The groups in the order their first setting is declared, each with its settings.
pub fn groups() -> Vec<(&'static str, Vec<&'static SettingSpec>)> {
    let mut groups: Vec<(&'static str, Vec<&'static SettingSpec>)> = Vec::new();
    for spec in SETTINGS {
        let group = group_of(spec);
        match groups.iter_mut().find(|(name, _)| *name == group) {
            Some((_, specs)) => specs.push(spec),
            None => groups.push((group, vec![spec])),
        }
    }
    groups
}

/// The settings `method` at `preset` start from in the viewer: the preset with the scene's
/// radius and, since the frames follow each other, the temporal filter on, as
/// `aokit render --frames N` makes them.
pub fn base_settings(method: Method, preset: Preset, radius: Option<f32>) -> AoSettings {
    let mut settings = AoSettings::preset(method, preset);
    settings.radius = radius.unwrap_or(settings.radius);
    settings.temporal.enabled = true;
    settings
}

/// `settings` as flags of `aokit render` and the other commands: `--method` and `--preset`,
/// then `--set key=value` for each setting that differs from `base` (what those flags give).
pub fn flags(settings: &AoSettings, preset: Preset, base: &AoSettings) -> String {
    let mut parts = vec![
        format!("--method {}", settings.method.name()),
        format!("--preset {}", preset.name()),
    ];
    for spec in SETTINGS {
        let value = spec.get(settings);
        if spec.name != "method" && value != spec.get(base) {
            parts.push(format!("--set {}={}", spec.name, value));
        }
    }
    parts.join(" ")
}

/// `settings` as a complete TOML settings file (`--settings FILE.toml`).
pub fn toml_text(settings: &AoSettings) -> String {
    toml::to_string(settings).unwrap_or_else(|e| format!("# cannot write TOML: {e}\n"))
}

/// What one frame of the panel changed.
#[derive(Default)]
pub struct PanelChange {
    /// A setting was set (and passed its checks).
    pub settings: bool,
    /// A setting was refused by its rule: the message to show.
    pub refused: Option<String>,
}

/// Draws one setting's widget for `spec` in `ui`, labelled by the key's last part with the help
/// as a tooltip, and sets the value through [`SettingSpec::set`], which checks the range and
/// any rule tying it to another setting; a refused value leaves `settings` as it was.
pub fn setting_ui(
    ui: &mut egui::Ui,
    spec: &SettingSpec,
    settings: &mut AoSettings,
    change: &mut PanelChange,
) {
    let label = spec.name.rsplit('.').next().unwrap_or(spec.name);
    let help = spec.help;
    let before = spec.get(settings);
    let mut after = before;
    ui.horizontal(|ui| {
        let response = match (widget_for(spec, settings), before) {
            (Widget::Check, SettingValue::Bool(mut on)) => {
                let r = ui.checkbox(&mut on, label);
                after = SettingValue::Bool(on);
                r
            }
            (Widget::IntSlider { min, max, step }, SettingValue::Integer(mut v)) => {
                let r = ui.add(
                    egui::Slider::new(&mut v, min..=max)
                        .step_by(step as f64)
                        .text(label),
                );
                after = SettingValue::Integer(v);
                r
            }
            (Widget::FloatSlider { min, max }, SettingValue::Float(mut v)) => {
                let r = ui.add(egui::Slider::new(&mut v, min..=max).text(label));
                after = SettingValue::Float(v);
                r
            }
            (Widget::FloatDrag { min }, SettingValue::Float(mut v)) => {
                let speed = (v.abs() * 0.01).max(0.001);
                let r = ui.add(
                    egui::DragValue::new(&mut v)
                        .range(min..=f32::MAX)
                        .speed(speed),
                );
                ui.label(label);
                after = SettingValue::Float(v);
                r
            }
            (Widget::Combo(names), SettingValue::Choice(mut current)) => {
                let r = egui::ComboBox::new(spec.name, label)
                    .selected_text(current)
                    .show_ui(ui, |ui| {
                        for &name in names {
                            ui.selectable_value(&mut current, name, name);
                        }
                    })
                    .response;
                after = SettingValue::Choice(current);
                r
            }
            (_, value) => ui.label(format!("{label} = {value}")),
        };
        response.on_hover_text(format!("{}\n\n{help}", spec.name));
    });
    if after != before {
        match spec.set(settings, after) {
            Ok(()) => change.settings = true,
            Err(e) => change.refused = Some(e.to_string()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use aokit::settings::{IntegerRange, find_setting};

    /// The values a widget can produce at its ends, as setting values.
    fn ends(widget: &Widget) -> Vec<SettingValue> {
        match *widget {
            Widget::Check => vec![SettingValue::Bool(false), SettingValue::Bool(true)],
            Widget::IntSlider { min, max, .. } => {
                vec![SettingValue::Integer(min), SettingValue::Integer(max)]
            }
            Widget::FloatSlider { min, max } => {
                vec![SettingValue::Float(min), SettingValue::Float(max)]
            }
            Widget::FloatDrag { min } => vec![SettingValue::Float(min), SettingValue::Float(1e6)],
            Widget::Combo(names) => names.iter().map(|&n| SettingValue::Choice(n)).collect(),
        }
    }

    #[test]
    fn every_setting_maps_to_a_widget_with_its_declared_bounds() {
        for method in Method::ALL {
            let settings = AoSettings::preset(method, Preset::Medium);
            for spec in SETTINGS {
                let widget = widget_for(spec, &settings);
                match (spec.kind, &widget) {
                    (SettingKind::Bool, Widget::Check) => {}
                    (SettingKind::Integer(IntegerRange { min, max, step }), w) => {
                        assert_eq!(*w, Widget::IntSlider { min, max, step }, "{}", spec.name)
                    }
                    (SettingKind::Choice(names), Widget::Combo(offered)) => {
                        assert_eq!(names, *offered, "{}", spec.name)
                    }
                    (SettingKind::Float(range), Widget::FloatSlider { min, max }) => {
                        assert!(min <= max, "{}", spec.name);
                        assert!(range.contains(*min, &settings), "{} {min}", spec.name);
                        assert!(range.contains(*max, &settings), "{} {max}", spec.name);
                    }
                    (SettingKind::Float(range), Widget::FloatDrag { min }) => {
                        assert!(range.contains(*min, &settings), "{} {min}", spec.name);
                        assert_eq!(range.max_value(&settings), None, "{}", spec.name);
                    }
                    (kind, widget) => panic!("{}: {kind:?} got {widget:?}", spec.name),
                }
                // Each end of the widget passes the range check of `set` (rules tying settings
                // together may still refuse a value, and the panel then keeps the old one).
                for value in ends(&widget) {
                    let mut next = settings;
                    if let Err(e) = spec.set(&mut next, value) {
                        assert!(
                            !e.to_string().contains("out of range:")
                                || e.to_string().contains(" with "),
                            "{}: {e}",
                            spec.name
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn open_ends_are_kept_out_of_the_sliders() {
        let settings = AoSettings::default();
        // radius > 0: the drag starts above 0.
        let Widget::FloatDrag { min } = widget_for(find_setting("radius").unwrap(), &settings)
        else {
            panic!("radius has no upper end")
        };
        assert!(min > 0.0);
        // temporal.blend in [0, 1): the slider stops short of 1.
        let Widget::FloatSlider { min, max } =
            widget_for(find_setting("temporal.blend").unwrap(), &settings)
        else {
            panic!("temporal.blend is bounded")
        };
        assert_eq!(min, 0.0);
        assert!(max < 1.0 && max > 0.99);
    }

    #[test]
    fn groups_follow_the_key_prefixes_and_cover_every_setting() {
        let group = |key| group_of(aokit::settings::find_setting(key).unwrap());
        assert_eq!(group("gtao.slice_count"), "gtao");
        assert_eq!(group("radius"), "general");
        let groups = groups();
        assert_eq!(groups[0].0, "general");
        assert!(groups.iter().any(|(name, _)| *name == "gtao"));
        let count: usize = groups.iter().map(|(_, specs)| specs.len()).sum();
        assert_eq!(count, SETTINGS.len());
        for (name, specs) in &groups {
            assert!(specs.iter().all(|spec| group_of(spec) == *name));
        }
    }

    /// A harness (egui_kittest: no window, the widgets found by their accessible labels)
    /// drawing the widget of the setting `name` over default settings.
    fn widget_of(name: &'static str) -> egui_kittest::Harness<'static, (AoSettings, PanelChange)> {
        let spec = aokit::settings::find_setting(name).unwrap();
        egui_kittest::Harness::new_ui_state(
            move |ui, (settings, change): &mut (AoSettings, PanelChange)| {
                setting_ui(ui, spec, settings, change);
            },
            (AoSettings::default(), PanelChange::default()),
        )
    }

    #[test]
    fn clicking_a_widget_sets_its_setting_through_the_declaration() {
        use egui_kittest::kittest::Queryable;
        let mut check = widget_of("spatial.enabled");
        check.get_by_label("enabled").click();
        check.run();
        let (settings, change) = check.state();
        assert!(!settings.spatial.enabled);
        assert!(change.settings && change.refused.is_none());

        let mut menu = widget_of("noise.kind");
        menu.get_by_label("kind").click();
        menu.run();
        menu.get_by_label("white").click();
        menu.run();
        let (settings, change) = menu.state();
        assert_eq!(settings.noise.kind, aokit::NoiseKind::White);
        assert!(change.settings);
    }

    #[test]
    fn flags_name_only_what_differs_from_the_preset_and_parse_back() {
        let base = base_settings(Method::Gtao, Preset::High, Some(0.5));
        assert_eq!(
            flags(&base, Preset::High, &base),
            "--method gtao --preset high"
        );
        let mut settings = base;
        settings.gtao.slice_count = 7;
        settings.radius = 0.75;
        let text = flags(&settings, Preset::High, &base);
        assert_eq!(
            text,
            "--method gtao --preset high --set radius=0.75 --set gtao.slice_count=7"
        );
        // What `aokit render --frames N` would make of them.
        let args = crate::settings_args::OverrideArgs {
            settings: None,
            set: vec!["radius=0.75".into(), "gtao.slice_count=7".into()],
        };
        let parsed = args
            .apply_to_sequence_preset(Method::Gtao, Preset::High, Some(0.5), None)
            .unwrap();
        assert_eq!(parsed, settings);
    }

    #[test]
    fn toml_is_a_settings_file_that_reads_back() {
        let mut settings = AoSettings::preset(Method::Hbao, Preset::Low);
        settings.intensity = 1.5;
        let text = toml_text(&settings);
        let back: AoSettings = toml::from_str(&text).unwrap();
        assert_eq!(back, settings);
    }
}
