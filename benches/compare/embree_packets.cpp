// Embree 3 on rays written by `examples/render_rays.rs`: one ray a query
// (rtcIntersect1) against packets of 8 and 16 (rtcIntersect8/16), one
// thread, as Mitsuba 3's LLVM variants trace with their own Embree 3
// (packets as wide as the vector unit; camera rays with the coherent
// context flag). Built by `benches/compare/packets.sh`.
//
//   embree_packets DIR ROBUST COHERENT
//
// The scene is built as Mitsuba builds its own (RTC_BUILD_QUALITY_HIGH).
// ROBUST 1 sets RTC_SCENE_FLAG_ROBUST (watertight, as this project's
// test; Mitsuba sets no flag); COHERENT 1 sets
// RTC_INTERSECT_CONTEXT_FLAG_COHERENT, 0 the incoherent flag. Prints, per
// ray set and query width, the rays, hits, the sum of hit distances (to
// check against the other widths and this project's) and the median rate
// of five passes; a packet width traces the rays left over one at a time.
#include <embree3/rtcore.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

// The wheel's Embree lives in namespace `mitsuba`; the header's macro
// says so (and is empty for a plain Embree build).
RTC_NAMESPACE_USE

static std::vector<float> load(const std::string &path) {
    FILE *file = std::fopen(path.c_str(), "rb");
    if (!file) {
        std::fprintf(stderr, "%s: cannot open\n", path.c_str());
        std::exit(1);
    }
    std::fseek(file, 0, SEEK_END);
    long bytes = std::ftell(file);
    std::fseek(file, 0, SEEK_SET);
    if (bytes < 0 || bytes % 4 != 0) {
        std::fprintf(stderr, "%s: not a file of 32-bit floats\n", path.c_str());
        std::exit(1);
    }
    std::vector<float> data(bytes / 4);
    if (std::fread(data.data(), 4, data.size(), file) != data.size()) {
        std::fprintf(stderr, "%s: read %ld bytes short\n", path.c_str(), bytes);
        std::exit(1);
    }
    std::fclose(file);
    return data;
}

// Fills lane k of a packet (RTCRayHit8 or RTCRayHit16) from ray q.
template <typename Packet> static void fill(Packet &p, int k, const float *q) {
    p.ray.org_x[k] = q[0]; p.ray.org_y[k] = q[1]; p.ray.org_z[k] = q[2];
    p.ray.dir_x[k] = q[3]; p.ray.dir_y[k] = q[4]; p.ray.dir_z[k] = q[5];
    p.ray.tnear[k] = q[6]; p.ray.tfar[k] = q[7]; p.ray.time[k] = 0;
    p.ray.mask[k] = ~0u; p.ray.id[k] = 0; p.ray.flags[k] = 0;
    p.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
    p.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
}

struct Tally { long hits = 0; double distances = 0; };

// Ray i of `rays` through rtcIntersect1, counted in `tally`.
static void trace_one(RTCScene scene, RTCIntersectContext &context, const std::vector<float> &rays,
                      size_t i, Tally &tally) {
    RTCRayHit one;
    const float *q = &rays[8 * i];
    one.ray.org_x = q[0]; one.ray.org_y = q[1]; one.ray.org_z = q[2];
    one.ray.dir_x = q[3]; one.ray.dir_y = q[4]; one.ray.dir_z = q[5];
    one.ray.tnear = q[6]; one.ray.tfar = q[7]; one.ray.time = 0;
    one.ray.mask = ~0u; one.ray.id = 0; one.ray.flags = 0;
    one.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    one.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &context, &one);
    if (one.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
        tally.hits++;
        tally.distances += one.ray.tfar;
    }
}

// Whole packets of W through `query`; the rays left over (fewer than W)
// one at a time, so that every width traces every ray.
template <int W, typename Packet, typename Query>
static void trace_packets(RTCScene scene, RTCIntersectContext &context,
                          const std::vector<float> &rays, Query query, Tally &tally) {
    alignas(64) Packet packet;
    alignas(64) int valid[W];
    std::fill(valid, valid + W, -1);
    size_t n = rays.size() / 8;
    for (size_t i = n / W * W; i < n; i++) trace_one(scene, context, rays, i, tally);
    for (size_t i = 0; i + W <= n; i += W) {
        for (int k = 0; k < W; k++) fill(packet, k, &rays[8 * (i + k)]);
        query(valid, &packet);
        for (int k = 0; k < W; k++)
            if (packet.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID) {
                tally.hits++;
                tally.distances += packet.ray.tfar[k];
            }
    }
}

int main(int argc, char **argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: embree_packets DIR ROBUST COHERENT\n");
        return 1;
    }
    std::string dir = argv[1];
    bool robust = std::atoi(argv[2]) != 0, coherent = std::atoi(argv[3]) != 0;
    std::vector<float> corners = load(dir + "/triangles.bin");
    size_t triangles = corners.size() / 9;
    RTCDevice device = rtcNewDevice("threads=1");
    if (!device) {
        std::fprintf(stderr, "Embree: no device (error %d)\n", (int)rtcGetDeviceError(nullptr));
        return 1;
    }
    rtcSetDeviceErrorFunction(device, [](void *, RTCError code, const char *what) {
        std::fprintf(stderr, "Embree error %d: %s\n", (int)code, what ? what : "");
        std::exit(1);
    }, nullptr);
    RTCScene scene = rtcNewScene(device);
    // As Mitsuba 3 sets up its scene (src/render/scene_embree.inl): high
    // build quality, and no flags but ROBUST where asked for.
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
    rtcSetSceneFlags(scene, robust ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE);
    RTCGeometry mesh = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto *vertices = (float *)rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_VERTEX, 0,
                                                      RTC_FORMAT_FLOAT3, 12, 3 * triangles);
    auto *indices = (unsigned *)rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_INDEX, 0,
                                                        RTC_FORMAT_UINT3, 12, triangles);
    std::copy(corners.begin(), corners.end(), vertices);
    for (unsigned i = 0; i < 3 * triangles; i++) indices[i] = i;
    rtcCommitGeometry(mesh);
    rtcAttachGeometry(scene, mesh);
    rtcReleaseGeometry(mesh);
    rtcCommitScene(scene);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    for (const char *set : {"camera", "bounce"}) {
        std::vector<float> rays = load(dir + "/" + set + ".bin");
        size_t n = rays.size() / 8;
        for (int width : {1, 8, 16}) {
            std::vector<double> rates;
            Tally tally;
            for (int pass = 0; pass < 5; pass++) {
                tally = Tally();
                auto start = std::chrono::steady_clock::now();
                if (width == 1) {
                    for (size_t i = 0; i < n; i++) trace_one(scene, context, rays, i, tally);
                } else if (width == 8) {
                    trace_packets<8, RTCRayHit8>(scene, context, rays, [&](const int *v, RTCRayHit8 *p) {
                        rtcIntersect8(v, scene, &context, p); }, tally);
                } else {
                    trace_packets<16, RTCRayHit16>(scene, context, rays, [&](const int *v, RTCRayHit16 *p) {
                        rtcIntersect16(v, scene, &context, p); }, tally);
                }
                std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
                rates.push_back(n / seconds.count() / 1e6);
            }
            std::sort(rates.begin(), rates.end());
            std::printf("Embree %s, %s flag, %s rays, %2d a query: %zu rays, %ld hits, sum of t %.1f, %.2f Mrays/s\n",
                        robust ? "robust" : "default", coherent ? "coherent" : "incoherent", set, width, n,
                        tally.hits, tally.distances, rates[2]);
        }
    }
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
    return 0;
}
