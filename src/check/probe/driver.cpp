// cs184_probe: the test driver of `check --source` (see PROTOCOL.md beside
// this file).
//
//   cs184_probe COMMANDS RESPONSES
//
// It is compiled together with a student's own CS184 PathTracer tree (by
// probe.cmake, through the student's CMake) and calls the functions the
// student wrote, one command line of COMMANDS at a time, writing what they
// return to RESPONSES, one line per command, flushed at once.
//
// It contains NO solution of the assignment: it only builds the course's
// objects (cameras, triangles, spheres, BVHs, BSDFs, environment lights)
// from the numbers it is given, calls the student's functions on them and
// prints their results. Every output the student's code might leave unset is
// NaN before the call, so an unwritten output reads `nan`.
//
// Plain C++11 (the course compiles with -std=c++11).

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "pathtracer/bsdf.h"
#include "pathtracer/camera.h"
#include "pathtracer/intersection.h"
#include "pathtracer/pathtracer.h"
#include "pathtracer/ray.h"
#include "scene/bbox.h"
#include "scene/bvh.h"
#include "scene/collada/camera_info.h"
#include "scene/environment_light.h"
#include "scene/light.h"
#include "scene/object.h"
#include "scene/scene.h"
#include "scene/sphere.h"
#include "scene/triangle.h"
#include "util/image.h"

using namespace CGL;
using namespace CGL::SceneObjects;

static const double NaN = std::numeric_limits<double>::quiet_NaN();

// The tag BSDF: primitives are given it, and an intersection's `bsdf` is
// compared with its address.
static DiffuseBSDF tag_bsdf(Vector3D(0.5));

// Read access to BVHAccel's private list of primitives (an explicit
// instantiation may name a private member), used only to check that a leaf's
// [start, end) lies inside that list before the driver reads it.
typedef std::vector<Primitive*> BVHAccel::*BVHPrimitivesMember;
BVHPrimitivesMember bvh_primitives_member();
template <BVHPrimitivesMember M> struct BVHPrimitivesAccess {
  friend BVHPrimitivesMember bvh_primitives_member() { return M; }
};
template struct BVHPrimitivesAccess<&BVHAccel::primitives>;

// Read access, the same way, to the tables EnvironmentLight::init fills.
typedef double* EnvironmentLight::*EnvTable;
EnvTable env_pdf_member();
EnvTable env_marginal_member();
EnvTable env_conds_member();
template <EnvTable M> struct EnvPdfAccess {
  friend EnvTable env_pdf_member() { return M; }
};
template <EnvTable M> struct EnvMarginalAccess {
  friend EnvTable env_marginal_member() { return M; }
};
template <EnvTable M> struct EnvCondsAccess {
  friend EnvTable env_conds_member() { return M; }
};
template struct EnvPdfAccess<&EnvironmentLight::pdf_envmap>;
template struct EnvMarginalAccess<&EnvironmentLight::marginal_y>;
template struct EnvCondsAccess<&EnvironmentLight::conds_y>;

// Triangle tests: every outermost call of a driver-made triangle's
// `intersect` or `has_intersection` (a student's `intersect` that calls
// its own `has_intersection` counts once), so that a BVH's work per ray can
// be told from a scan's.
static long long triangle_tests = 0;

struct CountingTriangle : public Triangle {
  mutable int depth;
  CountingTriangle() : depth(0) {}
  bool has_intersection(const Ray& r) const {
    if (depth++ == 0) ++triangle_tests;
    bool hit = Triangle::has_intersection(r);
    --depth;
    return hit;
  }
  bool intersect(const Ray& r, Intersection* i) const {
    if (depth++ == 0) ++triangle_tests;
    bool hit = Triangle::intersect(r, i);
    --depth;
    return hit;
  }
};

// ---------------------------------------------------------------- input

// A malformed command: the driver answers `error WHAT` for it.
struct BadCommand {
  std::string what;
  explicit BadCommand(const std::string& w) : what(w) {}
};

// The arguments of one command, read left to right.
struct Args {
  std::vector<std::string> words;
  size_t next;

  explicit Args(const std::string& line) : next(1) {
    std::istringstream in(line);  // any run of blanks separates (and a \r)
    std::string w;
    while (in >> w) words.push_back(w);
  }

  const std::string& name() const { return words[0]; }

  const std::string& word(const char* what) {
    if (next >= words.size())
      throw BadCommand(std::string("missing ") + what);
    return words[next++];
  }

