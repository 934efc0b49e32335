//! The catalogue's text: for every [`Mistake`], its name, part, starter
//! function, what is wrong and what it looks like.

use super::{Mistake, MistakeInfo};

impl Mistake {
    /// The catalogue's entry.
    pub fn info(self) -> MistakeInfo {
        let (name, part, function, what, symptom) = match self {
            Mistake::FovFullAngle => (
                "fov-full-angle",
                1,
                "Camera::generate_ray",
                "the sensor's half-width taken as tan(hFov), not tan(hFov / 2)",
                "the view about twice as wide: the scene small in the middle of a dark frame",
            ),
            Mistake::NoCosine => (
                "no-cosine",
                3,
                "estimate_direct_lighting_hemisphere / _importance",
                "the cosine at the shading point, cos(theta) = wi.z, is left out",
                "surfaces seen by the light at a grazing angle are too bright: walls near the ceiling, the floor far from the lamp",
            ),
            Mistake::NoPdf => (
                "no-pdf",
                3,
                "estimate_direct_lighting_hemisphere / _importance",
                "a sample is not divided by its pdf",
                "-H: 2 pi times too dark; light sampling: too bright by the light's pdf, a small lamp's several per steradian",
            ),
            Mistake::HemispherePdfOneOverPi => (
                "hemisphere-pdf-1-over-pi",
                3,
                "estimate_direct_lighting_hemisphere",
                "the uniform hemisphere's pdf taken as 1/pi instead of 1/(2 pi)",
                "-H: twice too dark; light sampling unchanged",
            ),
            Mistake::BrdfIsAlbedo => (
                "brdf-is-albedo",
                3,
                "DiffuseBSDF::f",
                "the diffuse BRDF returns the albedo, not albedo / pi",
                "everything lit is pi times too bright (clipped to white)",
            ),
            Mistake::ShadowAcne => (
                "shadow-acne",
                3,
                "estimate_direct_lighting_importance",
                "shadow rays start at the hit point with min_t = 0, without the EPS_F offset",
                "speckles of shadow (acne) all over lit surfaces",
            ),
            Mistake::ShadowRayReachesLight => (
                "shadow-ray-reaches-light",
                3,
                "estimate_direct_lighting_importance",
                "the shadow ray's max_t is not shortened before the light, so the lamp's own mesh blocks it",
                "no direct light from the lamp: the room is black but for the lamp",
            ),
            Mistake::LightFromBehind => (
                "light-from-behind",
                3,
                "estimate_direct_lighting_importance",
                "light samples from behind a one-sided light are counted (its cosine taken as |cos|)",
                "the ceiling above the lamp is lit",
            ),
            Mistake::LightSamplesNotAveraged => (
                "light-samples-not-averaged",
                3,
                "estimate_direct_lighting_importance",
                "the sum over an area light's -l samples is not divided by their number",
                "direct light -l times too bright (the same as the correct image at -l 1)",
            ),
            Mistake::RouletteNotDivided => (
                "roulette-not-divided",
                4,
                "at_least_one_bounce_radiance",
                "a path that survives Russian roulette is not divided by its probability 0.65",
                "indirect light too dark: shadows and the ceiling darker, direct light unchanged",
            ),
            Mistake::EmissionEveryBounce => (
                "emission-every-bounce",
                4,
                "at_least_one_bounce_radiance",
                "the emission a bounced ray finds is added at every bounce, besides light sampling",
                "light counted twice: too bright, most near the lamp",
            ),
            Mistake::DepthOffByOne => (
                "depth-off-by-one",
                4,
                "at_least_one_bounce_radiance",
                "the depth test lets one bounce more through than -m says",
                "-m N renders like -m N+1: -m 1 shows indirect light",
            ),
            Mistake::NoAccumulationSumsAll => (
                "o0-accumulates",
                4,
                "at_least_one_bounce_radiance",
                "-o 0 returns the sum of every bounce instead of the m-th alone",
                "-o 0 renders like -o 1",
            ),
            Mistake::ThroughputWithoutCosPdf => (
                "throughput-without-cos-pdf",
                4,
                "at_least_one_bounce_radiance",
                "the bounced light is multiplied by f alone, not by f cos / pdf",
                "indirect light pi times too dark on diffuse surfaces",
            ),
            Mistake::AdaptiveNotSquareRooted => (
                "adaptive-n-not-square-rooted",
                5,
                "PathTracer::raytrace_pixel",
                "the confidence half-width taken as 1.96 sigma / n, not 1.96 sigma / sqrt(n)",
                "pixels stop at the first check: the rate image almost all blue, the image noisier",
            ),
            Mistake::AdaptiveCountNotUpdated => (
                "adaptive-count-not-updated",
                5,
                "PathTracer::raytrace_pixel",
                "the pixel's sample count is left at ns_aa when it stops early",
                "the rate image all red; pixels that stopped early too dark by the share of samples they took",
            ),
            Mistake::ReflectWrongAxis => (
                "reflect-wrong-axis",
                6,
                "BSDF::reflect",
                "wo reflected through the tangent plane, (wo.x, wo.y, -wo.z), not about the normal, (-wo.x, -wo.y, wo.z)",
                "a mirror ball turns dark inside a bright ring: its rays head into the ball instead of away",
            ),
            Mistake::RefractionRatioInverted => (
                "refraction-ratio-inverted",
                6,
                "BSDF::refract",
                "Snell's law with the ratio of indices upside down (ior entering, 1 / ior leaving)",
                "glass looks like a mirror: light that meets it from outside is mostly totally reflected, and what enters bends the wrong way",
            ),
            Mistake::NoEtaSquared => (
                "no-eta-squared",
                6,
                "GlassBSDF::sample_f, RefractionBSDF::sample_f",
                "the transmitted radiance is not divided by eta^2",
                "nothing on a closed glass object seen from outside (the factors entering and leaving cancel); a single refracting surface is eta^2 too bright or too dark",
            ),
            Mistake::NoTotalInternalReflection => (
                "no-total-internal-reflection",
                6,
                "GlassBSDF::sample_f",
                "when refract() fails (total internal reflection) the sample returns no light instead of reflecting",
                "glass balls look the same (light inside a ball never meets the critical angle); glass of other shapes turns black where light should reflect inside, like the sides of a block seen through its top",
            ),
            Mistake::SchlickR0NotSquared => (
                "schlick-r0-not-squared",
                6,
                "GlassBSDF::sample_f",
                "Schlick's R0 = ((1 - ior) / (1 + ior))^2 taken without the square",
                "glass reflects about five times too much near normal incidence: strong reflections of the lamp and the walls on glass",
            ),
            Mistake::EnvPdfNoSin => (
                "env-pdf-no-sin",
                7,
                "EnvironmentLight::sample_L",
                "the density per steradian left without the 1 / sin(theta) of the lat-long map's Jacobian",
                "light from near the horizon too strong, from near the poles too weak: a biased, brighter image",
            ),
            Mistake::EnvPdfNoJacobian => (
                "env-pdf-no-jacobian",
                7,
                "EnvironmentLight::sample_L",
                "the density per steradian left without the 1 / (2 pi^2) of the lat-long map's Jacobian",
                "direct light from the map 2 pi^2 (about 20) times too dark",
            ),
            Mistake::EnvMapUFlipped => (
                "env-map-u-flipped",
                7,
                "EnvironmentLight::sample_dir, sample_L",
                "the map read with u (the azimuth) flipped",
                "the environment mirrored left to right: the sun and the shadows on the other side",
            ),
            Mistake::EnvMapVFlipped => (
                "env-map-v-flipped",
                7,
                "EnvironmentLight::sample_dir, sample_L",
                "the map read with v (the polar angle) flipped",
                "the environment upside down: sky below, ground above, objects lit from below",
            ),
            Mistake::LensRadiusUnscaled => (
                "lens-radius-unscaled",
                8,
                "Camera::generate_ray_for_thin_lens",
                "the point on the lens taken on the unit disk, not scaled by the lens radius -b",
                "everything but the plane of focus blurred as by a lens of radius 1, whatever -b says",
            ),
            Mistake::FocusOnASphere => (
                "focus-on-a-sphere",
                8,
                "Camera::generate_ray_for_thin_lens",
                "the point in focus taken at distance d along the normalised pinhole ray, not on the plane z = -d",
                "the focus curves towards the lens away from the image's centre: the corners focus nearer than -d",
            ),
        };
        MistakeInfo {
            name,
            part,
            function,
            what,
            symptom,
        }
    }
}
