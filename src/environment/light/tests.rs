use super::*;

/// A 16 x 8 map, black but for one bright texel at `(5, 3)`.
fn one_bright_texel() -> EnvironmentMap {
    let mut texels = vec![Rgb::ZERO; 16 * 8];
    texels[3 * 16 + 5] = Rgb::splat(10.0);
    EnvironmentMap::new("one texel", 16, 8, texels).unwrap()
}

/// The density kept beside each texel is the distribution's own, bit
/// for bit, wherever a direction falls (cell edges, the seam at
/// `u = 0`, near the poles): `escaped` and `pdf_li` read it, and
/// `sample_li` gives the directions it draws the same (to rounding).
/// Fails if the map's cell is found otherwise than the
/// distribution's (a `floor` of `u w - 1/2`, the lookup's own).
#[test]
fn the_density_beside_each_texel_is_the_distributions() {
    let map = EnvironmentMap::from_fn("bands", 16, 8, |d| {
        Rgb::new(1.0 + d.x.max(0.0) * 7.0, 0.5, 2.0 + d.y)
    })
    .unwrap();
    let light = EnvironmentLight::new(map, EnvironmentSampling::Importance);
    let tables = &light.tables;
    let expected = |w: Vec3| {
        let uv = direction_to_uv(w);
        tables.distribution.pdf(uv) / (2.0 * PI * PI * sin_theta(w))
    };
    let mut uvs = vec![Vec2::new(0.0, 0.5), Vec2::new(0.999_999, 0.01)];
    for k in 0..=32 {
        for m in 1..16 {
            // Every cell edge and the points between them.
            uvs.push(Vec2::new(k as f32 / 32.0, m as f32 / 16.0));
        }
    }
    for uv in uvs {
        let w = uv_to_direction(uv);
        assert!(expected(w) > 0.0, "{uv}");
        assert_eq!(light.escaped(w, true).1, expected(w), "{uv}");
        // pdf_li normalises its direction first.
        assert_eq!(light.pdf_li(w), expected(w.normalize()), "{uv}");
    }
    for k in 0..200 {
        let u = Vec2::new((k as f32 * 0.618_034).fract(), (k as f32 + 0.5) / 200.0);
        let s = light.sample_li(u).unwrap();
        let LightPdf::SolidAngle(p) = s.pdf else {
            panic!("{:?}", s.pdf)
        };
        // The same cell's density; sin(theta) of `wi` and of `wi`
        // normalised differ in the last bits.
        let back = light.pdf_li(s.wi);
        assert!((p - back).abs() <= 1e-5 * back, "{u}: {p} against {back}");
    }
}

/// The handout's weights: the texel's luminance times `sin(theta)`, so
/// the bright texel's cell takes every sample and its black
/// neighbour, where the bilinear lookup still shows light, none; the
/// default weights give the neighbour its share.
#[test]
fn texel_weights_are_the_handouts_pdf_envmap() {
    let map = one_bright_texel();
    let centre = |i: f32, j: f32| uv_to_direction(Vec2::new((i + 0.5) / 16.0, (j + 0.5) / 8.0));
    let course = EnvironmentLight::with_weights(
        map.clone(),
        EnvironmentSampling::Importance,
        EnvironmentWeights::Texel,
    );
    let ours = EnvironmentLight::new(map, EnvironmentSampling::Importance);
    assert_eq!(course.weights(), EnvironmentWeights::Texel);
    assert_eq!(ours.weights(), EnvironmentWeights::CellAverage);
    // p(w) = p(u, v) / (2 pi^2 sin theta), p(u, v) = w h for the one cell.
    let sin_theta = (PI * 3.5 / 8.0).sin();
    let expected = 16.0 * 8.0 / (2.0 * PI * PI * sin_theta);
    let bright = course.pdf_li(centre(5.0, 3.0));
    assert!(
        (bright - expected).abs() <= 1e-4 * expected,
        "{bright} against {expected}"
    );
    assert_eq!(course.pdf_li(centre(6.0, 3.0)), 0.0);
    assert!(ours.escaped_radiance(centre(5.6, 3.0)).x > 0.0);
    assert!(ours.pdf_li(centre(6.0, 3.0)) > 0.0);
    assert!(ours.pdf_li(centre(5.0, 3.0)) < bright);
    // In one row, the default density follows the cell averages, 6 : 36.
    let ratio = ours.pdf_li(centre(6.0, 3.0)) / ours.pdf_li(centre(5.0, 3.0));
    assert!((ratio - 1.0 / 6.0).abs() < 1e-5, "{ratio}");
    // The same tables are kept when the weights do not change.
    let again = course.reweighted(EnvironmentWeights::Texel);
    assert!(Arc::ptr_eq(&again.tables, &course.tables));
    assert_eq!(
        ours.reweighted(EnvironmentWeights::Texel)
            .pdf_li(centre(6.0, 3.0)),
        0.0
    );
}

/// A constant map is drawn uniformly over the sphere: the `sin(theta)`
/// in the cells' weights cancels the mapping's Jacobian, so through each
/// cell's centre the density per steradian is `1 / (4 pi)` (up to the
/// midpoint rule's sum of `sin(theta)` over the rows, `4e-4` relative at
/// 32 rows). Fails if the weight divides by `sin(theta)` or leaves it out.
#[test]
fn a_constant_map_is_sampled_uniformly_over_the_sphere() {
    let map = EnvironmentMap::new("constant", 64, 32, vec![Rgb::splat(3.0); 64 * 32]).unwrap();
    let light = EnvironmentLight::new(map, EnvironmentSampling::Importance);
    let uniform = 1.0 / (4.0 * PI);
    for j in 0..32 {
        for i in [0, 17, 63] {
            let uv = Vec2::new((i as f32 + 0.5) / 64.0, (j as f32 + 0.5) / 32.0);
            let pdf = light.pdf_li(uv_to_direction(uv));
            assert!((pdf / uniform - 1.0).abs() < 1e-3, "cell ({i}, {j}): {pdf}");
        }
    }
}

/// A sample at a pole (`u.y = 0` on a map whose top row has light) has no
/// density per steradian (`sin(theta) = 0`): no sample, not one of
/// density 0. Uniform sampling has a density there.
#[test]
fn a_sample_at_a_pole_is_none() {
    let map = EnvironmentMap::new("constant", 16, 8, vec![Rgb::splat(3.0); 16 * 8]).unwrap();
    let light = EnvironmentLight::new(map, EnvironmentSampling::Importance);
    assert_eq!(light.sample_li(Vec2::new(0.3, 0.0)), None);
    let inside = light.sample_li(Vec2::new(0.3, 0.01)).unwrap();
    assert!(matches!(inside.pdf, LightPdf::SolidAngle(p) if p > 0.0));
    let uniform = light.with_sampling(EnvironmentSampling::Uniform);
    let s = uniform.sample_li(Vec2::new(0.3, 0.0)).unwrap();
    assert_eq!(s.pdf, LightPdf::SolidAngle(1.0 / (4.0 * PI)));
}
