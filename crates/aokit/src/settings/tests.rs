use super::*;

#[test]
fn presets_are_valid_grow_in_cost_and_cost_the_same_for_every_method() {
    let mut last = 0;
    for preset in Preset::ALL {
        let cost = AoSettings::preset(Method::Gtao, preset).samples_per_pixel();
        assert!(cost > last, "{preset:?}");
        last = cost;
        for method in Method::ALL {
            let s = AoSettings::preset(method, preset);
            s.validate().unwrap();
            assert_eq!(s.samples_per_pixel(), cost, "{method:?} {preset:?}");
        }
    }
}

#[test]
fn bent_normals_need_a_slice_method_and_fades_need_room() {
    let mut s = AoSettings::preset(Method::Ssao, Preset::High);
    s.bent_normals = true;
    assert_eq!(s.validate().unwrap_err().field, "bent_normals");
    s.method = Method::Vbao;
    s.validate().unwrap();
    s.max_distance = 10.0;
    s.distance_falloff = 20.0;
    assert_eq!(s.validate().unwrap_err().field, "distance_falloff");
    s.distance_falloff = 5.0;
    s.validate().unwrap();
}

#[test]
fn out_of_range_values_name_their_field() {
    let field = |s: AoSettings| s.validate().unwrap_err().field;
    let base = AoSettings::default();
    assert_eq!(
        field(AoSettings {
            radius: f32::NAN,
            ..base
        }),
        "radius"
    );
    let mut s = AoSettings::default();
    s.gtao.steps_per_side = 65;
    assert_eq!(s.validate().unwrap_err().field, "gtao.steps_per_side");
    for pairs in [0, MAX_SAMPLE_COUNT + 1] {
        let mut s = AoSettings::preset(Method::Ue4Ssao, Preset::High);
        s.ue4_ssao.sample_count = pairs;
        assert_eq!(s.validate().unwrap_err().field, "ue4_ssao.sample_count");
    }
    assert_eq!(
        field(AoSettings {
            falloff: 1.5,
            ..base
        }),
        "falloff"
    );
    assert_eq!(
        field(AoSettings {
            intensity: -1.0,
            ..base
        }),
        "intensity"
    );
    for depth_mip_offset in [-0.5, 16.5, f32::NAN] {
        assert_eq!(
            field(AoSettings {
                depth_mip_offset,
                ..base
            }),
            "depth_mip_offset"
        );
    }
}

#[test]
fn spatial_settings_out_of_range_name_their_field() {
    let spatial = |spatial| {
        AoSettings {
            spatial,
            ..AoSettings::default()
        }
        .validate()
        .map_err(|e| e.field)
    };
    let base = SpatialSettings {
        enabled: true,
        ..SpatialSettings::default()
    };
    assert_eq!(spatial(base), Ok(()));
    for radius in [0, MAX_SPATIAL_RADIUS + 1] {
        assert_eq!(
            spatial(SpatialSettings { radius, ..base }),
            Err("spatial.radius")
        );
    }
    assert_eq!(
        spatial(SpatialSettings { sigma: 0.0, ..base }),
        Err("spatial.sigma")
    );
    assert_eq!(
        spatial(SpatialSettings {
            depth_sigma: f32::INFINITY,
            ..base
        }),
        Err("spatial.depth_sigma")
    );
    assert_eq!(
        spatial(SpatialSettings {
            normal_power: -1.0,
            ..base
        }),
        Err("spatial.normal_power")
    );
    for guided_epsilon in [0.0, -1e-3, f32::NAN] {
        assert_eq!(
            spatial(SpatialSettings {
                kind: SpatialKind::Guided,
                guided_epsilon,
                ..base
            }),
            Err("spatial.guided_epsilon")
        );
    }
    for guided_radius in [0, MAX_SPATIAL_RADIUS + 1] {
        assert_eq!(
            spatial(SpatialSettings {
                kind: SpatialKind::Guided,
                guided_radius,
                ..base
            }),
            Err("spatial.guided_radius")
        );
    }
    // Checked when off too, so that turning the filter on cannot fail later.
    assert_eq!(
        spatial(SpatialSettings {
            enabled: false,
            radius: 9,
            ..base
        }),
        Err("spatial.radius")
    );
}

