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