  double num(const char* what = "number") {
    const std::string& w = word(what);
    char* end = NULL;
    double x = strtod(w.c_str(), &end);
    if (w.empty() || *end != '\0')
      throw BadCommand(std::string("bad ") + what + " '" + w.substr(0, 40) + "'");
    return x;
  }

  long long count(const char* what, long long lo, long long hi) {
    const std::string& w = word(what);
    char* end = NULL;
    long long n = strtoll(w.c_str(), &end, 10);
    if (w.empty() || *end != '\0' || n < lo || n > hi)
      throw BadCommand(std::string("bad ") + what + " '" + w.substr(0, 40) + "'");
    return n;
  }

  Vector3D vec() {
    double x = num(), y = num(), z = num();
    return Vector3D(x, y, z);
  }

  // `ox oy oz dx dy dz min_t max_t`: Ray(o, d), then min_t and max_t.
  Ray ray() {
    Vector3D o = vec(), d = vec();
    double min_t = num("min_t"), max_t = num("max_t");
    Ray r(o, d);
    r.min_t = min_t;
    r.max_t = max_t;
    return r;
  }

  void done() const {
    if (next != words.size())
      throw BadCommand("too many arguments for " + words[0]);
  }
};

// ---------------------------------------------------------------- output

struct Reply {
  std::string s;
  Reply& word(const std::string& w) {
    if (!s.empty()) s += ' ';
    s += w;
    return *this;
  }
  Reply& num(double x) {
    char b[40];
    snprintf(b, sizeof b, "%.17g", x);
    return word(b);
  }
  Reply& integer(long long n) {
    char b[32];
    snprintf(b, sizeof b, "%lld", n);
    return word(b);
  }
  Reply& flag(bool b) { return word(b ? "1" : "0"); }
  Reply& vec(const Vector3D& v) { return num(v.x).num(v.y).num(v.z); }
  Reply& ray(const Ray& r) { return vec(r.o).vec(r.d).num(r.min_t).num(r.max_t); }
};

// ---------------------------------------------------------------- state

struct State {
  // Objects are never destroyed: a student's destructor (of a malformed BVH,
  // say) then cannot crash the driver, and pointers into them stay valid.
  Camera* camera;
  bool lens_set;
  double lens_radius, focal_distance;
  Triangle* triangle;
  Sphere* sphere;
  std::vector<Primitive*> mesh;  // Triangles
  std::vector<Ray> race;         // The rays `race` times
  std::map<const Primitive*, long long> mesh_position;
  BVHAccel* bvh;
  BSDF* bsdf;
  MicrofacetBSDF* microfacet;  // == bsdf when the current BSDF is one
  EnvironmentLight* env;
  size_t env_w, env_h;  // its map's size
  std::vector<SceneLight*> lights;  // area lights, each also two mesh triangles
  PathTracer* tracer;
  BSDF* furnace;                    // the furnace's walls, once built

  State() : camera(NULL), lens_set(false), lens_radius(NaN),
            focal_distance(NaN), triangle(NULL), sphere(NULL), bvh(NULL),
            bsdf(NULL), microfacet(NULL), env(NULL), env_w(0), env_h(0),
            tracer(NULL), furnace(NULL) {}
};

template <typename T> T* need(T* p, const char* what) {
  if (!p) throw BadCommand(std::string("no ") + what + " yet");
  return p;
}

static Intersection fresh_intersection() {
  Intersection isect;  // t = INF, primitive = bsdf = NULL
  isect.n = Vector3D(NaN);
  return isect;
}

// 1 when p is the probed object, 0 when null, 2 otherwise.
template <typename T> int which(const T* p, const T* probed) {
  return p == NULL ? 0 : (p == probed ? 1 : 2);
}

static long long mesh_index(const State& st, const Primitive* p) {
  std::map<const Primitive*, long long>::const_iterator i =
      st.mesh_position.find(p);
  return i == st.mesh_position.end() ? -1 : i->second;
}

// A Triangle as the starter's Mesh constructor makes one: the six vectors,
// the tag BSDF, and its bounding box.
static Triangle* read_triangle(Args& a) {
  Vector3D p1 = a.vec(), p2 = a.vec(), p3 = a.vec();
  Vector3D n1 = a.vec(), n2 = a.vec(), n3 = a.vec();
  a.done();
  Triangle* t = new CountingTriangle();
  t->p1 = p1; t->p2 = p2; t->p3 = p3;
  t->n1 = n1; t->n2 = n2; t->n3 = n3;
  t->bsdf = &tag_bsdf;
  t->bbox = BBox(p1);
  t->bbox.expand(p2);
  t->bbox.expand(p3);
  return t;
}

