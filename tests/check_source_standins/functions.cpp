// Short, plain stand-ins for the functions a student writes in the 3-1
// starter (parts 1 to 3), for tests/check_source_standins.rs. Each block
// starts with a marker `//== FILE :: LINE`: the test replaces, in its copy
// of the starter, the definition that starts with LINE and ends at the
// next `}` in column 0 with the block. Each catalogued mistake the test
// injects is one `STANDIN_...` macro of src/standin_mistake.h.

//== src/pathtracer/camera.cpp :: Ray Camera::generate_ray(double x, double y) const {
Ray Camera::generate_ray(double x, double y) const {
#if defined(STANDIN_FOV_IN_DEGREES)
  double w = tan(hFov / 2), h = tan(vFov / 2);
#elif defined(STANDIN_FOV_FULL_ANGLE)
  double w = tan(radians(hFov)), h = tan(radians(vFov));
#else
  double w = tan(radians(hFov) / 2), h = tan(radians(vFov) / 2);
#endif
  Vector3D d((2 * x - 1) * w, (2 * y - 1) * h, -1);
#ifndef STANDIN_RAY_IN_CAMERA_SPACE
  d = c2w * d;
#endif
  Ray ray(pos, d.unit());
  ray.min_t = nClip;
  ray.max_t = fClip;
  return ray;
}

//== src/scene/triangle.cpp :: bool Triangle::has_intersection(const Ray &r) const {
// Moller-Trumbore: whether r meets the triangle in [min_t, max_t], with
// its t and barycentrics.
static bool hit_triangle(const Ray &r, const Vector3D &p1, const Vector3D &p2,
                         const Vector3D &p3, double &t, double &b1, double &b2) {
  Vector3D e1 = p2 - p1, e2 = p3 - p1, s = r.o - p1;
  Vector3D s1 = cross(r.d, e2), s2 = cross(s, e1);
  double det = dot(s1, e1);
  t = dot(s2, e2) / det;
  b1 = dot(s1, s) / det;
  b2 = dot(s2, r.d) / det;
#ifdef STANDIN_TRIANGLE_CHAINED_COMPARISON
  bool in_range = r.min_t <= t <= r.max_t;
#elif defined(STANDIN_TRIANGLE_IGNORES_MAX_T)
  bool in_range = r.min_t <= t;
#else
  bool in_range = r.min_t <= t && t <= r.max_t;
#endif
  return in_range && b1 >= 0 && b2 >= 0 && b1 + b2 <= 1;
}

bool Triangle::has_intersection(const Ray &r) const {
  double t, b1, b2;
  return hit_triangle(r, p1, p2, p3, t, b1, b2);
}

//== src/scene/triangle.cpp :: bool Triangle::intersect(const Ray &r, Intersection *isect) const {
bool Triangle::intersect(const Ray &r, Intersection *isect) const {
  double t, b1, b2;
  if (!hit_triangle(r, p1, p2, p3, t, b1, b2))
    return false;
#ifndef STANDIN_MAX_T_NOT_SHRUNK
  r.max_t = t;
#endif
  isect->t = t;
#ifdef STANDIN_BARYCENTRIC_NORMALS_PERMUTED
  isect->n = (b1 * n1 + b2 * n2 + (1 - b1 - b2) * n3).unit();
#else
  isect->n = ((1 - b1 - b2) * n1 + b1 * n2 + b2 * n3).unit();
#endif
  isect->primitive = this;
  isect->bsdf = get_bsdf();
  return true;
}

//== src/scene/sphere.cpp :: bool Sphere::test(const Ray &r, double &t1, double &t2) const {
bool Sphere::test(const Ray &r, double &t1, double &t2) const {
  Vector3D oc = r.o - o;
  double a = dot(r.d, r.d), b = 2 * dot(oc, r.d), c = dot(oc, oc) - r2;
  double disc = b * b - 4 * a * c;
  if (disc < 0)
    return false;
  t1 = (-b - sqrt(disc)) / (2 * a);
  t2 = (-b + sqrt(disc)) / (2 * a);
  return true;
}

//== src/scene/sphere.cpp :: bool Sphere::has_intersection(const Ray &r) const {
bool Sphere::has_intersection(const Ray &r) const {
  double t1, t2;
  if (!test(r, t1, t2))
    return false;
  return (r.min_t <= t1 && t1 <= r.max_t) || (r.min_t <= t2 && t2 <= r.max_t);
}

