// Short, plain stand-ins for the functions a student writes in the 3-2
// starter (parts 6 to 8), for tests/check_source_standins_32.rs. Each
// block starts with a marker `//== FILE :: LINE`: the test replaces, in
// its copy of the starter, the definition whose first line is LINE
// (leading spaces aside) and that ends at the next `}` indented as LINE
// was with the block. Each catalogued mistake the test injects is one
// `STANDIN_...` macro of src/standin_mistake.h.

//== src/pathtracer/advanced_bsdf.cpp :: Vector3D MirrorBSDF::sample_f(const Vector3D wo, Vector3D* wi, double* pdf) {
// eta = n_i / n_t from wo's side to wi's: entering (wo.z > 0) or leaving.
static double standin_eta(const Vector3D &wo, double ior) {
  return wo.z > 0 ? 1.0 / ior : ior;
}

// f of a delta lobe of weight `weight`: weight / |cos(theta_i)|.
static Vector3D standin_delta(const Vector3D &weight, const Vector3D &wi) {
  double c = fabs(wi.z);
  return c > 0 ? weight / c : Vector3D();
}

Vector3D MirrorBSDF::sample_f(const Vector3D wo, Vector3D* wi, double* pdf) {
  reflect(wo, wi);
  *pdf = 1.0;
  return standin_delta(reflectance, *wi);
}

//== src/pathtracer/advanced_bsdf.cpp :: double MicrofacetBSDF::D(const Vector3D h) {
double MicrofacetBSDF::D(const Vector3D h) {
  if (h.z <= 0) return 0.0;
  double c2 = h.z * h.z, a2 = alpha * alpha;
  double d = exp(-(1.0 - c2) / c2 / a2) / (PI * a2);
#ifdef STANDIN_MICROFACET_D_NO_COS4
  return d;
#else
  return d / (c2 * c2);
#endif
}

//== src/pathtracer/advanced_bsdf.cpp :: Vector3D MicrofacetBSDF::F(const Vector3D wi) {
Vector3D MicrofacetBSDF::F(const Vector3D wi) {
  double c = clamp(wi.z, 0.0, 1.0), c2 = c * c;
  Vector3D out;
  for (int i = 0; i < 3; i++) {
    double e = eta[i], ek = e * e + k[i] * k[i];
    double rs = (ek - 2 * e * c + c2) / (ek + 2 * e * c + c2);
    double rp = (ek * c2 - 2 * e * c + 1) / (ek * c2 + 2 * e * c + 1);
    out[i] = (rs + rp) / 2;
  }
  return out;
}

//== src/pathtracer/advanced_bsdf.cpp :: Vector3D MicrofacetBSDF::f(const Vector3D wo, const Vector3D wi) {
Vector3D MicrofacetBSDF::f(const Vector3D wo, const Vector3D wi) {
  if (wo.z <= 0 || wi.z <= 0) return Vector3D();
  Vector3D h = (wo + wi).unit();
#ifdef STANDIN_MICROFACET_NO_4
  double denom = wo.z * wi.z;
#else
  double denom = 4 * wo.z * wi.z;
#endif
  return F(wi) * (G(wo, wi) * D(h) / denom);
}

//== src/pathtracer/advanced_bsdf.cpp :: Vector3D MicrofacetBSDF::sample_f(const Vector3D wo, Vector3D* wi, double* pdf) {
Vector3D MicrofacetBSDF::sample_f(const Vector3D wo, Vector3D* wi, double* pdf) {
  Vector2D r = sampler.get_sample();
  double a2 = alpha * alpha, tan2 = -a2 * log(1.0 - r.x);
  double c = 1.0 / sqrt(1.0 + tan2), s = sqrt(std::max(0.0, 1.0 - c * c));
  double phi = 2.0 * PI * r.y;
  Vector3D h(s * cos(phi), s * sin(phi), c);
  double wo_h = dot(wo, h);
  *wi = -wo + 2.0 * wo_h * h;
  if (wo.z <= 0 || wi->z <= 0 || wo_h <= 0) {
    *pdf = 1.0;
    return Vector3D();
  }
  double pdf_h = exp(-tan2 / a2) / (PI * a2 * c * c * c);
#ifdef STANDIN_MICROFACET_PDF_NO_JACOBIAN
  *pdf = pdf_h;
#else
  *pdf = pdf_h / (4.0 * dot(*wi, h));
#endif
  return MicrofacetBSDF::f(wo, *wi);
}