static void hit_reply(Reply& out, bool hit, const Intersection& isect,
                      const Primitive* probed, const Ray& r) {
  out.flag(hit).num(isect.t).vec(isect.n);
  out.integer(which(isect.primitive, probed));
  out.integer(which<BSDF>(isect.bsdf, &tag_bsdf)).num(r.max_t);
}

// The BVH in preorder: `I MIN MAX HASL HASR` or `L MIN MAX COUNT INDEX...`.
static void bvh_reply(Reply& out, const State& st) {
  const std::vector<Primitive*>& prims = st.bvh->*bvh_primitives_member();
  std::set<const BVHNode*> seen;
  std::vector<const BVHNode*> stack;
  if (st.bvh->get_root()) stack.push_back(st.bvh->get_root());
  while (!stack.empty()) {
    const BVHNode* node = stack.back();
    stack.pop_back();
    if (!seen.insert(node).second)
      throw BadCommand("bvh: a node is reached twice (not a tree)");
    if (node->isLeaf()) {
      long long lo = node->start - prims.begin();
      long long hi = node->end - prims.begin();
      if (lo < 0 || lo > hi || hi > (long long)prims.size())
        throw BadCommand("bvh: a leaf's [start, end) is not inside its list");
      out.word("L").vec(node->bb.min).vec(node->bb.max).integer(hi - lo);
      for (long long i = lo; i < hi; ++i) out.integer(mesh_index(st, prims[i]));
    } else {
      out.word("I").vec(node->bb.min).vec(node->bb.max);
      out.flag(node->l != NULL).flag(node->r != NULL);
      if (node->r) stack.push_back(node->r);
      if (node->l) stack.push_back(node->l);
    }
  }
}

// The quad of an area light, where the tree's AreaLight makes its own
// (the 3-2 starter's get_primitives: two triangles emitting
// radiance / area * max(0, dir . wo)); none in a 3-1 tree.
template <typename L>
auto own_quad(const L* light, int) -> decltype(light->get_primitives()) {
  return light->get_primitives();
}
template <typename L>
std::vector<Primitive*> own_quad(const L*, long) {
  return std::vector<Primitive*>();
}

// The 3-1 starter's EmissionBSDF(radiance), glowing both ways; NULL in a
// tree whose EmissionBSDF takes a direction too (the 3-2 starter's).
template <typename B>
auto two_sided_glow(const Vector3D& L, int) -> decltype(new B(L)) {
  return new B(L);
}
template <typename B>
B* two_sided_glow(const Vector3D&, long) {
  return NULL;
}

// An area light as the course's scenes have one: an AreaLight of radiance
// L at `centre`, spanning `dx` and `dy`, facing `dir`, and its quad in the
// mesh (what hemisphere sampling meets): the light's own where it makes
// one (answer 1), else two triangles with an EmissionBSDF(L) (answer 0).
static void light_quad(State& st, Args& a, Reply& out) {
  Vector3D L = a.vec(), c = a.vec(), dx = a.vec(), dy = a.vec(), dir = a.vec();
  a.done();
  AreaLight* light = new AreaLight(L, c, dir, dx, dy);
  st.lights.push_back(light);
  std::vector<Primitive*> own = own_quad(light, 0);
  if (!own.empty()) {
    for (size_t k = 0; k < own.size(); ++k) {
      st.mesh_position[own[k]] = (long long)st.mesh.size();
      st.mesh.push_back(own[k]);
    }
    out.integer(1);
    return;
  }
  BSDF* glow = two_sided_glow<EmissionBSDF>(L, 0);
  if (!glow) throw BadCommand("light_quad: no EmissionBSDF(radiance) and no get_primitives");
  Vector3D p[4] = {c - dx * 0.5 - dy * 0.5, c + dx * 0.5 - dy * 0.5,
                   c + dx * 0.5 + dy * 0.5, c - dx * 0.5 + dy * 0.5};
  for (int k = 0; k < 2; ++k) {
    Triangle* t = new CountingTriangle();
    t->p1 = p[0]; t->p2 = p[k + 1]; t->p3 = p[k + 2];
    t->n1 = t->n2 = t->n3 = dir;
    t->bsdf = glow;
    t->bbox = BBox(t->p1);
    t->bbox.expand(t->p2);
    t->bbox.expand(t->p3);
    st.mesh_position[t] = (long long)st.mesh.size();
    st.mesh.push_back(t);
  }
  out.integer(0);
}