//== src/scene/sphere.cpp :: bool Sphere::intersect(const Ray &r, Intersection *i) const {
bool Sphere::intersect(const Ray &r, Intersection *i) const {
  double t1, t2;
  if (!test(r, t1, t2))
    return false;
#ifdef STANDIN_SPHERE_FAR_ROOT
  double t = (r.min_t <= t2 && t2 <= r.max_t) ? t2 : t1;
#else
  double t = (r.min_t <= t1 && t1 <= r.max_t) ? t1 : t2;
#endif
  if (t < r.min_t || t > r.max_t)
    return false;
  r.max_t = t;
  i->t = t;
  i->n = (r.o + t * r.d - o).unit();
  i->primitive = this;
  i->bsdf = get_bsdf();
  return true;
}

//== src/scene/bbox.cpp :: bool BBox::intersect(const Ray& r, double& t0, double& t1) const {
bool BBox::intersect(const Ray& r, double& t0, double& t1) const {
  double enter = -INF_D, exit = INF_D;
  for (int k = 0; k < 3; k++) {
    double a = (min[k] - r.o[k]) * r.inv_d[k];
    double b = (max[k] - r.o[k]) * r.inv_d[k];
#ifdef STANDIN_BBOX_SLABS_NOT_SWAPPED
    enter = std::max(enter, a);
    exit = std::min(exit, b);
#else
    enter = std::max(enter, std::min(a, b));
    exit = std::min(exit, std::max(a, b));
#endif
  }
#ifdef STANDIN_BBOX_MISSES_RAYS_FROM_INSIDE
  if (enter > exit || enter < t0 || enter > t1)
    return false;
#else
  if (enter > exit || exit < t0 || enter > t1)
    return false;
#endif
  t0 = std::max(t0, enter);
  t1 = std::min(t1, exit);
  return true;
}

//== src/scene/bvh.cpp :: BVHNode *BVHAccel::construct_bvh(std::vector<Primitive *>::iterator start,
BVHNode *BVHAccel::construct_bvh(std::vector<Primitive *>::iterator start,
                                 std::vector<Primitive *>::iterator end,
                                 size_t max_leaf_size) {
  BBox bbox, centroids;
  for (auto p = start; p != end; p++) {
    bbox.expand((*p)->get_bbox());
    centroids.expand((*p)->get_bbox().centroid());
  }
  BVHNode *node = new BVHNode(bbox);
  node->start = start;
  node->end = end;
  if ((size_t)(end - start) <= max_leaf_size)
    return node;
  // Split at the middle of the centroids' box on its longest axis.
  Vector3D e = centroids.extent;
  int axis = (e.x >= e.y && e.x >= e.z) ? 0 : (e.y >= e.z ? 1 : 2);
  double mid = centroids.centroid()[axis];
  auto split = std::partition(start, end, [&](Primitive *p) {
    return p->get_bbox().centroid()[axis] < mid;
  });
  if (split == start || split == end)
    split = start + (end - start) / 2;
  node->l = construct_bvh(start, split, max_leaf_size);
  node->r = construct_bvh(split, end, max_leaf_size);
  return node;
}

//== src/scene/bvh.cpp :: bool BVHAccel::has_intersection(const Ray &ray, BVHNode *node) const {
bool BVHAccel::has_intersection(const Ray &ray, BVHNode *node) const {
  double t0 = ray.min_t, t1 = ray.max_t;
  if (!node->bb.intersect(ray, t0, t1))
    return false;
  if (node->isLeaf()) {
    for (auto p = node->start; p != node->end; p++) {
      total_isects++;
      if ((*p)->has_intersection(ray))
        return true;
    }
    return false;
  }
  return has_intersection(ray, node->l) || has_intersection(ray, node->r);
}

//== src/scene/bvh.cpp :: bool BVHAccel::intersect(const Ray &ray, Intersection *i, BVHNode *node) const {
bool BVHAccel::intersect(const Ray &ray, Intersection *i, BVHNode *node) const {
  double t0 = ray.min_t, t1 = ray.max_t;
#ifndef STANDIN_BVH_NO_BOX_TEST
  if (!node->bb.intersect(ray, t0, t1))
    return false;
#endif
  if (node->isLeaf()) {
    bool hit = false;
    for (auto p = node->start; p != node->end; p++) {
      total_isects++;
#ifdef STANDIN_BVH_LEAF_STOPS_AT_FIRST_HIT
      hit = hit || (*p)->intersect(ray, i);
#else
      hit = (*p)->intersect(ray, i) || hit;
#endif
    }
    return hit;
  }
#ifdef STANDIN_BVH_FIRST_HIT
  return intersect(ray, i, node->l) || intersect(ray, i, node->r);
#else
  bool hit_l = intersect(ray, i, node->l);
  bool hit_r = intersect(ray, i, node->r);
  return hit_l || hit_r;
#endif
}