//== src/pathtracer/advanced_bsdf.cpp :: Vector3D RefractionBSDF::sample_f(const Vector3D wo, Vector3D* wi, double* pdf) {
Vector3D RefractionBSDF::sample_f(const Vector3D wo, Vector3D* wi, double* pdf) {
  *pdf = 1.0;
  if (!refract(wo, wi, ior)) {
    reflect(wo, wi);
    return Vector3D();
  }
  Vector3D out = standin_delta(transmittance, *wi);
#ifndef STANDIN_NO_ETA_SQUARED
  double eta = standin_eta(wo, ior);
  out /= eta * eta;
#endif
  return out;
}

//== src/pathtracer/advanced_bsdf.cpp :: Vector3D GlassBSDF::sample_f(const Vector3D wo, Vector3D* wi, double* pdf) {
Vector3D GlassBSDF::sample_f(const Vector3D wo, Vector3D* wi, double* pdf) {
  if (!refract(wo, wi, ior)) {
    *pdf = 1.0;
#ifdef STANDIN_NO_TOTAL_INTERNAL_REFLECTION
    return Vector3D();
#endif
    reflect(wo, wi);
    return standin_delta(reflectance, *wi);
  }
  double r0 = (1.0 - ior) / (1.0 + ior);
#ifdef STANDIN_SCHLICK_R0_NOT_SQUARED
  r0 = fabs(r0);
#else
  r0 = r0 * r0;
#endif
  double R = r0 + (1.0 - r0) * pow(1.0 - fabs(wo.z), 5);
  if (coin_flip(R)) {
    reflect(wo, wi);
    *pdf = R;
    return standin_delta(R * reflectance, *wi);
  }
  *pdf = 1.0 - R;
  double eta = standin_eta(wo, ior);
  return standin_delta((1.0 - R) * transmittance, *wi) / (eta * eta);
}

//== src/pathtracer/advanced_bsdf.cpp :: void BSDF::reflect(const Vector3D wo, Vector3D* wi) {
void BSDF::reflect(const Vector3D wo, Vector3D* wi) {
#ifdef STANDIN_REFLECT_WRONG_AXIS
  *wi = Vector3D(wo.x, wo.y, -wo.z);
#else
  *wi = Vector3D(-wo.x, -wo.y, wo.z);
#endif
}

//== src/pathtracer/advanced_bsdf.cpp :: bool BSDF::refract(const Vector3D wo, Vector3D* wi, double ior) {
bool BSDF::refract(const Vector3D wo, Vector3D* wi, double ior) {
  double eta = standin_eta(wo, ior);
#ifdef STANDIN_REFRACTION_RATIO_INVERTED
  eta = 1.0 / eta;
#endif
  double cos2 = 1.0 - eta * eta * std::max(0.0, 1.0 - wo.z * wo.z);
  if (cos2 < 0) return false;
  double c = sqrt(cos2);
  *wi = Vector3D(-eta * wo.x, -eta * wo.y, wo.z > 0 ? -c : c);
  return true;
}

//== src/scene/environment_light.cpp :: void EnvironmentLight::init() {
void EnvironmentLight::init() {
  uint32_t w = envMap->w, h = envMap->h;
  pdf_envmap = new double[w * h];
  conds_y = new double[w * h];
  marginal_y = new double[h];
  // The pixels' probabilities, each row's cumulative distribution given
  // the row (conds_y) and the rows' (marginal_y).
  double sum = 0;
  for (uint32_t j = 0; j < h; ++j)
    for (uint32_t i = 0; i < w; ++i)
#ifdef STANDIN_ENV_INIT_NO_SIN
      sum += pdf_envmap[w * j + i] = envMap->data[w * j + i].illum();
#else
      sum += pdf_envmap[w * j + i] =
          envMap->data[w * j + i].illum() * sin(PI * (j + .5) / h);
#endif
  double acc = 0;
  for (uint32_t j = 0; j < h; ++j) {
    double row = 0;
    for (uint32_t i = 0; i < w; ++i) {
      double p = sum > 0 ? pdf_envmap[w * j + i] / sum : 1.0 / (w * h);
      pdf_envmap[w * j + i] = p;
      row += p;
      conds_y[w * j + i] = row;
    }
    for (uint32_t i = 0; i < w; ++i)
      conds_y[w * j + i] = row > 0 ? conds_y[w * j + i] / row : (i + 1.0) / w;
    conds_y[w * j + w - 1] = 1.0;
    marginal_y[j] = acc += row;
  }
  for (uint32_t j = 0; j < h; ++j) marginal_y[j] /= acc;
  marginal_y[h - 1] = 1.0;
}