// A diffuse surface that also glows, the same in every direction: inside a
// closed box of it, a path's k-th bounce brings rho^k Le (the furnace
// test). Both starters' get_emission are overridden (3-1's takes nothing,
// 3-2's the direction); the other is an unused overload.
struct FurnaceBSDF : public DiffuseBSDF {
  Vector3D glow;
  FurnaceBSDF(const Vector3D& rho, const Vector3D& le) : DiffuseBSDF(rho), glow(le) {}
  Vector3D get_emission() const { return glow; }
  Vector3D get_emission(Vector3D) const { return glow; }
};

// The cube [-1, 1]^3 of FurnaceBSDF(rho, le) walls, normals inward, and an
// area light outside it, which no ray from inside reaches but which makes
// the hemisphere estimator take ns_area_light samples.
static void furnace(State& st, Args& a) {
  Vector3D rho = a.vec(), le = a.vec();
  a.done();
  st.mesh.clear();
  st.mesh_position.clear();
  st.lights.clear();
  st.furnace = new FurnaceBSDF(rho, le);
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = -1; side <= 1; side += 2) {
      Vector3D n(0, 0, 0), u(0, 0, 0), v(0, 0, 0);
      n[axis] = -side;  // inward
      u[(axis + 1) % 3] = 1;
      v[(axis + 2) % 3] = 1;
      Vector3D c = -n;  // the face's centre, at side along axis
      Vector3D q[4] = {c - u - v, c + u - v, c + u + v, c - u + v};
      for (int k = 0; k < 2; ++k) {
        Triangle* t = new CountingTriangle();
        t->p1 = q[0]; t->p2 = q[k + 1]; t->p3 = q[k + 2];
        t->n1 = t->n2 = t->n3 = n;
        t->bsdf = st.furnace;
        t->bbox = BBox(t->p1);
        t->bbox.expand(t->p2);
        t->bbox.expand(t->p3);
        st.mesh_position[t] = (long long)st.mesh.size();
        st.mesh.push_back(t);
      }
    }
  }
  st.lights.push_back(new AreaLight(Vector3D(1), Vector3D(0, 0, 5), Vector3D(0, 0, -1),
                                    Vector3D(0.1, 0, 0), Vector3D(0, 0.1, 0)));
}

// `-o`'s field, where the tree has one (the 2025 starter's isAccumBounces):
// true when set.
template <typename P>
auto set_accumulate(P* pt, bool on, int) -> decltype(pt->isAccumBounces = on, true) {
  pt->isAccumBounces = on;
  return true;
}
template <typename P>
bool set_accumulate(P*, bool, long) {
  return false;
}

// `MEAN(C) VAR(C)` of the values of n calls of `call`: their mean and
// sample variance per channel (Welford's running sums).
template <typename Call> static void moments(long long n, Reply& out, Call call) {
  Vector3D mean, m2;
  for (long long k = 1; k <= n; ++k) {
    Vector3D v = call();
    Vector3D delta = v - mean;
    mean += delta / (double)k;
    m2 += delta * (v - mean);
  }
  out.vec(mean).vec(m2 / (double)(n - 1));
}

// One of the direct-lighting estimators called N times at the hit
// `o + t d` with normal `n` on a DiffuseBSDF(albedo): `moments` of its
// values.
static void direct(State& st, Args& a, Reply& out) {
  const std::string& which = a.word("hemi or importance");
  long long n = a.count("call count", 2, 10000000);
  Vector3D o = a.vec(), d = a.vec();
  double t = a.num("t");
  Vector3D normal = a.vec(), albedo = a.vec();
  a.done();
  if (which != "hemi" && which != "importance")
    throw BadCommand("direct: hemi or importance");
  PathTracer* pt = need(st.tracer, "tracer");
  Ray r(o, d, (int)pt->max_ray_depth);
  Intersection isect;
  isect.t = t;
  isect.n = normal;
  isect.bsdf = new DiffuseBSDF(albedo);
  bool hemi = which == "hemi";
  moments(n, out, [&]() {
    return hemi ? pt->estimate_direct_lighting_hemisphere(r, isect)
                : pt->estimate_direct_lighting_importance(r, isect);
  });
}