#[test]
fn names_parse_back() {
    for m in Method::ALL {
        assert_eq!(m.name().parse::<Method>().unwrap(), m);
    }
    for p in Preset::ALL {
        assert_eq!(p.name().parse::<Preset>().unwrap(), p);
    }
    for e in NormalEncoding::ALL {
        assert_eq!(e.name().parse::<NormalEncoding>().unwrap(), e);
    }
    for k in NoiseKind::ALL {
        assert_eq!(k.name().parse::<NoiseKind>().unwrap(), k);
    }
    for w in DepthWeight::ALL {
        assert_eq!(w.name().parse::<DepthWeight>().unwrap(), w);
    }
    for k in SpatialKind::ALL {
        assert_eq!(k.name().parse::<SpatialKind>().unwrap(), k);
    }
    for r in Resolution::ALL {
        assert_eq!(r.name().parse::<Resolution>().unwrap(), r);
    }
    for d in Downsample::ALL {
        assert_eq!(d.name().parse::<Downsample>().unwrap(), d);
    }
    for u in Upsample::ALL {
        assert_eq!(u.name().parse::<Upsample>().unwrap(), u);
    }
    for f in FilterResolution::ALL {
        assert_eq!(f.name().parse::<FilterResolution>().unwrap(), f);
    }
    for m in SampleDepth::ALL {
        assert_eq!(m.name().parse::<SampleDepth>().unwrap(), m);
    }
    for m in DepthMips::ALL {
        assert_eq!(m.name().parse::<DepthMips>().unwrap(), m);
    }
    assert!("hbao9".parse::<Method>().unwrap_err().contains("gtao"));
}

#[test]
fn the_separable_hbao_variant_is_refused_to_hbao_plus_and_stops_at_its_apron() {
    let mut s = AoSettings::preset(Method::HbaoPlus, Preset::High);
    s.hbao.variant = "separable".parse().unwrap();
    assert_eq!(s.validate().unwrap_err().field, "hbao.variant");
    // Kept but unused by the methods that have no `hbao` block.
    s.method = Method::Gtao;
    s.validate().unwrap();
    assert_eq!(s.effective_max_radius_px(), s.max_radius_px);
    s.method = Method::Hbao;
    s.validate().unwrap();
    assert_eq!(s.samples_per_pixel(), 4 * s.hbao.step_count);
    let apron = SEPARABLE_HBAO_MAX_RADIUS_PX as f32;
    for (resolution, max_radius_px, expected) in [
        (Resolution::Full, 256.0, apron),
        (Resolution::Half, 256.0, 256.0),
        (Resolution::Half, 1000.0, 2.0 * apron),
        (Resolution::Quarter, 1000.0, 4.0 * apron),
        (Resolution::Full, 40.0, 40.0),
    ] {
        let s = AoSettings {
            resolution,
            max_radius_px,
            ..s
        };
        assert_eq!(s.effective_max_radius_px(), expected, "{resolution:?}");
    }
    assert_eq!(
        HbaoVariant::ALL.map(HbaoVariant::name),
        ["per-pixel", "separable"]
    );
    for v in HbaoVariant::ALL {
        assert_eq!(v.name().parse::<HbaoVariant>().unwrap(), v);
    }
}