//== src/scene/environment_light.cpp :: Vector3D EnvironmentLight::sample_L(const Vector3D p, Vector3D* wi,
// The index of the first of the n cumulative values `cdf` above u, and
// where u lies inside its step (0 to 1) in `frac`.
static long standin_pick(const double *cdf, long n, double u, double &frac) {
  long i = std::min(long(std::upper_bound(cdf, cdf + n, u) - cdf), n - 1);
  double lo = i > 0 ? cdf[i - 1] : 0.0, step = cdf[i] - lo;
  frac = step > 0 ? std::min(std::max((u - lo) / step, 0.0), 1.0) : 0.5;
  return i;
}

Vector3D EnvironmentLight::sample_L(const Vector3D p, Vector3D* wi,
                                    double* distToLight, double* pdf) const {
  uint32_t w = envMap->w, h = envMap->h;
  Vector2D r = sampler_uniform2d.get_sample();
  double fx, fy;
  long j = standin_pick(marginal_y, h, r.y, fy);
  long i = standin_pick(conds_y + (size_t)w * j, w, r.x, fx);
  Vector2D xy(i + fx, j + fy), dir_xy = xy;
#ifdef STANDIN_ENV_MAP_U_FLIPPED
  dir_xy.x = w - dir_xy.x;
#endif
#ifdef STANDIN_ENV_MAP_V_FLIPPED
  dir_xy.y = h - dir_xy.y;
#endif
  Vector2D theta_phi = xy_to_theta_phi(xy);
  *wi = theta_phi_to_dir(xy_to_theta_phi(dir_xy));
  *distToLight = INF_D;
  // Per steradian: w h P(pixel) / (2 pi^2 sin(theta)).
  double jacobian = 2.0 * PI * PI;
#ifdef STANDIN_ENV_PDF_NO_JACOBIAN
  jacobian = 1.0;
#endif
#ifndef STANDIN_ENV_PDF_NO_SIN
  jacobian *= std::max(sin(theta_phi.x), 1e-12);
#endif
  *pdf = pdf_envmap[(size_t)w * j + i] * w * h / jacobian;
  return bilerp(xy);
}

//== src/scene/environment_light.cpp :: Vector3D EnvironmentLight::sample_dir(const Ray& r) const {
Vector3D EnvironmentLight::sample_dir(const Ray& r) const {
  Vector2D xy = theta_phi_to_xy(dir_to_theta_phi(r.d));
  double w = envMap->w, h = envMap->h;
#ifdef STANDIN_ENV_MAP_U_FLIPPED
  xy.x = w - xy.x;
#endif
#ifdef STANDIN_ENV_MAP_V_FLIPPED
  xy.y = h - xy.y;
#endif
  // Inside the map (acos of a y rounded past 1 is NaN).
  xy.x = xy.x >= 0 ? std::min(xy.x, w) : 0;
  xy.y = xy.y >= 0 ? std::min(xy.y, h) : 0;
  return bilerp(xy);
}

//== src/pathtracer/camera_lens.cpp :: Ray Camera::generate_ray_for_thin_lens(double x, double y, double rndR, double rndTheta) const {
Ray Camera::generate_ray_for_thin_lens(double x, double y, double rndR, double rndTheta) const {
  // The pinhole ray's direction at z = -1, the lens in the plane z = 0,
  // the plane of focus z = -focalDistance (rndTheta is already an angle).
  Vector3D d((2 * x - 1) * tan(radians(hFov) / 2),
             (2 * y - 1) * tan(radians(vFov) / 2), -1);
#ifdef STANDIN_LENS_RADIUS_UNSCALED
  double r = sqrt(rndR);
#else
  double r = lensRadius * sqrt(rndR);
#endif
  Vector3D lens(r * cos(rndTheta), r * sin(rndTheta), 0);
#ifdef STANDIN_FOCUS_ON_A_SPHERE
  Vector3D focus = focalDistance * d.unit();
#else
  Vector3D focus = focalDistance * d;
#endif
  Ray ray(pos + c2w * lens, (c2w * (focus - lens)).unit());
  ray.min_t = nClip;
  ray.max_t = fClip;
  return ray;
}