static void set_bsdf(State& st, BSDF* b, MicrofacetBSDF* m, Reply& out) {
  b->reflectanceMap = NULL;  // unused by the course; not left uninitialised
  b->normalMap = NULL;
  st.bsdf = b;
  st.microfacet = m;
  out.word("ok");
}

static double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
      .count();
}

// The seconds one pass over the race's rays takes: through the BVH
// (passes repeated until they last 0.05 s, their mean), and through a scan
// of every triangle (one pass).
static void race(State& st, bool nearest, Reply& out) {
  BVHAccel* bvh = need(st.bvh, "bvh");
  long long passes = 0;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  double bvh_seconds = 0;
  do {
    for (size_t k = 0; k < st.race.size(); ++k) {
      Ray r = st.race[k];
      Intersection isect = fresh_intersection();
      if (nearest) bvh->intersect(r, &isect);
      else bvh->has_intersection(r);
    }
    ++passes;
    bvh_seconds = seconds_since(start);
  } while (bvh_seconds < 0.05 && passes < 1000000);
  start = std::chrono::steady_clock::now();
  for (size_t k = 0; k < st.race.size(); ++k) {
    Ray r = st.race[k];
    Intersection isect = fresh_intersection();
    for (size_t i = 0; i < st.mesh.size(); ++i) {
      if (nearest) st.mesh[i]->intersect(r, &isect);
      else if (st.mesh[i]->has_intersection(r)) break;
    }
  }
  out.num(bvh_seconds / passes).num(seconds_since(start));
}

// ---------------------------------------------------------------- commands