//== src/pathtracer/bsdf.cpp :: Vector3D DiffuseBSDF::f(const Vector3D wo, const Vector3D wi) {
Vector3D DiffuseBSDF::f(const Vector3D wo, const Vector3D wi) {
#ifdef STANDIN_BRDF_IS_ALBEDO
  return reflectance;
#else
  return reflectance / PI;
#endif
}

//== src/pathtracer/bsdf.cpp :: Vector3D DiffuseBSDF::sample_f(const Vector3D wo, Vector3D *wi, double *pdf) {
Vector3D DiffuseBSDF::sample_f(const Vector3D wo, Vector3D *wi, double *pdf) {
  *wi = sampler.get_sample(pdf);
  return f(wo, *wi);
}

//== src/pathtracer/pathtracer.cpp :: PathTracer::estimate_direct_lighting_hemisphere(const Ray &r,
PathTracer::estimate_direct_lighting_hemisphere(const Ray &r,
                                                const Intersection &isect) {
  Matrix3x3 o2w;
  make_coord_space(o2w, isect.n);
  Matrix3x3 w2o = o2w.T();
  const Vector3D hit_p = r.o + r.d * isect.t;
  const Vector3D w_out = w2o * (-r.d);
  int num_samples = scene->lights.size() * ns_area_light;
  Vector3D L_out;
#ifdef STANDIN_HEMISPHERE_PDF_1_OVER_PI
  double pdf = 1.0 / PI;
#else
  double pdf = 1.0 / (2.0 * PI);
#endif
  for (int k = 0; k < num_samples; k++) {
    Vector3D wi = hemisphereSampler->get_sample();
    Ray shadow(hit_p, o2w * wi);
    shadow.min_t = EPS_F;
    Intersection light_isect;
    if (!bvh->intersect(shadow, &light_isect))
      continue;
    Vector3D term = isect.bsdf->f(w_out, wi) * light_isect.bsdf->get_emission();
#ifndef STANDIN_NO_COSINE
    term *= wi.z;
#endif
#ifndef STANDIN_NO_PDF
    term /= pdf;
#endif
    L_out += term;
  }
  return num_samples > 0 ? L_out / (double)num_samples : L_out;
}

//== src/pathtracer/pathtracer.cpp :: PathTracer::estimate_direct_lighting_importance(const Ray &r,
PathTracer::estimate_direct_lighting_importance(const Ray &r,
                                                const Intersection &isect) {
  Matrix3x3 o2w;
  make_coord_space(o2w, isect.n);
  Matrix3x3 w2o = o2w.T();
  const Vector3D hit_p = r.o + r.d * isect.t;
  const Vector3D w_out = w2o * (-r.d);
  Vector3D L_out;
  for (size_t l = 0; l < scene->lights.size(); l++) {
    SceneLight *light = scene->lights[l];
    int ns = light->is_delta_light() ? 1 : (int)ns_area_light;
    Vector3D sum;
    for (int k = 0; k < ns; k++) {
      Vector3D wi_world;
      double dist, pdf;
      Vector3D L = light->sample_L(hit_p, &wi_world, &dist, &pdf);
#ifdef STANDIN_LIGHT_FROM_BEHIND
      AreaLight *area = dynamic_cast<AreaLight *>(light);
      if (area && L.x == 0 && L.y == 0 && L.z == 0)
        L = area->radiance;
#endif
      Vector3D wi = w2o * wi_world;
      if (wi.z <= 0 || !(pdf > 0))
        continue;
      Ray shadow(hit_p, wi_world);
#ifdef STANDIN_SHADOW_ACNE
      shadow.min_t = 0;
#else
      shadow.min_t = EPS_F;
#endif
#ifdef STANDIN_SHADOW_RAY_REACHES_LIGHT
      shadow.max_t = INF_D;
#else
      shadow.max_t = dist - EPS_F;
#endif
      if (bvh->has_intersection(shadow))
        continue;
      Vector3D term = isect.bsdf->f(w_out, wi) * L;
#ifndef STANDIN_NO_COSINE
      term *= wi.z;
#endif
#ifndef STANDIN_NO_PDF
      term /= pdf;
#endif
      sum += term;
    }
#ifdef STANDIN_LIGHT_SAMPLES_NOT_AVERAGED
    L_out += sum;
#else
    L_out += sum / (double)ns;
#endif
  }
  return L_out;
}

//== src/pathtracer/pathtracer.cpp :: Vector3D PathTracer::zero_bounce_radiance(const Ray &r,
Vector3D PathTracer::zero_bounce_radiance(const Ray &r,
                                          const Intersection &isect) {
  return isect.bsdf->get_emission();
}