#[test]
fn validate_names_the_key_the_value_and_the_declared_range() {
    let message = |change: fn(&mut AoSettings)| {
        let mut s = AoSettings::default();
        change(&mut s);
        s.validate().unwrap_err().to_string()
    };
    type Change = fn(&mut AoSettings);
    let cases: [(Change, &str); 12] = [
        (
            |s| s.radius = 0.0,
            "setting `radius` = 0 is out of range: a finite number > 0",
        ),
        (
            |s| s.radius_multiplier = 4.5,
            "setting `radius_multiplier` = 4.5 is out of range: a number in (0, 4]",
        ),
        (
            |s| s.max_radius_px = 0.5,
            "setting `max_radius_px` = 0.5 is out of range: a finite number >= 1",
        ),
        (
            |s| s.min_radius_px = 300.0,
            "setting `min_radius_px` = 300 with max_radius_px = 256 is out of range: a number in \
             [0, max_radius_px]",
        ),
        (
            |s| s.angle_bias = 2.0,
            "setting `angle_bias` = 2 is out of range: a number in [0, pi/2) (radians)",
        ),
        (
            |s| {
                s.max_distance = 10.0;
                s.distance_falloff = 20.0;
            },
            "setting `distance_falloff` = 20 with max_distance = 10 is out of range: a number \
             in [0, max_distance]",
        ),
        (
            |s| s.msvo.sample_count = 7,
            "setting `msvo.sample_count` = 7 is out of range: an even integer in 2..=64",
        ),
        (
            |s| s.msvo.levels = 6,
            "setting `msvo.levels` = 6 is out of range: an integer in 1..=5",
        ),
        (
            |s| s.noise.blue_size = 96,
            "setting `noise.blue_size` = 96 is out of range: 64 or 128",
        ),
        (
            |s| s.temporal.blend = 1.0,
            "setting `temporal.blend` = 1 is out of range: a number in [0, 1)",
        ),
        (
            |s| s.depth_mip_offset = f32::NAN,
            "setting `depth_mip_offset` = NaN is out of range: a number in [0, 16] (log2 pixels)",
        ),
        (
            |s| {
                s.method = Method::HbaoPlus;
                s.hbao.variant = HbaoVariant::Separable;
            },
            "setting `hbao.variant` = separable with method hbao-plus is out of range: per-pixel: \
             the separable passes integrate hbao's horizons, which hbao-plus does not have",
        ),
    ];
    for (change, expected) in cases {
        assert_eq!(message(change), expected);
    }
}

#[test]
fn the_declarations_are_unique_and_their_limits_name_earlier_float_settings() {
    for (i, spec) in SETTINGS.iter().enumerate() {
        assert!(
            SETTINGS[..i].iter().all(|s| s.name != spec.name),
            "{} declared twice",
            spec.name
        );
        assert!(!spec.help.is_empty(), "{}", spec.name);
        if let SettingKind::Float(FloatRange {
            max: Some(Limit::Setting { key, .. }),
            ..
        }) = spec.kind
        {
            let limit = SETTINGS[..i].iter().find(|s| s.name == key);
            assert!(
                matches!(limit.map(|s| s.kind), Some(SettingKind::Float(_))),
                "{}'s limit {key} is not a float setting checked before it",
                spec.name
            );
        }
        if let SettingKind::Choice(names) = spec.kind {
            assert!(names.len() >= 2, "{}", spec.name);
        }
    }
}

#[test]
fn every_setting_reads_back_what_it_sets_and_refuses_other_types() {
    for method in Method::ALL {
        for preset in Preset::ALL {
            let settings = AoSettings::preset(method, preset);
            for spec in SETTINGS {
                let mut copy = settings;
                let value = spec.get(&settings);
                spec.set(&mut copy, value).unwrap();
                assert_eq!(copy, settings, "{}", spec.name);
                assert_eq!(spec.parse(&value.to_string()), Ok(value), "{}", spec.name);
                let other = match value {
                    SettingValue::Bool(_) => SettingValue::Choice("x"),
                    _ => SettingValue::Bool(true),
                };
                assert!(matches!(
                    spec.set(&mut copy, other),
                    Err(SetError::Invalid { .. })
                ));
                assert_eq!(copy, settings, "{}", spec.name);
            }
        }
    }
}

#[test]
fn set_by_key_checks_like_validate_and_suggests_a_key() {
    let mut s = AoSettings::default();
    s.set("spatial.kind", SettingValue::Choice("guided"))
        .unwrap();
    assert_eq!(s.spatial.kind, SpatialKind::Guided);
    // Floats take integers.
    s.set("radius", SettingValue::Integer(2)).unwrap();
    assert_eq!(s.radius, 2.0);
    let err = s
        .set("spatial.guided_epsilon", SettingValue::Float(0.0))
        .unwrap_err();
    assert_eq!(
        err,
        SetError::OutOfRange(SettingsError {
            field: "spatial.guided_epsilon",
            value: "0".into(),
            expected: "a finite number > 0",
        })
    );
    let err = s
        .set("spatial.kind", SettingValue::Choice("box"))
        .unwrap_err();
    assert!(
        err.to_string().contains("bilateral, guided, edges"),
        "{err}"
    );
    assert_eq!(suggest_setting("gtao.steps"), Some("gtao.steps_per_side"));
    assert_eq!(suggest_setting("Radius"), Some("radius"));
    assert_eq!(suggest_setting("zzz"), None);
}