static void run(State& st, Args& a, Reply& out) {
  const std::string& c = a.name();

  if (c == "camera") {
    Collada::CameraInfo info;
    info.hFov = (float)a.num("hfov");
    info.vFov = (float)a.num("vfov");
    size_t w = (size_t)a.count("width", 1, 1 << 20);
    size_t h = (size_t)a.count("height", 1, 1 << 20);
    Vector3D target = a.vec();
    double phi = a.num("phi"), theta = a.num("theta"), r = a.num("r");
    info.nClip = (float)a.num("nclip");
    info.fClip = (float)a.num("fclip");
    a.done();
    st.camera = new Camera();
    st.camera->lensRadius = st.lens_radius;
    st.camera->focalDistance = st.focal_distance;
    st.camera->configure(info, w, h);
    st.camera->place(target, phi, theta, r, r, r);
    const Camera& cam = *st.camera;
    out.vec(cam.position()).vec(cam.up_dir()).num(cam.v_fov());
    out.num(cam.aspect_ratio()).num(cam.near_clip()).num(cam.far_clip());
  } else if (c == "ray") {
    double x = a.num("x"), y = a.num("y");
    a.done();
    out.ray(need(st.camera, "camera")->generate_ray(x, y));
  } else if (c == "lens") {
    double radius = a.num("radius"), focal = a.num("focal distance");
    a.done();
    st.lens_set = true;
    st.lens_radius = radius;
    st.focal_distance = focal;
    if (st.camera) {
      st.camera->lensRadius = radius;
      st.camera->focalDistance = focal;
    }
    out.word("ok");
  } else if (c == "lens_ray") {
    double x = a.num("x"), y = a.num("y");
    double rnd_r = a.num("rndR"), rnd_theta = a.num("rndTheta");
    a.done();
    Camera* cam = need(st.camera, "camera");
    if (!st.lens_set) throw BadCommand("no lens yet");
    out.ray(cam->generate_ray_for_thin_lens(x, y, rnd_r, rnd_theta));

  } else if (c == "triangle") {
    st.triangle = read_triangle(a);
    out.word("ok");
  } else if (c == "tri_any") {
    Ray r = a.ray();
    a.done();
    bool hit = need(st.triangle, "triangle")->has_intersection(r);
    out.flag(hit).num(r.max_t);
  } else if (c == "tri_hit") {
    Ray r = a.ray();
    a.done();
    Triangle* t = need(st.triangle, "triangle");
    Intersection isect = fresh_intersection();
    bool hit = t->intersect(r, &isect);
    hit_reply(out, hit, isect, t, r);

  } else if (c == "sphere") {
    Vector3D center = a.vec();
    double radius = a.num("radius");
    a.done();
    SphereObject* object = new SphereObject(center, radius, &tag_bsdf);
    st.sphere = new Sphere(object, center, radius);
    out.word("ok");
  } else if (c == "sph_test") {
    Ray r = a.ray();
    a.done();
    double t1 = NaN, t2 = NaN;
    bool hit = need(st.sphere, "sphere")->test(r, t1, t2);
    out.flag(hit).num(t1).num(t2).num(r.max_t);
  } else if (c == "sph_any") {
    Ray r = a.ray();
    a.done();
    bool hit = need(st.sphere, "sphere")->has_intersection(r);
    out.flag(hit).num(r.max_t);
  } else if (c == "sph_hit") {
    Ray r = a.ray();
    a.done();
    Sphere* s = need(st.sphere, "sphere");
    Intersection isect = fresh_intersection();
    bool hit = s->intersect(r, &isect);
    hit_reply(out, hit, isect, s, r);

  } else if (c == "bbox") {
    Vector3D lo = a.vec(), hi = a.vec();
    Ray r = a.ray();
    double t0 = a.num("t0"), t1 = a.num("t1");
    a.done();
    bool hit = BBox(lo, hi).intersect(r, t0, t1);
    out.flag(hit).num(t0).num(t1);

  } else if (c == "mesh_clear") {
    a.done();
    st.mesh.clear();
    st.mesh_position.clear();
    st.race.clear();
    st.lights.clear();
    st.bvh = NULL;
    st.tracer = NULL;
    out.word("ok");
  } else if (c == "mesh_tri") {
    Triangle* t = read_triangle(a);
    st.mesh_position[t] = (long long)st.mesh.size();
    st.mesh.push_back(t);
    out.word("ok");
  } else if (c == "bvh") {
    size_t leaf = (size_t)a.count("leaf size", 0, 1 << 30);
    a.done();
    st.bvh = new BVHAccel(st.mesh, leaf);
    bvh_reply(out, st);
  } else if (c == "bvh_hit") {
    Ray r = a.ray();
    a.done();
    Intersection isect = fresh_intersection();
    bool hit = need(st.bvh, "bvh")->intersect(r, &isect);
    out.flag(hit).num(isect.t);
    out.integer(mesh_index(st, isect.primitive)).num(r.max_t);
  } else if (c == "bvh_any") {
    Ray r = a.ray();
    a.done();
    bool hit = need(st.bvh, "bvh")->has_intersection(r);
    out.flag(hit).num(r.max_t);
  } else if (c == "light_quad") {
    light_quad(st, a, out);
  } else if (c == "light_sample") {
    Vector3D p = a.vec();
    long long n = a.count("sample count", 0, 1000000);
    a.done();
    if (st.lights.empty()) throw BadCommand("no light yet");
    for (long long k = 0; k < n; ++k) {
      Vector3D wi(NaN);
      double dist = NaN, pdf = NaN;
      Vector3D L = st.lights.back()->sample_L(p, &wi, &dist, &pdf);
      out.vec(wi).num(dist).num(pdf).vec(L);
    }
  } else if (c == "furnace") {
    furnace(st, a);
    out.word("ok");
  } else if (c == "accumulate") {
    long long on = a.count("0 or 1", 0, 1);
    a.done();
    out.flag(set_accumulate(need(st.tracer, "tracer"), on == 1, 0));
  } else if (c == "bounces") {
    long long n = a.count("call count", 2, 10000000);
    Vector3D o = a.vec(), d = a.vec();
    double t = a.num("t");
    Vector3D normal = a.vec();
    a.done();
    PathTracer* pt = need(st.tracer, "tracer");
    Ray r(o, d, (int)pt->max_ray_depth);
    Intersection isect;
    isect.t = t;
    isect.n = normal;
    isect.bsdf = need(st.furnace, "furnace");
    moments(n, out, [&]() { return pt->at_least_one_bounce_radiance(r, isect); });
  } else if (c == "pixels") {
    size_t w = (size_t)a.count("width", 1, 4096);
    size_t h = (size_t)a.count("height", 1, 4096);
    size_t ns_aa = (size_t)a.count("samples a pixel", 1, 1 << 20);
    size_t batch = (size_t)a.count("samples a batch", 0, 1 << 20);
    double tolerance = a.num("tolerance");
    size_t x0 = (size_t)a.count("x0", 0, w), y0 = (size_t)a.count("y0", 0, h);
    size_t x1 = (size_t)a.count("x1", x0, w), y1 = (size_t)a.count("y1", y0, h);
    a.done();
    PathTracer* pt = need(st.tracer, "tracer");
    pt->camera = need(st.camera, "camera");
    pt->set_frame_size(w, h);
    pt->ns_aa = ns_aa;
    pt->samplesPerBatch = batch;
    pt->maxTolerance = tolerance;
    for (size_t y = y0; y < y1; ++y) {
      for (size_t x = x0; x < x1; ++x) {
        pt->sampleBuffer.data[x + y * w] = Vector3D(NaN);
        pt->sampleCountBuffer[x + y * w] = -1;
        pt->raytrace_pixel(x, y);
        out.vec(pt->sampleBuffer.data[x + y * w]);
        out.integer(pt->sampleCountBuffer[x + y * w]);
      }
    }
  } else if (c == "tracer") {
    size_t ns = (size_t)a.count("samples a light", 1, 1 << 20);
    size_t depth = (size_t)a.count("max ray depth", 0, 1000);
    long long hemi = a.count("hemisphere 0 or 1", 0, 1);
    a.done();
    PathTracer* pt = new PathTracer();
    pt->bvh = new BVHAccel(st.mesh, 4);
    pt->scene = new Scene(std::vector<SceneObject*>(), st.lights);
    pt->ns_area_light = ns;
    pt->max_ray_depth = depth;
    pt->direct_hemisphere_sample = hemi == 1;
    pt->envLight = NULL;
    pt->camera = NULL;
    st.tracer = pt;
    out.word("ok");
  } else if (c == "direct") {
    direct(st, a, out);
  } else if (c == "tests") {
    a.done();
    out.integer(triangle_tests);
    triangle_tests = 0;
  } else if (c == "race_ray") {
    st.race.push_back(a.ray());
    a.done();
    out.word("ok");
  } else if (c == "race") {
    const std::string& how = a.word("hit or any");
    a.done();
    if (how != "hit" && how != "any") throw BadCommand("race: hit or any");
    race(st, how == "hit", out);
    triangle_tests = 0;
  } else if (c == "bvh_hit_at" || c == "bvh_any_at") {
    // The node reached from the root by a word of `l` and `r` (`-`: the
    // root), then the overload that takes a node.
    std::string path = a.word("path");
    Ray r = a.ray();
    a.done();
    BVHAccel* bvh = need(st.bvh, "bvh");
    BVHNode* node = bvh->get_root();
    for (size_t i = 0; i < path.size() && path != "-"; ++i) {
      if (!node || (path[i] != 'l' && path[i] != 'r'))
        throw BadCommand("no node");
      node = path[i] == 'l' ? node->l : node->r;
    }
    if (!node) throw BadCommand("no node");
    if (c == "bvh_hit_at") {
      Intersection isect = fresh_intersection();
      bool hit = bvh->intersect(r, &isect, node);
      out.flag(hit).num(isect.t);
      out.integer(mesh_index(st, isect.primitive)).num(r.max_t);
    } else {
      bool hit = bvh->has_intersection(r, node);
      out.flag(hit).num(r.max_t);
    }

  } else if (c == "diffuse") {
    Vector3D albedo = a.vec();
    a.done();
    set_bsdf(st, new DiffuseBSDF(albedo), NULL, out);
  } else if (c == "mirror") {
    Vector3D reflectance = a.vec();
    a.done();
    set_bsdf(st, new MirrorBSDF(reflectance), NULL, out);
  } else if (c == "refraction") {
    Vector3D transmittance = a.vec();
    double roughness = a.num("roughness"), ior = a.num("ior");
    a.done();
    set_bsdf(st, new RefractionBSDF(transmittance, roughness, ior), NULL, out);
  } else if (c == "glass") {
    Vector3D transmittance = a.vec(), reflectance = a.vec();
    double roughness = a.num("roughness"), ior = a.num("ior");
    a.done();
    set_bsdf(st, new GlassBSDF(transmittance, reflectance, roughness, ior),
             NULL, out);
  } else if (c == "microfacet") {
    Vector3D eta = a.vec(), k = a.vec();
    double alpha = a.num("alpha");
    a.done();
    MicrofacetBSDF* m = new MicrofacetBSDF(eta, k, alpha);
    set_bsdf(st, m, m, out);
  } else if (c == "f") {
    Vector3D wo = a.vec(), wi = a.vec();
    a.done();
    out.vec(need(st.bsdf, "bsdf")->f(wo, wi));
  } else if (c == "sample") {
    Vector3D wo = a.vec();
    long long n = a.count("sample count", 0, 1000000);
    a.done();
    BSDF* b = need(st.bsdf, "bsdf");
    for (long long i = 0; i < n; ++i) {
      Vector3D wi(NaN);
      double pdf = NaN;
      Vector3D f = b->sample_f(wo, &wi, &pdf);
      out.vec(wi).num(pdf).vec(f);
    }
  } else if (c == "reflect") {
    Vector3D wo = a.vec();
    a.done();
    // BSDF::reflect is the base class's helper: any BSDF will do.
    BSDF* b = st.bsdf ? st.bsdf : &tag_bsdf;
    Vector3D wi(NaN);
    b->reflect(wo, &wi);
    out.vec(wi);
  } else if (c == "refract") {
    Vector3D wo = a.vec();
    double ior = a.num("ior");
    a.done();
    BSDF* b = st.bsdf ? st.bsdf : &tag_bsdf;
    Vector3D wi(NaN);
    bool ok = b->refract(wo, &wi, ior);
    out.flag(ok).vec(wi);
  } else if (c == "mf_F") {
    Vector3D wi = a.vec();
    a.done();
    out.vec(need(st.microfacet, "microfacet bsdf")->F(wi));
  } else if (c == "mf_G") {
    Vector3D wo = a.vec(), wi = a.vec();
    a.done();
    out.num(need(st.microfacet, "microfacet bsdf")->G(wo, wi));
  } else if (c == "mf_D") {
    Vector3D h = a.vec();
    a.done();
    out.num(need(st.microfacet, "microfacet bsdf")->D(h));

  } else if (c == "envmap") {
    size_t w = (size_t)a.count("width", 1, 1 << 14);
    size_t h = (size_t)a.count("height", 1, 1 << 14);
    if (w * h > (1u << 22)) throw BadCommand("envmap too large");
    if (a.words.size() != 3 + 3 * w * h)
      throw BadCommand("envmap needs W*H colours");
    HDRImageBuffer* map = new HDRImageBuffer(w, h);
    for (size_t y = 0; y < h; ++y)
      for (size_t x = 0; x < w; ++x) map->data[x + y * w] = a.vec();
    a.done();
    st.env = new EnvironmentLight(map);
    st.env_w = w;
    st.env_h = h;
    out.word("ok");
  } else if (c == "env_sample") {
    long long n = a.count("sample count", 0, 1000000);
    a.done();
    EnvironmentLight* env = need(st.env, "envmap");
    for (long long i = 0; i < n; ++i) {
      Vector3D wi(NaN);
      double dist = NaN, pdf = NaN;
      Vector3D L = env->sample_L(Vector3D(0), &wi, &dist, &pdf);
      out.vec(wi).num(dist).num(pdf).vec(L);
    }
  } else if (c == "env_tables") {
    a.done();
    EnvironmentLight* env = need(st.env, "envmap");
    size_t w = st.env_w, h = st.env_h;
    const double* pdf = env->*env_pdf_member();
    const double* marginal = env->*env_marginal_member();
    const double* conds = env->*env_conds_member();
    if (!pdf || !marginal || !conds) throw BadCommand("env_tables: a table is null");
    for (size_t k = 0; k < w * h; ++k) out.num(pdf[k]);
    for (size_t j = 0; j < h; ++j) out.num(marginal[j]);
    for (size_t k = 0; k < w * h; ++k) out.num(conds[k]);
  } else if (c == "env_dir") {
    Vector3D d = a.vec();
    a.done();
    out.vec(need(st.env, "envmap")->sample_dir(Ray(Vector3D(0), d)));

  } else {
    throw BadCommand("unknown command '" + c.substr(0, 40) + "'");
  }
}

int main(int argc, char** argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: %s COMMANDS RESPONSES\n", argv[0]);
    return 2;
  }
  std::ifstream commands(argv[1]);
  if (!commands) {
    fprintf(stderr, "cs184_probe: cannot read %s\n", argv[1]);
    return 2;
  }
  FILE* responses = fopen(argv[2], "w");
  if (!responses) {
    fprintf(stderr, "cs184_probe: cannot write %s\n", argv[2]);
    return 2;
  }
  fputs("cs184-probe 1\n", responses);
  fflush(responses);

  State st;
  std::string line;
  while (std::getline(commands, line)) {
    Args args(line);
    if (args.words.empty() || args.words[0][0] == '#') continue;
    Reply out;
    try {
      run(st, args, out);
    } catch (const BadCommand& bad) {
      out.s = "error " + bad.what;
    }
    fputs(out.s.c_str(), responses);
    fputc('\n', responses);
    fflush(responses);
  }
  fclose(responses);
  return 0;
}