//== src/pathtracer/pathtracer.cpp :: Vector3D PathTracer::one_bounce_radiance(const Ray &r,
Vector3D PathTracer::one_bounce_radiance(const Ray &r,
                                         const Intersection &isect) {
  return direct_hemisphere_sample ? estimate_direct_lighting_hemisphere(r, isect)
                                  : estimate_direct_lighting_importance(r, isect);
}

//== src/pathtracer/pathtracer.cpp :: Vector3D PathTracer::at_least_one_bounce_radiance(const Ray &r,
Vector3D PathTracer::at_least_one_bounce_radiance(const Ray &r,
                                                  const Intersection &isect) {
  Matrix3x3 o2w;
  make_coord_space(o2w, isect.n);
  Matrix3x3 w2o = o2w.T();
  Vector3D hit_p = r.o + r.d * isect.t;
  Vector3D w_out = w2o * (-r.d);
  Vector3D L_out(0, 0, 0);
#ifdef STANDIN_O0_ACCUMULATES
  bool accumulate = true;
#else
  bool accumulate = isAccumBounces;
#endif
  // The camera ray has depth max_ray_depth; the last bounce leaves depth 1.
#ifdef STANDIN_DEPTH_OFF_BY_ONE
  int last = 0;
#else
  int last = 1;
#endif
  int depth = r.depth;
  if (accumulate || depth == last)
    L_out = one_bounce_radiance(r, isect);
  if (depth <= last)
    return L_out;
  // Russian roulette from the second bounce on, continuing with 0.65.
  double q = (int)max_ray_depth - depth + 1 >= 2 ? 0.65 : 1.0;
  if (!coin_flip(q))
    return L_out;
  Vector3D wi;
  double pdf;
  Vector3D f = isect.bsdf->sample_f(w_out, &wi, &pdf);
  if (!(pdf > 0))
    return L_out;
  Ray next(hit_p, o2w * wi, depth - 1);
  next.min_t = EPS_F;
  Intersection next_isect;
  if (!bvh->intersect(next, &next_isect))
    return L_out;
  Vector3D incoming = at_least_one_bounce_radiance(next, next_isect);
#ifdef STANDIN_EMISSION_EVERY_BOUNCE
  incoming += zero_bounce_radiance(next, next_isect);
#endif
#ifdef STANDIN_THROUGHPUT_WITHOUT_COS_PDF
  Vector3D onward = f * incoming;
#else
  Vector3D onward = f * incoming * wi.z / pdf;
#endif
#ifndef STANDIN_ROULETTE_NOT_DIVIDED
  onward /= q;
#endif
  return accumulate ? L_out + onward : onward;
}

//== src/pathtracer/pathtracer.cpp :: Vector3D PathTracer::est_radiance_global_illumination(const Ray &r) {
Vector3D PathTracer::est_radiance_global_illumination(const Ray &r) {
  Intersection isect;
  Vector3D L_out;
  if (!bvh->intersect(r, &isect))
    return envLight ? envLight->sample_dir(r) : L_out;
  if (isAccumBounces || max_ray_depth == 0)
    L_out += zero_bounce_radiance(r, isect);
  if (max_ray_depth >= 1)
    L_out += at_least_one_bounce_radiance(r, isect);
  return L_out;
}

//== src/pathtracer/pathtracer.cpp :: void PathTracer::raytrace_pixel(size_t x, size_t y) {
void PathTracer::raytrace_pixel(size_t x, size_t y) {
  int num_samples = ns_aa;
  Vector2D origin = Vector2D(x, y);
  double w = sampleBuffer.w, h = sampleBuffer.h;
  Vector3D sum;
  double s1 = 0, s2 = 0;
  int n = 0;
  while (n < num_samples) {
    Vector2D p = origin + gridSampler->get_sample();
    Ray r = camera->generate_ray(p.x / w, p.y / h);
    r.depth = max_ray_depth;
    Vector3D L = est_radiance_global_illumination(r);
    sum += L;
    s1 += L.illum();
    s2 += L.illum() * L.illum();
    n++;
    if (samplesPerBatch > 0 && n % samplesPerBatch == 0 && n < num_samples) {
      double mu = s1 / n;
      double sigma = sqrt(std::max(0.0, (s2 - s1 * s1 / n) / (n - 1)));
#ifdef STANDIN_ADAPTIVE_N_NOT_SQUARE_ROOTED
      if (1.96 * sigma / n <= maxTolerance * mu)
        break;
#else
      if (1.96 * sigma / sqrt((double)n) <= maxTolerance * mu)
        break;
#endif
    }
  }
#ifdef STANDIN_ADAPTIVE_COUNT_NOT_UPDATED
  int count = num_samples;
#else
  int count = n;
#endif
  sampleBuffer.update_pixel(sum / (double)count, x, y);
  sampleCountBuffer[x + y * sampleBuffer.w] = count;
}
